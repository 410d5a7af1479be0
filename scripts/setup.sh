#!/usr/bin/env bash
# Installs the Debian packages the project needs (only those missing), then configures and
# builds everything into build/. Used by both README commands; safe to run again.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(
  cmake make g++ pkg-config          # tool chain
  libglm-dev libpng-dev              # maths, PNG files
  libvulkan-dev mesa-vulkan-drivers  # Vulkan loader + headers, Mesa lavapipe
  vulkan-validationlayers            # Khronos validation layer, on in every render test
  glslang-tools                      # GLSL -> SPIR-V at build time
  spirv-tools                        # SPIRV-Tools optimiser: the renderer specialises its shaders
  libglfw3-dev xvfb xauth            # windows, and a virtual X server to test them
  libxtst-dev                        # real pointer and key events on the virtual X server
  catch2                             # tests
  clang-format                       # the style test (sources follow .clang-format)
  doxygen                            # the API reference (target docs) and its no-warnings test
  hershey-fonts-data                 # stroke fonts for PHIGS text
  libcairo2-dev                      # PDF, SVG and EPS hardcopy (phigs_hardcopy)
  poppler-utils librsvg2-bin         # the hardcopy tests rasterise PDF and SVG files
  libsisl-dev                        # baseline in the geometry benchmarks
  libocct-foundation-dev             # OpenCASCADE, second baseline in bench_geom_kernel: kernel, maths
  libocct-modeling-data-dev          #   its B-spline surfaces (TKG3d)
  libocct-modeling-algorithms-dev    #   its intersection and projection (TKGeomAlgo)
  libtbb-dev                         #   libtbb.so, named by OpenCASCADE's CMake config
  libocct-data-exchange-dev          # IGES and STEP export and import (geom_exchange)
)
# CI's second sanitizer stage builds the kernel's tests with clang as well (PHIGS_SETUP_CLANG=1).
if [ "${PHIGS_SETUP_CLANG:-0}" = 1 ]; then
  packages+=(clang libclang-rt-14-dev)  # clang 14 and its ASan/UBSan runtime
fi
missing=()
for package in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || missing+=("$package")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}"
  sudo=""
  if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
  export DEBIAN_FRONTEND=noninteractive
  $sudo apt-get update -qq
  $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

build_type="${BUILD_TYPE:-RelWithDebInfo}"
cmake -S . -B build -DCMAKE_BUILD_TYPE="$build_type" ${CMAKE_ARGS:-}
cmake --build build -j"$(nproc)"
