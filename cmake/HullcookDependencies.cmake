# Every third-party package comes from Debian 12 (scripts/setup installs them).
find_package(glm REQUIRED)
# Images: libpng and libwebp directly (OpenCV's imgcodecs loads some 120 shared libraries at every
# start of hullcook); zlib for the PNG checksums.
find_package(PNG REQUIRED)
find_package(ZLIB REQUIRED)
find_package(PkgConfig REQUIRED)
pkg_check_modules(WebP REQUIRED IMPORTED_TARGET libwebp)
find_package(TinyGLTF REQUIRED)
find_package(draco REQUIRED)
# EXT_meshopt_compression (glTF --meshopt), libmeshoptimizer-dev.
find_package(meshoptimizer REQUIRED)
find_package(nlohmann_json 3 REQUIRED)
find_package(CLI11 REQUIRED)
find_package(Threads REQUIRED)
if(HULLCOOK_BUILD_ADAPTERS)
  find_package(box2d 2.4 REQUIRED)
  find_package(Chipmunk 7 REQUIRED)
endif()
if(HULLCOOK_BUILD_TESTS)
  find_package(GTest REQUIRED)
  # Only the tests: they draw images with it and check the decoders against its imdecode.
  find_package(OpenCV REQUIRED COMPONENTS core imgproc imgcodecs)
endif()
if(HULLCOOK_BUILD_BENCHMARKS)
  find_package(benchmark REQUIRED)
endif()
