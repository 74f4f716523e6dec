#!/usr/bin/env bash
# Paint over the plane along a drawn field at 35 degrees to its axes, and over the cylinder
# along its axis (curved, but its stripes can run straight and evenly spaced, as on the plane),
# from samples made by paint_samples.py (numpy): paint_neighbourhoods.py, written apart from the
# painter, reads 7 x 7 neighbourhoods back in the field's frame and compares them with the
# sample's. Each must be at most 1.5x the sample's own leave-one-out distance and half a planar
# projection's, and the stripes must run within 10 degrees of the field. Over the bunny, along
# its drawn field (which turns under every window), the height map holds both bars too. A sample
# of odd sides (63 x 47) runs coarse to fine over three sizes and reads over the sphere within
# three quarters of its projection (a single level, as before odd sides were halved, read 0.87).
# usage: paint_neighbourhoods_test.sh MESHQUILT SHARED_MESHES WORK_DIR
set -euo pipefail
meshquilt=$1 meshes=$2 work=$3
here=$(dirname "$0")
[ -f "$meshes/plane.off" ] && [ -f "$meshes/cylinder.off" ] && [ -f "$meshes/bunny.off" ] || { echo "skipped: $meshes not found"; exit 77; }
source "$(dirname "$0")/numpy_python.sh"
mkdir -p "$work"
"$python" "$here/paint_samples.py" "$work" 5
echo '{"directions": [{"point": [0, 0, 0], "direction": [0.7071068, 0, 0.7071068]}]}' > "$work/plane.json"
echo '{"directions": [{"point": [1.5, 1, 0], "direction": [1, 0, 0]}]}' > "$work/cylinder.json"
for base in plane cylinder; do
  for sample in stochastic striped; do
    out=$work/$base-$sample
    "$meshquilt" paint --base "$meshes/$base.off" --image "$work/$sample.ppm" --field "$work/$base.json" \
      --stats "$out.json" --write-field "$out.field" -o "$out.ply"
    stripes=()
    [ "$sample" = striped ] && stripes=(--stripes --max-stripe-angle 10)
    "$python" "$here/paint_neighbourhoods.py" --painted "$out.ply" --field "$out.field" \
      --sample "$work/$sample.ppm" --stats "$out.json" --max-loo-ratio 1.5 --max-projection-ratio 0.5 \
      "${stripes[@]}"
  done
done
out=$work/sphere-odd
"$meshquilt" paint --base "$here/../../data/sphere.off" --image "$work/odd.ppm" --backend cpu \
  --stats "$out.json" --write-field "$out.field" -o "$out.ply"
grep -q '"sample_levels": 3' "$out.json" || { echo "odd.ppm: expected 3 sample levels"; cat "$out.json"; exit 1; }
"$python" "$here/paint_neighbourhoods.py" --painted "$out.ply" --field "$out.field" --sample "$work/odd.ppm" \
  --stats "$out.json" --max-loo-ratio 1.5 --max-projection-ratio 0.75
out=$work/bunny-heights
"$meshquilt" paint --base "$meshes/bunny.off" --image "$work/heights.pgm" --field "$here/../../data/bunny_field.json" \
  --stats "$out.json" --write-field "$out.field" -o "$out.ply"
"$python" "$here/paint_neighbourhoods.py" --painted "$out.ply" --field "$out.field" --sample "$work/heights.pgm" \
  --stats "$out.json" --max-loo-ratio 1.5 --max-projection-ratio 0.5
