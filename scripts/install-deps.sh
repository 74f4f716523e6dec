#!/usr/bin/env bash
# Installs every build and test dependency of meshquilt from Debian's packages (run as root).
set -euo pipefail
packages=(
  build-essential cmake ninja-build pkg-config
  libvulkan-dev mesa-vulkan-drivers vulkan-tools
  glslang-tools glslang-dev spirv-tools
  libembree-dev libpng-dev libtbb-dev libeigen3-dev libglm-dev libopenmesh-dev
  libboost-graph-dev
  libcli11-dev nlohmann-json3-dev libgtest-dev libgmock-dev libbenchmark-dev
  python3
  clang-14 libclang-rt-14-dev
  slurm-wlm munge
)
# With --tests, what only the tests need: tests/foreign/make_swatches.py builds foreign swatches
# with numpy, tests/paint/field_stripes.py solves for reference stripes with scipy, and the Python module (built when pybind11 is there) is tested with pytest and
# installed with pip into a venv, and the Blender add-on runs headless in Debian's Blender and in
# its window under Xvfb (the build and every job run without them).
if [ "${1:-}" = "--tests" ]; then
  packages+=(python3-numpy python3-scipy python3-dev python3-pybind11 pybind11-dev python3-pytest python3-venv python3-pip
             python3-setuptools python3-wheel blender xvfb xauth)
fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
