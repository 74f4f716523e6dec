#!/usr/bin/env python3
"""`meshquilt loom` end to end, judged from its output alone (issue: the loom).

A design of three regions (plain, twill 2/2, satin 4/1) woven from three exemplars: the plain
one made by make_exemplar.py (numpy, not meshquilt), the others by `meshquilt swatch weave`.
The fabric is judged as a reader of its files would: a ray cast down at each crossing of the
stats' `loom.grid` must hit the yarn the design puts on top; every yarn is one closed element;
warps and wefts run the design's extent; no two yarns meet. The naive assignment is judged the
same way beside it.

    loom_cli_test.py MESHQUILT WORKDIR [--size N] [--stations S] [--sides K]
Exit 77 (skipped) where numpy is missing.
"""
import argparse
import json
import os
import subprocess
import sys

try:
    import numpy as np
except ImportError:  # another Python of this machine may have it (Debian's, beside a pyenv one)
    for candidate in ("/usr/bin/python3", "python3"):
        if candidate != sys.executable and subprocess.run([candidate, "-c", "import numpy"],
                                                          capture_output=True).returncode == 0:
            os.execvp(candidate, [candidate] + sys.argv)
    print("skipped: no Python with numpy (Debian: apt-get install python3-numpy)")
    sys.exit(77)

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from loom_design import three_regions, write_pbm  # noqa: E402


def read_ply(path):
    """Vertices (V, 3) and faces (F, 3) with their per-face `element` from a binary PLY."""
    with open(path, "rb") as f:
        data = f.read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode().splitlines()
    counts, vertex_props, face_props, current = {}, [], [], None
    for line in header:
        words = line.split()
        if words[0] == "element":
            current = words[1]
            counts[current] = int(words[2])
        elif words[0] == "property" and current == "vertex":
            vertex_props.append((words[2], {"double": "<f8", "float": "<f4"}[words[1]]))
        elif words[0] == "property" and current == "face" and words[1] != "list":
            face_props.append((words[2], {"int": "<i4", "uint": "<u4"}[words[1]]))
    vertices = np.frombuffer(data, dtype=vertex_props, count=counts["vertex"], offset=end)
    offset = end + vertices.nbytes
    faces = np.frombuffer(data, dtype=[("n", "u1"), ("v", "<i4", 3)] + face_props, count=counts["face"], offset=offset)
    xyz = np.stack([vertices["x"], vertices["y"], vertices["z"]], -1).astype(np.float64)
    return xyz, faces["v"].astype(np.int64), faces["element"].astype(np.int64)


def judge(xyz, faces, element, grid, pattern):
    """Share of crossings whose topmost yarn, by a ray cast down at the crossing, is the design's."""
    rows, columns = grid["rows"], grid["columns"]
    origin, row_step, column_step = (np.array(grid[k]) for k in ("origin", "row_step", "column_step"))
    tri = xyz[faces]
    centroid = tri.mean(axis=1)[:, :2]
    # Each face's nearest crossing, to look only at faces around a crossing.
    basis = np.linalg.inv(np.stack([row_step, column_step], -1))
    rc = np.rint((centroid - origin) @ basis.T).astype(np.int64)
    buckets = {}
    order = np.lexsort((rc[:, 1], rc[:, 0], element))
    keys = np.stack([element[order], rc[order, 0], rc[order, 1]], -1)
    starts = np.flatnonzero(np.r_[True, np.any(keys[1:] != keys[:-1], axis=1)])
    for s, e in zip(starts, np.r_[starts[1:], len(order)]):
        buckets[tuple(keys[s])] = order[s:e]
    right = 0
    for r in range(rows):
        for c in range(columns):
            p = origin + r * row_step + c * column_step
            best, warp = -np.inf, None
            for yarn in (c, columns + r):
                near = [buckets.get((yarn, r + dr, c + dc)) for dr in (-1, 0, 1) for dc in (-1, 0, 1)]
                near = np.concatenate([n for n in near if n is not None]) if any(n is not None for n in near) else None
                if near is None:
                    continue
                a, b, q = tri[near, 0], tri[near, 1], tri[near, 2]
                d = (b[:, 0] - a[:, 0]) * (q[:, 1] - a[:, 1]) - (q[:, 0] - a[:, 0]) * (b[:, 1] - a[:, 1])
                ok = np.abs(d) > 1e-15
                u = ((p[0] - a[:, 0]) * (q[:, 1] - a[:, 1]) - (q[:, 0] - a[:, 0]) * (p[1] - a[:, 1])) / np.where(ok, d, 1)
                v = ((b[:, 0] - a[:, 0]) * (p[1] - a[:, 1]) - (p[0] - a[:, 0]) * (b[:, 1] - a[:, 1])) / np.where(ok, d, 1)
                hit = ok & (u >= 0) & (v >= 0) & (u + v <= 1)
                if hit.any():
                    z = (a[:, 2] + u * (b[:, 2] - a[:, 2]) + v * (q[:, 2] - a[:, 2]))[hit].max()
                    if z > best:
                        best, warp = z, yarn == c
            right += warp is not None and warp == bool(pattern[r, c])
    return right / (rows * columns)


def run(cli, *args):
    done = subprocess.run([cli, *args], capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit("FAIL: meshquilt %s: exit %d: %s" % (" ".join(args), done.returncode, done.stderr.strip()))
    return done.stdout


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("cli")
    parser.add_argument("work")
    parser.add_argument("--size", type=int, default=64)
    parser.add_argument("--stations", type=int, default=8)
    parser.add_argument("--sides", type=int, default=8)
    parser.add_argument("--no-intersections-up-to", type=int, default=32)
    args = parser.parse_args()
    os.makedirs(args.work, exist_ok=True)
    w = lambda name: os.path.join(args.work, name)
    subprocess.run([sys.executable, os.path.join(HERE, "make_exemplar.py"), w("plain.obj"), "--tilt", "7"], check=True)
    run(args.cli, "swatch", "weave", "--pattern", "twill:2/2", "--warps", "8", "--wefts", "8", "-o", w("twill.ply"))
    run(args.cli, "swatch", "weave", "--pattern", "satin:4/1", "--warps", "10", "--wefts", "10", "--sides", "6",
        "-o", w("satin.ply"))
    rows = three_regions(args.size)
    write_pbm(w("design.pbm"), rows)
    pattern = np.array(rows, dtype=np.uint8)
    failures = []
    scores = {}
    for method in ("structured", "naive"):
        out, stats = w(method + ".ply"), w(method + ".json")
        run(args.cli, "loom", "--design", w("design.pbm"), "--exemplar", w("plain.obj"), "--exemplar", w("twill.ply"),
            "--exemplar", w("satin.ply"), "--method", method, "--stations", str(args.stations), "--sides",
            str(args.sides), "-o", out, "--stats", stats, "--progress", "none")
        with open(stats) as f:
            loom = json.load(f)["loom"]
        xyz, faces, element = read_ply(out)
        report = json.loads(run(args.cli, "inspect", out, "--json"))
        share = judge(xyz, faces, element, loom["grid"], pattern)
        extents = []
        for yarn in range(args.size * 2):
            run_axis = 1 if yarn < args.size else 0
            picked = xyz[faces[element == yarn]].reshape(-1, 3)[:, run_axis]
            extents.append((picked.max() - picked.min()) / (args.size * loom["exemplars"][0]["pitch"][0]))
        scores[method] = (share, loom["assignment"], report["intersecting_face_pairs"])
        print("%s: right yarn on top at %.4f of crossings; consistent %.3f, continuous %.3f; %d elements, %d "
              "closed; median yarn %.3f of the extent; %d intersecting face pairs"
              % (method, share, loom["assignment"]["consistent"], loom["assignment"]["continuous"],
                 report["elements"], report["closed_elements"], float(np.median(extents)),
                 report["intersecting_face_pairs"]))
        if method != "structured":
            continue
        if share < 0.995:
            failures.append("right yarn on top at %.4f of crossings (bar 0.995)" % share)
        if report["elements"] != 2 * args.size or report["closed_elements"] != 2 * args.size:
            failures.append("%d elements, %d closed; want %d closed" % (report["elements"], report["closed_elements"],
                                                                         2 * args.size))
        if float(np.median(extents)) < 0.9:
            failures.append("median yarn runs %.3f of the extent (bar 0.9)" % float(np.median(extents)))
        if args.size <= args.no_intersections_up_to and report["intersecting_face_pairs"] != 0:
            failures.append("%d intersecting face pairs" % report["intersecting_face_pairs"])
    if not scores["structured"][1]["consistent"] > scores["naive"][1]["consistent"] + 0.2:
        failures.append("structured consistency %.3f not above naive %.3f" %
                        (scores["structured"][1]["consistent"], scores["naive"][1]["consistent"]))
    for failure in failures:
        print("FAIL: " + failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
