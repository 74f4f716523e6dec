#!/usr/bin/env python3
"""A relief's heights against its sample, measured apart from the synthesizer.

Each vertex of the relief's output is raised off the base it was grown on; its height is read
back as its distance to the nearest point of the base's surface (heights are never negative:
black is the base itself). Divided by the height of white, they should be distributed as the
sample's grey levels are. Prints a JSON summary: the two-sample Kolmogorov-Smirnov distance over
every vertex and over the vertices whose signal (their grey colour) was not lowered to keep the
surface from passing through itself, and the share lowered.

usage: relief_heights.py --base B.off|.ply --relief OUT.ply --sample SAMPLE.pgm --stats S.json
       [--max-ks D]   (exit 1 when the distance over every vertex exceeds D)
"""
import argparse
import json
import sys

import numpy as np


def read_off(path):
    words = open(path).read().split()
    start = 1 if words[0] == "OFF" else 0
    nv, nf = int(words[start]), int(words[start + 1])
    at = start + 3
    vertices = np.array(words[at:at + 3 * nv], dtype=float).reshape(nv, 3)
    at += 3 * nv
    faces = []
    for _ in range(nf):
        k = int(words[at])
        corners = [int(w) for w in words[at + 1:at + 1 + k]]
        faces.extend([corners[0], corners[i], corners[i + 1]] for i in range(1, k - 1))
        at += 1 + k
    return vertices, np.array(faces, dtype=np.int64)


def read_ply(path):
    """Binary little-endian PLY: vertex x y z (double or float) with optional uchar colours."""
    data = open(path, "rb").read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode().splitlines()
    types = {"double": "<f8", "float": "<f4", "uchar": "u1", "int": "<i4", "uint": "<u4"}
    elements, current = [], None
    for line in header:
        words = line.split()
        if words[0] == "element":
            current = (words[1], int(words[2]), [])
            elements.append(current)
        elif words[0] == "property":
            current[2].append(words[1:])
    at = end
    vertices = colours = faces = None
    for name, count, properties in elements:
        if name == "vertex":
            dtype = np.dtype([(p[-1], types[p[0]]) for p in properties])
            table = np.frombuffer(data, dtype=dtype, count=count, offset=at)
            at += dtype.itemsize * count
            vertices = np.stack([table["x"], table["y"], table["z"]], axis=1).astype(float)
            if "red" in table.dtype.names:
                colours = np.stack([table["red"], table["green"], table["blue"]], axis=1).astype(float)
        elif name == "face":
            extra = [types[p[-2 if p[0] == "list" else 0]] for p in properties[1:]]
            record = np.dtype([("n", "u1"), ("v", "<i4", 3)] + [("x%d" % i, t) for i, t in enumerate(extra)])
            table = np.frombuffer(data, dtype=record, count=count, offset=at)
            if np.any(table["n"] != 3):
                sys.exit(path + ": only triangles are read")
            faces = table["v"].astype(np.int64)
            at += record.itemsize * count
    return vertices, faces, colours


def read_pgm(path):
    words = open(path).read().split()
    if words[0] != "P2":
        sys.exit(path + ": expected a plain PGM")
    width, height, top = int(words[1]), int(words[2]), float(words[3])
    return np.array(words[4:4 + width * height], dtype=float) / top


def segment_closest(p, a, b):
    ab = b - a
    t = np.einsum("ijk,ijk->ij", p - a, ab) / np.maximum(np.einsum("ijk,ijk->ij", ab, ab), 1e-300)
    t = np.clip(t, 0.0, 1.0)
    q = a + t[..., None] * ab
    return np.linalg.norm(p - q, axis=2), q


def point_triangle_closest(points, a, b, c):
    """|points| x |triangles| distances and closest points: on the plane where the projection
    falls inside, else on the nearest edge."""
    p = points[:, None, :]
    a, b, c = a[None], b[None], c[None]
    n = np.cross(b - a, c - a)
    length = np.linalg.norm(n, axis=2, keepdims=True)
    unit = n / np.maximum(length, 1e-300)
    height = np.einsum("ijk,ijk->ij", p - a, unit)
    q = p - height[..., None] * unit
    inside = np.ones(height.shape, dtype=bool)
    for u, v in ((a, b), (b, c), (c, a)):
        inside &= np.einsum("ijk,ijk->ij", np.cross(v - u, q - u), unit) >= 0.0
    inside &= length[..., 0] > 0.0
    best, closest = np.abs(height), q
    edge_best = np.full(height.shape, np.inf)
    edge_closest = np.zeros(q.shape)
    for u, v in ((a, b), (b, c), (c, a)):
        d, e = segment_closest(p, u, v)
        better = d < edge_best
        edge_best = np.where(better, d, edge_best)
        edge_closest = np.where(better[..., None], e, edge_closest)
    return np.where(inside, best, edge_best), np.where(inside[..., None], closest, edge_closest)


def surface_closest(points, vertices, faces, reach):
    """Distance from each point to the nearest face, and the nearest point, for points within
    `reach` of the surface: faces are bucketed by their boxes grown by `reach` in a grid of cells
    `reach` wide."""
    corners = vertices[faces]
    lo = corners.min(axis=1) - reach
    hi = corners.max(axis=1) + reach
    origin = lo.min(axis=0)
    buckets = {}
    for f in range(len(faces)):
        i0 = np.floor((lo[f] - origin) / reach).astype(int)
        i1 = np.floor((hi[f] - origin) / reach).astype(int)
        for x in range(i0[0], i1[0] + 1):
            for y in range(i0[1], i1[1] + 1):
                for z in range(i0[2], i1[2] + 1):
                    buckets.setdefault((x, y, z), []).append(f)
    cell = np.floor((points - origin) / reach).astype(int)
    order = np.lexsort((cell[:, 2], cell[:, 1], cell[:, 0]))
    result = np.full(len(points), np.inf)
    feet = np.array(points, dtype=float)
    start = 0
    while start < len(order):
        key = tuple(cell[order[start]])
        end = start
        while end < len(order) and tuple(cell[order[end]]) == key:
            end += 1
        members = order[start:end]
        near = buckets.get(key)
        if near:
            near = np.array(near)
            d, q = point_triangle_closest(points[members], corners[near, 0], corners[near, 1], corners[near, 2])
            best = d.argmin(axis=1)
            result[members] = d[np.arange(len(members)), best]
            feet[members] = q[np.arange(len(members)), best]
        start = end
    return result, feet


def surface_distances(points, vertices, faces, reach):
    return surface_closest(points, vertices, faces, reach)[0]


def ks_distance(x, y):
    x, y = np.sort(x), np.sort(y)
    grid = np.concatenate([x, y])
    return float(np.max(np.abs(np.searchsorted(x, grid, side="right") / len(x) -
                               np.searchsorted(y, grid, side="right") / len(y))))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--base", required=True)
    parser.add_argument("--relief", required=True)
    parser.add_argument("--sample", required=True)
    parser.add_argument("--stats", required=True)
    parser.add_argument("--max-ks", type=float)
    args = parser.parse_args()
    if args.base.endswith(".off"):
        base_vertices, base_faces = read_off(args.base)
    else:
        base_vertices, base_faces, _ = read_ply(args.base)
    vertices, _, colours = read_ply(args.relief)
    white = json.load(open(args.stats))["height"]
    sample = read_pgm(args.sample)
    heights = surface_distances(vertices, base_vertices, base_faces, 1.05 * white) / white
    if not np.all(np.isfinite(heights)):
        sys.exit(args.relief + ": a vertex lies farther from the base than the height of white")
    # The signal each vertex was to be raised by, as its grey colour says (8-bit).
    signal = colours @ np.array([0.299, 0.587, 0.114]) / 255.0
    kept = heights >= signal - 1.0 / 255.0 - 1e-3
    summary = {
        "vertices": int(len(vertices)),
        "lowered_share": float(1.0 - kept.mean()),
        "ks_all": ks_distance(heights, sample),
        "ks_unlowered": ks_distance(heights[kept], sample),
        "ks_signal": ks_distance(signal, sample),
        "mean_height": float(heights.mean()),
        "mean_sample": float(sample.mean()),
    }
    print(json.dumps(summary, indent=2))
    if args.max_ks is not None and summary["ks_all"] > args.max_ks:
        sys.exit(1)


if __name__ == "__main__":
    main()
