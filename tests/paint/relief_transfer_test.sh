#!/usr/bin/env bash
# armadillo.off's detail raised over bunny.off: the heights, read back from the geometry by
# relief_heights.py (numpy, apart from the synthesizer), must be distributed as the sample's grey
# levels (two-sample KS <= 0.1) and their neighbourhoods within 1.5x the sample's leave-one-out
# distance (paint_neighbourhoods.py), and the result closed with no face passing through another
# and none turned over.
# The heights as synthesized, before the geometry clamps and tilts them (paint over the same
# sample at the same pitch, as relief synthesizes it), also meet half a planar projection's
# distance; read back through the geometry they do not (decision 0048).
# usage: relief_transfer_test.sh MESHQUILT SHARED_MESHES WORK_DIR
set -euo pipefail
meshquilt=$1 meshes=$2 work=$3
[ -f "$meshes/armadillo.off" ] && [ -f "$meshes/bunny.off" ] || { echo "skipped: $meshes not found"; exit 77; }
source "$(dirname "$0")/numpy_python.sh"
mkdir -p "$work"
# The detail at its own height, scaled as its width is (1.9% of the bunny's diagonal at
# --scale 0.1): raised along the base's smooth normals, 5% of the vertices are clamped to their
# room and KS is 0.052; at the default --scale 0.25 (4.8%), 0.115.
"$meshquilt" relief --base "$meshes/bunny.off" --from "$meshes/armadillo.off" --scale 0.1 \
  --write-sample "$work/sample.pgm" --write-field "$work/relief.field" --stats "$work/stats.json" \
  -o "$work/relief.ply"
"$python" "$(dirname "$0")/relief_heights.py" --base "$meshes/bunny.off" --relief "$work/relief.ply" \
  --sample "$work/sample.pgm" --stats "$work/stats.json" --max-ks 0.1
"$python" "$(dirname "$0")/paint_neighbourhoods.py" --painted "$work/relief.ply" --field "$work/relief.field" \
  --sample "$work/sample.pgm" --stats "$work/stats.json" --heights-over "$meshes/bunny.off" --max-loo-ratio 1.5
pixels_per_unit=$("$python" -c 'import json, sys; print(repr(json.load(open(sys.argv[1]))["pixels_per_unit"]))' \
  "$work/stats.json")
"$meshquilt" paint --base "$meshes/bunny.off" --image "$work/sample.pgm" --pixels-per-unit "$pixels_per_unit" \
  --progress none --stats "$work/painted.json" --write-field "$work/painted.field" -o "$work/painted.ply"
"$python" "$(dirname "$0")/paint_neighbourhoods.py" --painted "$work/painted.ply" --field "$work/painted.field" \
  --sample "$work/sample.pgm" --stats "$work/painted.json" --max-loo-ratio 1.5 --max-projection-ratio 0.5
# No face turned over against the base as refined alike (paint's output: the same split).
"$python" - "$(dirname "$0")" "$work/relief.ply" "$work/painted.ply" <<'PY'
import sys
import numpy as np
sys.path.insert(0, sys.argv[1])
from relief_heights import read_ply
raised, faces, _ = read_ply(sys.argv[2])
base, base_faces, _ = read_ply(sys.argv[3])
if not np.array_equal(faces, base_faces):
    sys.exit("relief and paint refined the bunny differently")
normal = lambda v: np.cross(v[faces[:, 1]] - v[faces[:, 0]], v[faces[:, 2]] - v[faces[:, 0]])
turned = int((np.einsum("ij,ij->i", normal(raised), normal(base)) < 0).sum())
print("turned faces:", turned)
sys.exit(1 if turned else 0)
PY
"$meshquilt" inspect "$work/relief.ply" --json > "$work/inspect.json"
"$python" - "$work/inspect.json" <<'PY'
import json, sys
report = json.load(open(sys.argv[1]))
bad = {k: report[k] for k in ("boundary_edges", "nonmanifold_edges", "self_intersecting_face_pairs") if report[k] != 0}
print("inspect:", {k: report[k] for k in ("faces", "boundary_edges", "self_intersecting_face_pairs")})
sys.exit(1 if bad else 0)
PY
