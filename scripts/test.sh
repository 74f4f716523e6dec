#!/usr/bin/env bash
# Builds meshquilt and runs every test (unit, back-end parity on lavapipe and CPU, end to end).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
ctest --test-dir build --output-on-failure -j"$(nproc)" --timeout 900
