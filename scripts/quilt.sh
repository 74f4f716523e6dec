#!/usr/bin/env bash
# The main job: builds meshquilt, then quilts the built-in chain-mail swatch over a 4x4 plane
# (or runs `meshquilt synth` with the arguments given). Prints the output path at the end.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh >/dev/null
mkdir -p out
if [ $# -eq 0 ]; then
  set -- -o out/quilt.ply --stats out/quilt.json
fi
exec build/cli/meshquilt synth "$@"
