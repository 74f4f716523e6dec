#!/usr/bin/env bash
# Installs the dependencies (Debian packages; needs root or sudo) and builds meshquilt into build/.
# --tests adds what only the tests need.
set -euo pipefail
cd "$(dirname "$0")/.."
if [ "$(id -u)" = 0 ]; then
  bash scripts/install-deps.sh "$@"
elif command -v sudo >/dev/null; then
  sudo bash scripts/install-deps.sh "$@"
else
  echo "meshquilt: not root and no sudo: assuming the packages of scripts/install-deps.sh are installed" >&2
fi
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)"
