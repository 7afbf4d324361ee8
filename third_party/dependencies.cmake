# Third-party code comes from Debian packages (tools/install-deps.sh). Included from the top level so the
# imported targets are visible everywhere.
set(THREADS_PREFER_PTHREAD_FLAG ON)
find_package(Threads REQUIRED)
find_package(Vulkan REQUIRED)
find_package(glm REQUIRED)
find_package(nlohmann_json 3 REQUIRED)
find_package(PkgConfig REQUIRED)
pkg_check_modules(STB REQUIRED IMPORTED_TARGET GLOBAL stb)

# libpng writes the PNGs (io/png.cpp): its zlib at level 2 with the Sub filter encodes a 1280x720 frame in
# ~35 ms where stb_image_write took ~200 ms, and smaller.
find_package(PNG REQUIRED)

# Images are decoded by the maintained, security-patched libraries (io/image_decode.h): libpng, libjpeg-turbo
# and libwebp (glTF's EXT_texture_webp); nettle computes the dataset manifests' SHA-256 (io/sha256.h).
pkg_check_modules(JPEG REQUIRED IMPORTED_TARGET GLOBAL libjpeg)
pkg_check_modules(WEBP REQUIRED IMPORTED_TARGET GLOBAL libwebp)
pkg_check_modules(NETTLE REQUIRED IMPORTED_TARGET GLOBAL nettle)
add_library(lagoon_codecs INTERFACE)
target_link_libraries(lagoon_codecs INTERFACE PNG::PNG PkgConfig::JPEG PkgConfig::WEBP PkgConfig::NETTLE)

# stb: stb_easy_font (header only) for the text on images, and stb_image_write in the tests (they encode their
# own PNG and JPEG inputs with an encoder independent of the decoders).
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

if(NOT LAGOON_BUILD_DEMO)
  return()  # the window and the panel are the demo's (tools/install-deps.sh run installs neither)
endif()
pkg_check_modules(GLFW REQUIRED IMPORTED_TARGET GLOBAL glfw3)
# Dear ImGui for the demo: the library from libimgui-dev, and the GLFW and Vulkan backends that the package
# ships as sources under its documentation (install-deps.sh extracts them from the .deb into
# /usr/local/share/lagoon/imgui-backends where dpkg is told to skip /usr/share/doc, as in Docker images).
pkg_check_modules(IMGUI REQUIRED IMPORTED_TARGET GLOBAL imgui)
find_path(IMGUI_BACKENDS_DIR imgui_impl_vulkan.cpp
          PATHS /usr/share/doc/libimgui-dev/examples/backends /usr/local/share/lagoon/imgui-backends
          NO_DEFAULT_PATH)
if(NOT IMGUI_BACKENDS_DIR)
  message(FATAL_ERROR "imgui_impl_vulkan.cpp (from libimgui-dev) not found; run tools/install-deps.sh")
endif()
find_path(IMGUI_BACKEND_HEADERS imgui_impl_vulkan.h PATH_SUFFIXES imgui/backends REQUIRED)
add_library(lagoon_imgui STATIC ${IMGUI_BACKENDS_DIR}/imgui_impl_glfw.cpp ${IMGUI_BACKENDS_DIR}/imgui_impl_vulkan.cpp)
target_include_directories(lagoon_imgui SYSTEM PUBLIC ${IMGUI_BACKEND_HEADERS})
target_link_libraries(lagoon_imgui PUBLIC PkgConfig::IMGUI PkgConfig::GLFW Vulkan::Vulkan)
