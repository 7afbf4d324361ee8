#!/usr/bin/env bash
# Installs Lagoon's build and test dependencies from Debian 12 packages.
# Idempotent: apt-get runs only when a package is missing. Works as root or through sudo.
set -euo pipefail

packages=(
  # toolchain (a minimal Debian has none of it)
  g++ cmake make pkg-config ca-certificates clang-format
  # Vulkan: loader, lavapipe (CPU device), validation layer, shader compiler and tools
  libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers glslang-tools spirv-tools
  # libraries
  libglfw3-dev libglm-dev libtinygltf-dev libimgui-dev libstb-dev nlohmann-json3-dev
  # tests and benchmarks; clang-14 with libFuzzer's runtime builds the fuzz targets (tests/fuzz)
  libgtest-dev libbenchmark-dev libfftw3-dev clang-14 libclang-rt-14-dev
  # headless window tests
  xvfb xauth
)

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$p")
done

# libimgui-dev ships its GLFW and Vulkan backends as sources under /usr/share/doc, which images built with
# a dpkg path-exclude for docs (Docker's Debian) leave out; then they are taken from the same .deb.
backends=/usr/share/doc/libimgui-dev/examples/backends
extracted=/usr/local/share/lagoon/imgui-backends
need_backends() { [[ ! -f $backends/imgui_impl_vulkan.cpp && ! -f $extracted/imgui_impl_vulkan.cpp ]]; }

if [[ ${#missing[@]} -eq 0 ]] && ! need_backends; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

sudo_cmd=()
if [[ $(id -u) -ne 0 ]]; then
  command -v sudo >/dev/null || { echo "install-deps: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
  sudo_cmd=(sudo)
fi

export DEBIAN_FRONTEND=noninteractive
if [[ ${#missing[@]} -gt 0 ]]; then
  echo "install-deps: installing ${missing[*]}"
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
