#!/usr/bin/env bash
# The main job: builds meshquilt, then covers the sphere shipped in data/ with the built-in chain
# mail (or runs `meshquilt synth` with the arguments given). Prints the output path at the end.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh >/dev/null
mkdir -p out
if [ $# -eq 0 ]; then
  set -- --base data/sphere.off --scale 0.2 -o out/quilt.ply --stats out/quilt.json --preview out/quilt.png
fi
exec build/cli/meshquilt synth "$@"
