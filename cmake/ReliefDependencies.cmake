# Finds every third-party dependency once, with the workarounds PLATFORM.md documents.
find_package(Qt6 6.4 REQUIRED COMPONENTS Core Gui Widgets OpenGL OpenGLWidgets Concurrent Test)
find_package(OpenImageIO REQUIRED CONFIG)
find_package(glm REQUIRED)
find_package(assimp REQUIRED)
find_package(Threads REQUIRED)
find_package(PkgConfig REQUIRED)
pkg_check_modules(FFTW3F REQUIRED IMPORTED_TARGET fftw3f)
find_library(FFTW3F_THREADS_LIBRARY fftw3f_threads REQUIRED)

# Debian's OpenImageIO config lists /usr/include/opencv4 as an include directory even when
# OpenCV's headers are absent, which makes CMake refuse to generate. Drop that entry.
foreach(prop INTERFACE_INCLUDE_DIRECTORIES INTERFACE_SYSTEM_INCLUDE_DIRECTORIES)
  get_target_property(dirs OpenImageIO::OpenImageIO ${prop})
  if(dirs)
    list(FILTER dirs EXCLUDE REGEX "opencv4")
    set_target_properties(OpenImageIO::OpenImageIO PROPERTIES ${prop} "${dirs}")
  endif()
endforeach()
