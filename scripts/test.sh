#!/usr/bin/env bash
# Builds meshquilt and runs every test (unit, back-end parity on lavapipe and CPU, end to end).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh --tests
ctest --test-dir build --output-on-failure -j"$(nproc)" --timeout 900
# Then the same tests (less the labels end_to_end, slow) under ASan+UBSan, fuzz corpora included,
# and 10 s of each libFuzzer target: a memory error, leak or undefined behaviour fails the run.
bash scripts/sanitize.sh
bash scripts/fuzz.sh 10
