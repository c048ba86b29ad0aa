#!/usr/bin/env bash
# Installs every Debian 12 package Kiln needs to build, test and run. Idempotent: packages already
# present are left alone and apt is not touched at all when nothing is missing.
set -euo pipefail

PACKAGES=(
    # build tools
    build-essential cmake ninja-build pkg-config git python3
    clang libclang-rt-14-dev llvm
    # shader toolchain
    glslang-dev glslang-tools spirv-tools spirv-headers libspirv-cross-c-shared-dev
    # runtime
    libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers vulkan-tools
    libopencolorio-dev libglm-dev libtinygltf-dev libstb-dev libjpeg-dev
    # utilities
    nlohmann-json3-dev libcli11-dev libxxhash-dev
    # kiln and kiln-worker's allocator (tools/CMakeLists.txt)
    libjemalloc-dev
    # the accuracy report's figure (PNG and SVG from one drawing, with real fonts)
    libcairo2-dev fonts-dejavu-core zlib1g-dev
    # tests and benchmarks
    libgtest-dev libgmock-dev libbenchmark-dev
    # the frame debugger's page, opened headless by its test
    chromium
)

missing=()
for p in "${PACKAGES[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
        missing+=("$p")
    fi
done

if [ ${#missing[@]} -eq 0 ]; then
    echo "setup: all ${#PACKAGES[@]} packages already installed"
    exit 0
fi

echo "setup: installing ${#missing[@]} packages: ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then
    SUDO="sudo"
fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
$SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
echo "setup: done"
