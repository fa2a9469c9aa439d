# relief_target_defaults(<target>): warnings (errors under RELIEF_STRICT) and sanitizers for
# Relief's own targets only, so third-party headers never break the build.
if(RELIEF_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "RELIEF_FUZZ needs clang (libFuzzer): configure with -DCMAKE_CXX_COMPILER=clang++")
  endif()
  # Coverage for libFuzzer in every object of ours; the targets link the fuzzer itself.
  add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined
                      -fno-omit-frame-pointer -g)
  add_link_options(-fsanitize=address,undefined)
elseif(RELIEF_SANITIZE)
  # Sanitizers apply to every target of ours, including the executables that link them.
  set(RELIEF_SANITIZER_FLAGS -fsanitize=address,undefined -fno-sanitize-recover=undefined
                             -fno-omit-frame-pointer)
  add_compile_options(${RELIEF_SANITIZER_FLAGS})
  add_link_options(-fsanitize=address,undefined)
endif()

# Where the modules (core/CMakeLists.txt) are built and installed; executables find them through
# their run path: the build folder in a build, $ORIGIN/<bin to module folder> once installed.
include(GNUInstallDirs)
set(RELIEF_MODULE_BUILD_DIR ${PROJECT_BINARY_DIR}/modules)
set(RELIEF_MODULE_INSTALL_DIR ${CMAKE_INSTALL_LIBDIR}/relief)
file(RELATIVE_PATH RELIEF_MODULE_INSTALL_RPATH ${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_BINDIR}
     ${CMAKE_INSTALL_PREFIX}/${RELIEF_MODULE_INSTALL_DIR})
set(RELIEF_MODULE_INSTALL_RPATH "$ORIGIN/${RELIEF_MODULE_INSTALL_RPATH}")

function(relief_target_defaults target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wshadow -Wnon-virtual-dtor
                                           -Woverloaded-virtual)
  if(RELIEF_STRICT)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
  target_compile_definitions(${target} PRIVATE QT_NO_KEYWORDS
                                               GLM_FORCE_CXX17)
  # Every sanitized executable carries the runtime's defaults (why: SanitizerDefaults.cpp) and
  # counts its heap's peak when asked to (HeapPeak.cpp; tests/cli/LargeMapTest.cpp reads it).
  get_target_property(type ${target} TYPE)
  if(type STREQUAL "EXECUTABLE")
    set_property(TARGET ${target} APPEND PROPERTY BUILD_RPATH ${RELIEF_MODULE_BUILD_DIR})
  endif()
  if((RELIEF_SANITIZE OR RELIEF_FUZZ) AND type STREQUAL "EXECUTABLE")
    target_sources(${target} PRIVATE $<TARGET_OBJECTS:relief_sanitizer_support>)
  endif()
endfunction()

# Compiled once and linked into every executable of a sanitizer build (relief_target_defaults).
if(RELIEF_SANITIZE OR RELIEF_FUZZ)
  add_library(relief_sanitizer_support OBJECT
              ${PROJECT_SOURCE_DIR}/tools/sanitizers/SanitizerDefaults.cpp
              ${PROJECT_SOURCE_DIR}/tools/sanitizers/HeapPeak.cpp)
  target_compile_options(relief_sanitizer_support PRIVATE -Wall -Wextra)
endif()

# relief_precompile(<target> <header>...): the system headers most of a target's files include,
# parsed once per target instead of once per file. With the sanitizers, parsing Qt's, the
# standard library's and GoogleTest's headers was about half of each file's compile time, and
# the test build is most of CI's wall time. Only system headers go in: a project header in the
# set would rebuild the whole target on every change to it. RELIEF_PRECOMPILED_HEADERS=OFF
# (the package build) compiles every file alone, which also proves each file includes what it
# uses.
option(RELIEF_PRECOMPILED_HEADERS "Precompile each target's common system headers" ON)
function(relief_precompile target)
  if(RELIEF_PRECOMPILED_HEADERS)
    list(TRANSFORM ARGN PREPEND "<")
    list(TRANSFORM ARGN APPEND ">")
    target_precompile_headers(${target} PRIVATE ${ARGN})
  endif()
endfunction()
# relief_unity(<target>): compiles the target's files a few at a time as one file (a unity
# build): they include much the same project and Qt headers beyond the precompiled ones, and
# parsing those once per batch instead of once per file took a third off the test executables'
# compile time. Names in a file's anonymous namespace must then differ from those of the other
# files of its target. RELIEF_UNITY_BUILD=OFF (the package build) compiles every file alone.
option(RELIEF_UNITY_BUILD "Compile the heaviest targets' files a few at a time as one" ON)
function(relief_unity target)
  if(RELIEF_UNITY_BUILD)
    set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 6)
  endif()
endfunction()
set(RELIEF_STD_PRECOMPILED algorithm array cmath cstdint cstring functional memory optional string
                           string_view vector)

# relief_folder_sources(<variable> <folder> <Class>...): appends a folder's sources to <variable>,
# one class per name (Class.cpp and Class.h, or only the one that exists: Result.h, BcCodec.cpp).
# The layers' CMakeLists list their folders with it, so the grouping of the code is visible there.
function(relief_folder_sources variable folder)
  set(files ${${variable}})
  foreach(class ${ARGN})
    set(found FALSE)
    foreach(extension cpp h)
      if(EXISTS ${CMAKE_CURRENT_SOURCE_DIR}/${folder}/${class}.${extension})
        list(APPEND files ${folder}/${class}.${extension})
        set(found TRUE)
      endif()
    endforeach()
    if(NOT found)
      message(FATAL_ERROR "${folder}/${class}: neither ${class}.cpp nor ${class}.h exists")
    endif()
  endforeach()
  set(${variable} ${files} PARENT_SCOPE)
endfunction()
