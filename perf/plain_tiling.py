#!/usr/bin/python3
"""The floor of repeating-texture synthesis: a plain tiling of a swatch to a face count, written
as binary PLY by numpy alone. Prints the seconds the tiling and the write took (median of runs).

Usage: perf/plain_tiling.py SWATCH.off FACES OUT.ply [--runs N]
"""
import sys
import time

import numpy as np


def read_off(path):
    words = open(path).read().split()
    if words[0] != "OFF":
        sys.exit(f"{path}: not an OFF file")
    nv, nf = int(words[1]), int(words[2])
    at = 4
    v = np.array(words[at:at + 3 * nv], dtype=np.float64).reshape(nv, 3)
    at += 3 * nv
    f = np.array(words[at:at + 4 * nf], dtype=np.int32).reshape(nf, 4)[:, 1:]
    return v, f


def tile(v, f, faces):
    copies = -(-faces // len(f))
    side = int(np.ceil(np.sqrt(copies)))
    extent = v.max(axis=0) - v.min(axis=0)
    ij = np.stack(np.divmod(np.arange(copies), side), axis=1)[:, ::-1]
    offsets = np.zeros((copies, 3))
    offsets[:, :2] = ij * extent[:2]
    verts = (v[None, :, :] + offsets[:, None, :]).reshape(-1, 3).astype(np.float32)
    tris = (f[None, :, :] + (np.arange(copies) * len(v))[:, None, None]).reshape(-1, 3)
    return verts, tris


def write_ply(path, verts, tris):
    header = (f"ply\nformat binary_little_endian 1.0\nelement vertex {len(verts)}\n"
              "property float x\nproperty float y\nproperty float z\n"
              f"element face {len(tris)}\nproperty list uchar int vertex_indices\nend_header\n")
    face = np.empty(len(tris), dtype=[("n", "u1"), ("i", "<i4", 3)])
    face["n"] = 3
    face["i"] = tris
    with open(path, "wb") as out:
        out.write(header.encode())
        out.write(verts.astype("<f4").tobytes())
        out.write(face.tobytes())


def main():
    args = sys.argv[1:]
    runs = 5
    if "--runs" in args:
        at = args.index("--runs")
        runs = int(args[at + 1])
        del args[at:at + 2]
    if len(args) != 3:
        sys.exit(__doc__)
    v, f = read_off(args[0])
    faces = int(args[1])
    seconds = []
    for _ in range(runs):
        start = time.perf_counter()
        verts, tris = tile(v, f, faces)
        write_ply(args[2], verts, tris)
        seconds.append(time.perf_counter() - start)
    print(f"{np.median(seconds):.4f}")


if __name__ == "__main__":
    main()
