#!/usr/bin/env bash
# Installs Lagoon's dependencies from Debian 12 packages.
#   install-deps.sh run    what building and running the `lagoon` command needs (make run)
#   install-deps.sh [all]  that, plus the demo, the tests, the fuzz targets and the style check (make test)
# Idempotent: apt-get runs only when a package is missing. Works as root or through sudo.
set -euo pipefail

profile=${1:-all}
case $profile in
  run | all) ;;
  *) echo "install-deps: unknown profile '$profile' (use 'run' or 'all')" >&2; exit 2 ;;
esac

packages=(
  # toolchain (a minimal Debian has none of it)
  g++ cmake make ninja-build pkg-config ca-certificates
  # Vulkan: loader and lavapipe (a CPU device), the shader compiler
  libvulkan-dev mesa-vulkan-drivers glslang-tools
  # header and small libraries the command uses; FFTW is the CPU baseline of `lagoon bench compute`
  libglm-dev libtinygltf-dev libstb-dev libpng-dev nlohmann-json3-dev libfftw3-dev
  # image decoding (PNG, JPEG, WebP) and the dataset manifests' SHA-256, by maintained libraries
  libjpeg62-turbo-dev libwebp-dev nettle-dev
)
if [[ $profile == all ]]; then
  packages+=(
    # the validation layer every Vulkan test runs with, SPIR-V tools, the style check
    vulkan-validationlayers spirv-tools clang-format
    # tools/convert-compass.py and its test
    python3
    # the demo: window and panel
    libglfw3-dev libimgui-dev
    # tests and benchmarks; clang-14 with libFuzzer's runtime builds the fuzz targets (tests/fuzz)
    libgtest-dev libbenchmark-dev clang-14 libclang-rt-14-dev
    # headless window tests
    xvfb xauth
    # the Python module (apps/python) and its tests
    pybind11-dev python3-dev python3-numpy python3-pytest
  )
fi

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$p")
done

# libimgui-dev ships its GLFW and Vulkan backends as sources under /usr/share/doc, which images built with
# a dpkg path-exclude for docs (Docker's Debian) leave out; then they are taken from the same .deb.
backends=/usr/share/doc/libimgui-dev/examples/backends
extracted=/usr/local/share/lagoon/imgui-backends
need_backends() {
  [[ $profile == all && ! -f $backends/imgui_impl_vulkan.cpp && ! -f $extracted/imgui_impl_vulkan.cpp ]]
}

if [[ ${#missing[@]} -eq 0 ]] && ! need_backends; then
  echo "install-deps: all ${#packages[@]} packages of '$profile' present"
  exit 0
fi

sudo_cmd=()
if [[ $(id -u) -ne 0 ]]; then
  command -v sudo >/dev/null || { echo "install-deps: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
  sudo_cmd=(sudo)
fi

export DEBIAN_FRONTEND=noninteractive
if [[ ${#missing[@]} -gt 0 ]]; then
  echo "install-deps: installing ${#missing[@]} packages for '$profile' (and what they need): ${missing[*]}"
  "${sudo_cmd[@]}" apt-get update -q
  "${sudo_cmd[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

if need_backends; then
  echo "install-deps: extracting the ImGui backends from libimgui-dev into $extracted"
  tmp=$(mktemp -d)
  trap 'rm -rf "$tmp"' EXIT
  version=$(dpkg-query -W -f='${Version}' libimgui-dev)
  [[ ${#missing[@]} -gt 0 ]] || "${sudo_cmd[@]}" apt-get update -q  # download needs the package lists
  (cd "$tmp" && apt-get download -q "libimgui-dev=$version")
  dpkg-deb -x "$tmp"/libimgui-dev_*.deb "$tmp/root"
  "${sudo_cmd[@]}" mkdir -p "$extracted"
  "${sudo_cmd[@]}" cp "$tmp/root$backends"/imgui_impl_{glfw,vulkan}.cpp "$extracted/"
fi
