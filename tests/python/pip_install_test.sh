#!/usr/bin/env bash
# `python3 -m pip install --no-build-isolation .` in a fresh venv made with
# --system-site-packages: it drives the project's CMake (reusing BUILD, so no third full build),
# installs the package, and the installed module gives what `meshquilt synth` gives.
# usage: pip_install_test.sh SOURCE BUILD MESHQUILT_CLI
set -euo pipefail
source_dir=$1 build_dir=$2 cli=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
/usr/bin/python3 -m venv --system-site-packages "$work/venv"
cd "$source_dir"
MESHQUILT_BUILD_DIR="$build_dir" "$work/venv/bin/python" -m pip install --no-build-isolation --no-index -q . \
  2> "$work/pip.log" || { cat "$work/pip.log" >&2; exit 1; }
cd "$work"
"$cli" synth --plane 2x2 --seed 1 --backend cpu --progress none -o "$work/cli.ply" > /dev/null
"$work/venv/bin/python" - "$work/cli.ply" <<'PY'
import struct, sys
import numpy as np
import meshquilt
assert "venv" in meshquilt.__file__, meshquilt.__file__
data = open(sys.argv[1], "rb").read()
end = data.index(b"end_header\n") + len(b"end_header\n")
header = data[:end].decode().split("\n")
nv = int(next(l for l in header if l.startswith("element vertex")).split()[2])
nf = int(next(l for l in header if l.startswith("element face")).split()[2])
v = np.frombuffer(data, dtype="<f8", count=3 * nv, offset=end).reshape(nv, 3)
rows = np.frombuffer(data, dtype=np.dtype([("n", "u1"), ("v", "<i4", 3), ("e", "<i4"), ("s", "<i4")]), count=nf,
                     offset=end + 24 * nv)
r = meshquilt.synth(plane=(2, 2), seed=1, backend="cpu")
assert np.array_equal(r.vertices, v), "vertices differ"
assert np.array_equal(r.faces, rows["v"]), "faces differ"
print(f"installed module = CLI: {nv} vertices, {nf} faces")
PY
