#!/usr/bin/env bash
# The stochastic sample of paint_samples.py (numpy) over bunny.off at --scale 0.125, read back by
# paint_neighbourhoods.py (written apart from the painter): at most 1.5x the sample's own
# leave-one-out distance and half a planar projection's, #44's bars. At the default 0.25 the
# bunny's curvature, a quarter of the sample's width, breaks the copies into patches too small
# for the second bar (0.61); at 0.125 seed 1 reads 0.46 (seeds 2 and 3: 0.50, 0.51). The striped
# sample along data/bunny_field.json at the default scale: half its projection and within 10
# degrees of the field (its leave-one-out distance is only the sample's noise: decision 0046).
# usage: paint_bunny_test.sh MESHQUILT SHARED_MESHES WORK_DIR
set -euo pipefail
meshquilt=$1 meshes=$2 work=$3
here=$(dirname "$0")
[ -f "$meshes/bunny.off" ] || { echo "skipped: $meshes not found"; exit 77; }
source "$here/numpy_python.sh"
mkdir -p "$work"
"$python" "$here/paint_samples.py" "$work" 5
out=$work/bunny-stochastic
"$meshquilt" paint --base "$meshes/bunny.off" --image "$work/stochastic.ppm" --scale 0.125 --seed 1 --backend cpu \
  --progress none --stats "$out.json" --write-field "$out.field" -o "$out.ply"
"$python" "$here/paint_neighbourhoods.py" --painted "$out.ply" --field "$out.field" --sample "$work/stochastic.ppm" \
  --stats "$out.json" --max-loo-ratio 1.5 --max-projection-ratio 0.5
out=$work/bunny-striped
"$meshquilt" paint --base "$meshes/bunny.off" --image "$work/striped.ppm" --field "$here/../../data/bunny_field.json" \
  --backend cpu --progress none --stats "$out.json" --write-field "$out.field" -o "$out.ply"
"$python" "$here/paint_neighbourhoods.py" --painted "$out.ply" --field "$out.field" --sample "$work/striped.ppm" \
  --stats "$out.json" --stripes --max-projection-ratio 0.5 --max-stripe-angle 10
