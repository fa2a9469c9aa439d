# Finds every third-party dependency once, with the workarounds Debian 12's packages need.
find_package(Qt6 6.4 REQUIRED COMPONENTS Core Gui Widgets OpenGL OpenGLWidgets Concurrent Charts Test)
find_package(OpenImageIO REQUIRED CONFIG)
# OpenEXR's own library writes the EXR files tests/core/ImageConformanceTest.cpp reads (an
# independent writer); the app reads EXR through OpenImageIO.
find_package(OpenEXR REQUIRED CONFIG)
find_package(glm REQUIRED)
find_package(assimp REQUIRED)
find_package(Threads REQUIRED)
find_package(PkgConfig REQUIRED)
pkg_check_modules(FFTW3F REQUIRED IMPORTED_TARGET fftw3f)
find_library(FFTW3F_THREADS_LIBRARY fftw3f_threads REQUIRED)
# zlib for Relief's own PNG writer (core/image/PngWriter.h).
find_package(ZLIB REQUIRED)
# libdeflate for its reader (core/image/PngReader.h): whole-buffer inflate at 2.5x zlib's speed.
pkg_check_modules(DEFLATE REQUIRED IMPORTED_TARGET libdeflate)
# Zstandard for KTX2 supercompression (scheme 2).
pkg_check_modules(ZSTD REQUIRED IMPORTED_TARGET libzstd)

# Debian's OpenImageIO config lists /usr/include/opencv4 as an include directory even when
# OpenCV's headers are absent, which makes CMake refuse to generate. Drop that entry.
foreach(prop INTERFACE_INCLUDE_DIRECTORIES INTERFACE_SYSTEM_INCLUDE_DIRECTORIES)
  get_target_property(dirs OpenImageIO::OpenImageIO ${prop})
  if(dirs)
    list(FILTER dirs EXCLUDE REGEX "opencv4")
    set_target_properties(OpenImageIO::OpenImageIO PROPERTIES ${prop} "${dirs}")
  endif()
endforeach()

# Texture codecs. libsquish has no CMake config and an empty pkg-config prefix.
# android-libetc1 (ETC1), which only the tests link to compare Relief's ETC1 encoder with, lives in
# a private folder without any metadata, so it is linked by path with an rpath (CMake adds it for
# full library paths outside the system folders).
find_path(SQUISH_INCLUDE_DIR squish.h REQUIRED)
find_library(SQUISH_LIBRARY squish REQUIRED)
add_library(relief_squish INTERFACE)
target_include_directories(relief_squish SYSTEM INTERFACE ${SQUISH_INCLUDE_DIR})
target_link_libraries(relief_squish INTERFACE ${SQUISH_LIBRARY})

find_package(astcenc REQUIRED CONFIG)

find_path(ETC1_INCLUDE_DIR android/ETC1/etc1.h REQUIRED)
find_library(ETC1_LIBRARY ETC1 PATHS /usr/lib/x86_64-linux-gnu/android /usr/lib/android
             PATH_SUFFIXES android REQUIRED)
add_library(relief_etc1 INTERFACE)
target_include_directories(relief_etc1 SYSTEM INTERFACE ${ETC1_INCLUDE_DIR})
target_link_libraries(relief_etc1 INTERFACE ${ETC1_LIBRARY})
