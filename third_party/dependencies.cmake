# Third-party code comes from Debian packages (tools/install-deps.sh). Included from the top level so the
# imported targets are visible everywhere.
set(THREADS_PREFER_PTHREAD_FLAG ON)
find_package(Threads REQUIRED)
find_package(Vulkan REQUIRED)
find_package(glm REQUIRED)
find_package(nlohmann_json 3 REQUIRED)
find_package(PkgConfig REQUIRED)
pkg_check_modules(STB REQUIRED IMPORTED_TARGET GLOBAL stb)
pkg_check_modules(GLFW REQUIRED IMPORTED_TARGET GLOBAL glfw3)

add_library(lagoon_stb INTERFACE)
target_link_libraries(lagoon_stb INTERFACE PkgConfig::STB)

# FFTW is the CPU reference of the tests and the baseline of `lagoon bench`; never used by the library.
pkg_check_modules(FFTW REQUIRED IMPORTED_TARGET GLOBAL fftw3 fftw3f)
find_library(FFTW3F_THREADS fftw3f_threads REQUIRED)
if(LAGOON_BUILD_TESTS)
  find_package(GTest REQUIRED)
endif()
if(LAGOON_BUILD_BENCHMARKS)
  find_package(benchmark REQUIRED)
endif()
