# Every dependency is a Debian bookworm package; scripts/setup.sh installs the missing ones.
find_package(glm CONFIG REQUIRED)
find_package(ZLIB REQUIRED)
find_package(TBB CONFIG REQUIRED)
find_package(CLI11 CONFIG REQUIRED)
find_package(PNG REQUIRED)  # PNG written directly (src/core/png_writer.cpp)
find_package(OpenImageIO CONFIG REQUIRED)  # every other image format, in a plugin
find_package(embree 3 CONFIG REQUIRED)
find_package(pegtl CONFIG REQUIRED)
find_package(Freetype REQUIRED)
find_package(SDL2 CONFIG REQUIRED)  # the +D preview window (src/display/)
# convray view's text overlays (src/display/view_window.cpp): Debian's SDL2_ttf has no CMake
# config, only its pkg-config file.
find_package(PkgConfig REQUIRED)
pkg_check_modules(SDL2_TTF REQUIRED IMPORTED_TARGET SDL2_ttf)
# .gz meshes inflated in one call where the trailer's size is right (src/mesh/gzip.cpp): about
# twice zlib's speed; zlib stays for everything else. Debian's libdeflate has pkg-config only.
pkg_check_modules(LIBDEFLATE REQUIRED IMPORTED_TARGET libdeflate)

# Debian's OpenImageIO config names /usr/include/opencv4 as an include directory, and CMake
# refuses a missing one; we never use OpenCV, so drop it instead of installing libopencv-dev.
foreach(prop INTERFACE_INCLUDE_DIRECTORIES INTERFACE_SYSTEM_INCLUDE_DIRECTORIES)
  get_target_property(dirs OpenImageIO::OpenImageIO ${prop})
  if(dirs)
    list(FILTER dirs EXCLUDE REGEX "opencv4")
    set_target_properties(OpenImageIO::OpenImageIO PROPERTIES ${prop} "${dirs}")
  endif()
endforeach()

if(CONVRAY_BUILD_TESTS)
  find_package(GTest REQUIRED)
endif()
if(CONVRAY_BUILD_BENCH)
  find_package(benchmark REQUIRED)
endif()
