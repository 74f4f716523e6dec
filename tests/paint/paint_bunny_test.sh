#!/usr/bin/env bash
# The stochastic sample of paint_samples.py (numpy) over bunny.off at --scale 0.125, read back by
# paint_neighbourhoods.py (written apart from the painter): at most 1.5x the sample's own
# leave-one-out distance and half a planar projection's, #44's bars. At the default 0.25 the
# bunny's curvature, a quarter of the sample's width, breaks the copies into patches too small
# for the second bar (0.61); at 0.125 seed 1 reads 0.46 (seeds 2 and 3: 0.50, 0.51). The striped
# sample along data/bunny_field.json at the default scale: half its projection, within 10 degrees
# of the field, and within 1.15x of the best stripes that field allows (field_stripes.py, scipy),
# since no stripes along it come near its leave-one-out bar (decision 0047). That reference is
# first checked over the cylinder along its axis, where the best stripes are rings.
# usage: paint_bunny_test.sh MESHQUILT SHARED_MESHES WORK_DIR
set -euo pipefail
meshquilt=$1 meshes=$2 work=$3
here=$(dirname "$0")
[ -f "$meshes/bunny.off" ] || { echo "skipped: $meshes not found"; exit 77; }
source "$here/numpy_python.sh"
"$python" -c "import scipy" 2>/dev/null || { echo "skipped: no scipy (Debian: apt-get install python3-scipy)"; exit 77; }
mkdir -p "$work"
"$python" "$here/paint_samples.py" "$work" 5
out=$work/bunny-stochastic
"$meshquilt" paint --base "$meshes/bunny.off" --image "$work/stochastic.ppm" --scale 0.125 --seed 1 --backend cpu \
  --progress none --stats "$out.json" --write-field "$out.field" -o "$out.ply"
"$python" "$here/paint_neighbourhoods.py" --painted "$out.ply" --field "$out.field" --sample "$work/stochastic.ppm" \
  --stats "$out.json" --max-loo-ratio 1.5 --max-projection-ratio 0.5
out=$work/cylinder-striped
echo '{"directions": [{"point": [1.5, 1, 0], "direction": [1, 0, 0]}]}' > "$work/cylinder.json"
"$meshquilt" paint --base "$meshes/cylinder.off" --image "$work/striped.ppm" --field "$work/cylinder.json" \
  --backend cpu --progress none --stats "$out.json" --write-field "$out.field" -o "$out.ply"
"$python" "$here/field_stripes.py" "$out.ply" "$out.field" "$out.json" "$out.best.ply"
"$python" "$here/paint_neighbourhoods.py" --painted "$out.best.ply" --field "$out.field" \
  --sample "$work/striped.ppm" --stats "$out.json" --stripes --max-loo-ratio 1 --max-stripe-angle 0.5
out=$work/bunny-striped
"$meshquilt" paint --base "$meshes/bunny.off" --image "$work/striped.ppm" --field "$here/../../data/bunny_field.json" \
  --backend cpu --progress none --stats "$out.json" --write-field "$out.field" -o "$out.ply"
"$python" "$here/field_stripes.py" "$out.ply" "$out.field" "$out.json" "$out.best.ply"
"$python" "$here/paint_neighbourhoods.py" --painted "$out.ply" --field "$out.field" --sample "$work/striped.ppm" \
  --stats "$out.json" --stripes --max-projection-ratio 0.5 --max-stripe-angle 10 \
  --reference "$out.best.ply" --max-reference-ratio 1.15
