#!/usr/bin/env python3
"""A painted surface's neighbourhoods against its sample's, measured apart from the synthesizer.

Around random output vertices, a 7 x 7 neighbourhood is resampled at the sample's pitch in the
field's frame (x along the field `paint --write-field` wrote, y along normal x field): the faces
round the vertex are projected onto its tangent plane, and each grid point takes the colour
interpolated linearly over the face it falls in. Its
distance to the sample is the RMS difference to the best of every 7 x 7 window of the (wrapped)
sample, taken at quarter-pixel shifts too, since the painter reads the sample between pixels. Two references, read the same way:
- leave-one-out: each of some sample windows against the best window at least 3 pixels away;
- a plain planar projection: every vertex coloured by the sample laid over the plane of the
  surface's two longest principal axes, at the same pitch.
With --heights-over, the mesh is a relief: its signal is read back from the geometry as
relief_heights.py reads it, and its neighbourhoods are taken on the base under it.
With --stripes, the sample's stripes run along its x axis: a plane fitted to the luma round each
centre gives the stripes' direction, whose angle to the field is reported.
With --reference, another colouring of the same mesh (field_stripes.py's best stripes for the
field) is read over the same neighbourhoods, and the painted distance is reported over its.

Prints a JSON summary; exits 1 when a ratio or the angle passes its bound.

usage: paint_neighbourhoods.py --painted OUT.ply --field FIELD.txt --sample SAMPLE.ppm|.pgm
       --stats S.json [--heights-over BASE] [--centres N] [--seed S] [--stripes] [--max-loo-ratio R]
       [--max-projection-ratio R] [--max-stripe-angle DEG] [--reference REF.ply --max-reference-ratio R]
"""
import argparse
import json
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from relief_heights import read_off, read_ply, surface_closest  # noqa: E402

HALF = 3  # 7 x 7


def read_netpbm(path):
    """P2/P3 (plain) or P5/P6 (binary, 8-bit) as height x width x 3 floats in [0, 1]."""
    data = open(path, "rb").read()
    words, at = [], 0
    while len(words) < 4:
        while data[at:at + 1].isspace():
            at += 1
        if data[at:at + 1] == b"#":
            at = data.index(b"\n", at)
            continue
        end = at
        while not data[end:end + 1].isspace():
            end += 1
        words.append(data[at:end].decode())
        at = end
    kind, width, height, top = words[0], int(words[1]), int(words[2]), float(words[3])
    channels = 3 if kind in ("P3", "P6") else 1
    count = width * height * channels
    if kind in ("P5", "P6"):
        values = np.frombuffer(data, dtype=np.uint8, count=count, offset=at + 1).astype(float)
    elif kind in ("P2", "P3"):
        values = np.array(data[at:].split()[:count], dtype=float)
    else:
        sys.exit(path + ": expected a PGM or PPM")
    image = values.reshape(height, width, channels) / top
    return np.repeat(image, 3, axis=2) if channels == 1 else image


def vertex_normals(vertices, faces):
    n = np.cross(vertices[faces[:, 1]] - vertices[faces[:, 0]], vertices[faces[:, 2]] - vertices[faces[:, 0]])
    normals = np.zeros_like(vertices)
    for k in range(3):
        np.add.at(normals, faces[:, k], n)
    return normals / np.maximum(np.linalg.norm(normals, axis=1, keepdims=True), 1e-300)


def bilinear(image, x, y):
    """The wrapped sample at pixel coordinates (x, y), pixel centres at integers + 0.5."""
    h, w, _ = image.shape
    x, y = x - 0.5, y - 0.5
    x0, y0 = np.floor(x).astype(int), np.floor(y).astype(int)
    fx, fy = (x - x0)[:, None], (y - y0)[:, None]
    at = lambda i, j: image[j % h, i % w]  # noqa: E731
    return ((1 - fx) * (1 - fy) * at(x0, y0) + fx * (1 - fy) * at(x0 + 1, y0) + (1 - fx) * fy * at(x0, y0 + 1) +
            fx * fy * at(x0 + 1, y0 + 1))


def neighbourhood_weights(vertices, faces, normals, field, centres, pixels_per_unit):
    """For each centre, the 7 x 7 grid points (row = y, column = x) as (vertex indices 49 x 3,
    barycentric weights 49 x 3) of the faces their points lie in once the faces round the centre
    are projected onto its tangent plane; None where a grid point lies in none of them (a border,
    or a part too thin)."""
    reach = (HALF + 1.5) * np.sqrt(2.0) / pixels_per_unit
    grid = np.stack(np.meshgrid(np.arange(-HALF, HALF + 1), np.arange(-HALF, HALF + 1)), axis=-1).reshape(-1, 2)
    vertex_faces = {}
    result = []
    for c in centres:
        d = vertices - vertices[c]
        near = (np.einsum("ij,ij->i", d, d) <= reach * reach) & (normals @ normals[c] > 0.5)
        local = faces[near[faces].all(axis=1)]
        n = normals[c]
        x = field[c] - np.dot(field[c], n) * n
        x /= np.linalg.norm(x)
        y = np.cross(n, x)
        plane = np.stack([d @ x, d @ y], axis=1) * pixels_per_unit
        a, b, e = plane[local[:, 0]], plane[local[:, 1]], plane[local[:, 2]]
        area = (b[:, 0] - a[:, 0]) * (e[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (e[:, 0] - a[:, 0])
        ok = np.abs(area) > 1e-12
        local, a, b, e, area = local[ok], a[ok], b[ok], e[ok], area[ok]
        p = grid[:, None, :]
        w1 = ((p[..., 0] - a[:, 0]) * (e[:, 1] - a[:, 1]) - (p[..., 1] - a[:, 1]) * (e[:, 0] - a[:, 0])) / area
        w2 = ((b[:, 0] - a[:, 0]) * (p[..., 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (p[..., 0] - a[:, 0])) / area
        w0 = 1.0 - w1 - w2
        inside = (w0 >= -1e-9) & (w1 >= -1e-9) & (w2 >= -1e-9)
        if not inside.any(axis=1).all():
            result.append(None)
            continue
        # Of the faces holding a point, the one nearest the tangent plane (folds lie over others).
        depth = np.abs(((vertices[local] - vertices[c]) @ n).mean(axis=1))
        chosen = np.where(inside, depth[None, :], np.inf).argmin(axis=1)
        rows = np.arange(len(grid))
        weights = np.stack([w0[rows, chosen], w1[rows, chosen], w2[rows, chosen]], axis=1)
        result.append((local[chosen], weights))
    return result


def resampled(values, neighbourhoods):
    """values (#V x k) read at each neighbourhood's grid points: N x (49 * k)."""
    return np.stack([np.einsum("gc,gck->gk", w, values[ix]).reshape(-1) for ix, w in neighbourhoods])


def sample_windows(image, steps):
    """Every 7 x 7 window of the wrapped sample, flattened, at `steps` x `steps` sub-pixel shifts
    (bilinear, as the sample is read between pixels): (steps^2 * height * width) x 147, with each
    window's top-left (y, x) in pixels."""
    h, w, _ = image.shape
    rows = (np.arange(h)[:, None] + np.arange(-HALF, HALF + 1)[None, :]) % h
    cols = (np.arange(w)[:, None] + np.arange(-HALF, HALF + 1)[None, :]) % w
    windows, at = [], []
    for sy in np.arange(steps) / steps:
        for sx in np.arange(steps) / steps:
            shifted = ((1 - sy) * (1 - sx) * image + (1 - sy) * sx * np.roll(image, -1, axis=1) +
                       sy * (1 - sx) * np.roll(image, -1, axis=0) + sy * sx * np.roll(image, (-1, -1), axis=(0, 1)))
            windows.append(shifted[rows[:, None, :, None], cols[None, :, None, :]].reshape(h * w, -1))
            yy, xx = np.mgrid[0:h, 0:w]
            at.append(np.stack([yy.reshape(-1) + sy, xx.reshape(-1) + sx], axis=1))
    return np.concatenate(windows).astype(np.float32), np.concatenate(at)


def best_distances(neighbourhoods, windows, exclude=None):
    """RMS distance of each neighbourhood to its best window; exclude(i, j), where given, masks
    the windows neighbourhoods i..j-1 may not use."""
    neighbourhoods = neighbourhoods.astype(np.float32)
    w2 = np.einsum("ij,ij->i", windows, windows)
    out = []
    for i in range(0, len(neighbourhoods), 64):
        block = neighbourhoods[i:i + 64]
        d2 = np.einsum("ij,ij->i", block, block)[:, None] + w2[None, :] - 2.0 * block @ windows.T
        if exclude is not None:
            d2 = np.where(exclude(i, i + len(block)), np.inf, d2)
        out.append(np.sqrt(np.maximum(d2.min(axis=1), 0.0) / windows.shape[1]))
    return np.concatenate(out)


def stripe_angles(luma, vertices, normals, field, centres, pixels_per_unit):
    """Degrees between the stripes (across the luma's fitted gradient) and the field, per centre
    whose gradient is clear; None elsewhere."""
    angles = []
    reach = (HALF + 0.5) / pixels_per_unit
    for c in centres:
        d = vertices - vertices[c]
        near = np.nonzero((np.einsum("ij,ij->i", d, d) <= reach * reach) & (normals @ normals[c] > 0.5))[0]
        n = normals[c]
        x = field[c] - np.dot(field[c], n) * n
        x /= np.linalg.norm(x)
        y = np.cross(n, x)
        a = np.stack([d[near] @ x, d[near] @ y, np.ones(len(near))], axis=1)
        (gx, gy, _), *_ = np.linalg.lstsq(a, luma[near], rcond=None)
        angles.append(np.degrees(np.arctan2(abs(gx), abs(gy))) if np.hypot(gx, gy) > 0 else None)
    return angles


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--painted", required=True)
    parser.add_argument("--field", required=True)
    parser.add_argument("--sample", required=True)
    parser.add_argument("--stats", required=True)
    parser.add_argument("--centres", type=int, default=300)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--heights-over", metavar="BASE",
                        help="the painted mesh is a relief over BASE: its signal is each vertex's height read back as "
                             "its distance to BASE over the stats' height of white, at its nearest point of BASE")
    parser.add_argument("--stripes", action="store_true")
    parser.add_argument("--max-loo-ratio", type=float)
    parser.add_argument("--max-projection-ratio", type=float)
    parser.add_argument("--max-stripe-angle", type=float)
    parser.add_argument("--reference", help="another colouring of the painted mesh's vertices")
    parser.add_argument("--max-reference-ratio", type=float)
    args = parser.parse_args()

    vertices, faces, colours = read_ply(args.painted)
    if args.heights_over:
        base = read_off(args.heights_over) if args.heights_over.endswith(".off") else read_ply(args.heights_over)[:2]
        white = json.load(open(args.stats))["height"]
        heights, vertices = surface_closest(vertices, base[0], base[1], 1.05 * white)
        if not np.all(np.isfinite(heights)):
            sys.exit(args.painted + ": a vertex lies farther from the base than the height of white")
        colours = np.repeat((heights / white)[:, None], 3, axis=1)
    elif colours is None:
        sys.exit(args.painted + ": no vertex colours")
    else:
        colours /= 255.0
    field = np.loadtxt(args.field).reshape(-1, 3)
    if len(field) != len(vertices):
        sys.exit("%s: %d directions for %d vertices" % (args.field, len(field), len(vertices)))
    sample = read_netpbm(args.sample)
    pixels_per_unit = json.load(open(args.stats))["pixels_per_unit"]
    normals = vertex_normals(vertices, faces)
    rng = np.random.default_rng(args.seed)

    centres = rng.choice(len(vertices), size=min(args.centres, len(vertices)), replace=False)
    found = neighbourhood_weights(vertices, faces, normals, field, centres, pixels_per_unit)
    kept = [k for k, nb in enumerate(found) if nb is not None]
    if len(kept) < len(centres) // 2:
        sys.exit("fewer than half the centres have whole neighbourhoods")
    neighbourhoods = [found[k] for k in kept]
    windows, window_at = sample_windows(sample, 4)
    painted = best_distances(resampled(colours, neighbourhoods), windows)

    # The planar projection: the sample laid over the plane of the two longest principal axes.
    centred = vertices - vertices.mean(axis=0)
    axes = np.linalg.svd(centred, full_matrices=False)[2]
    u, v = centred @ axes[0] * pixels_per_unit, centred @ axes[1] * pixels_per_unit
    projected_colours = bilinear(sample, u, v)
    projected = best_distances(resampled(projected_colours, neighbourhoods), windows)

    # Leave-one-out: windows at whole pixels against every window at least 3 pixels away
    # (wrapping round).
    h, w, _ = sample.shape
    picks = rng.choice(h * w, size=min(400, h * w), replace=False)  # the unshifted windows come first

    def near(i, j):
        gap = np.abs(window_at[picks[i:j]][:, None, :] - window_at[None, :, :])
        return np.minimum(gap, np.array([h, w]) - gap).max(axis=2) < 3

    loo = best_distances(windows[picks], windows, exclude=near)

    summary = {
        "centres": len(kept),
        "painted": float(painted.mean()),
        "leave_one_out": float(loo.mean()),
        "projection": float(projected.mean()),
    }
    if args.reference:
        reference_vertices, _, reference_colours = read_ply(args.reference)
        if reference_colours is None or len(reference_vertices) != len(vertices):
            sys.exit(args.reference + ": expected colours over the painted mesh's %d vertices" % len(vertices))
        reference = best_distances(resampled(reference_colours / 255.0, neighbourhoods), windows)
        summary["reference"] = float(reference.mean())
    summary["loo_ratio"] = summary["painted"] / max(summary["leave_one_out"], 1e-12)
    summary["projection_ratio"] = summary["painted"] / max(summary["projection"], 1e-12)
    failed = []
    if args.reference:
        summary["reference_ratio"] = summary["painted"] / max(summary["reference"], 1e-12)
        if args.max_reference_ratio is not None and summary["reference_ratio"] > args.max_reference_ratio:
            failed.append("reference_ratio")
    if args.max_loo_ratio is not None and summary["loo_ratio"] > args.max_loo_ratio:
        failed.append("loo_ratio")
    if args.max_projection_ratio is not None and summary["projection_ratio"] > args.max_projection_ratio:
        failed.append("projection_ratio")
    if args.stripes:
        luma = colours @ np.array([0.2126, 0.7152, 0.0722])
        angles = [a for a in stripe_angles(luma, vertices, normals, field, centres[kept], pixels_per_unit)
                  if a is not None]
        summary["stripe_angle_median"] = float(np.median(angles))
        summary["stripe_angle_p90"] = float(np.percentile(angles, 90))
        if args.max_stripe_angle is not None and summary["stripe_angle_median"] > args.max_stripe_angle:
            failed.append("stripe_angle_median")
    summary["failed"] = failed
    print(json.dumps(summary, indent=1))
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
