#!/usr/bin/env python3
"""The best sinusoidal stripes a field allows over a mesh, as a reference the painter's stripes are
held to, written apart from it (numpy, scipy).

Stripes along a field X with a period P must have a phase whose gradient is 2 pi / P along Y = N x X.
Where the field curls, no phase has that gradient everywhere: the stripes must bend, change their
spacing, or end. Knoppel et al. 2015 ("Stripe patterns on surfaces") find the least-squares
compromise as the smallest eigenvector of a connection Laplacian; this is its vertex form: complex
psi per vertex, each edge asking psi_j = exp(i w_ij) psi_i with w_ij = 2 pi / P <Y, e_ij> (or its
conjugate where the line field flips along the edge), cotangent-weighted, against the lumped mass.
Each vertex takes the striped sample's colours at the phase arg psi (paint_samples.py: stripes of
0.5 + 0.5 sin, without its noise).

usage: field_stripes.py PAINTED.ply FIELD.txt STATS.json OUT.ply [--period PIXELS]
PAINTED.ply gives the mesh (the painter's output, so the two are read over the same vertices),
FIELD.txt the field paint --write-field wrote and STATS.json its pixels per unit.
"""
import argparse
import json
import os
import sys

import numpy as np

try:
    import scipy.sparse as sparse
    import scipy.sparse.linalg as sparse_linalg
except ImportError:
    sys.exit("field_stripes.py: needs scipy (Debian: apt-get install python3-scipy)")

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from paint_neighbourhoods import vertex_normals  # noqa: E402
from paint_samples import STRIPE_DARK, STRIPE_LIGHT  # noqa: E402
from relief_heights import read_ply  # noqa: E402


def edges_with_cotangent_weights(vertices, faces):
    """Unique edges (i < j) with their cotangent weights, clamped positive."""
    n = len(vertices)
    first, second, weight = [], [], []
    for k in range(3):
        a, b, c = faces[:, k], faces[:, (k + 1) % 3], faces[:, (k + 2) % 3]
        u, v = vertices[a] - vertices[c], vertices[b] - vertices[c]
        cross = np.maximum(np.linalg.norm(np.cross(u, v), axis=1), 1e-300)
        first.append(np.minimum(a, b))
        second.append(np.maximum(a, b))
        weight.append(0.5 * np.einsum("ij,ij->i", u, v) / cross)
    key = np.concatenate(first) * n + np.concatenate(second)
    unique, inverse = np.unique(key, return_inverse=True)
    return unique // n, unique % n, np.maximum(np.bincount(inverse, weights=np.concatenate(weight)), 1e-8)


def stripe_phase(vertices, faces, field, frequency):
    """Phase per vertex of the least-squares stripes across `field` at `frequency` radians per
    unit, and the amplitude of psi (near zero at the pattern's singularities)."""
    n = len(vertices)
    normals = vertex_normals(vertices, faces)
    x = field - np.einsum("ij,ij->i", field, normals)[:, None] * normals
    x /= np.linalg.norm(x, axis=1, keepdims=True)
    y = np.cross(normals, x)
    i, j, w = edges_with_cotangent_weights(vertices, faces)
    same = np.einsum("ij,ij->i", y[i], y[j]) >= 0
    y_edge = 0.5 * (y[i] + np.where(same, 1.0, -1.0)[:, None] * y[j])
    angle = frequency * np.einsum("ij,ij->i", y_edge, vertices[j] - vertices[i])
    c, s = np.cos(angle), np.sin(angle)
    # The 2 x 2 real map from (re, im) of psi_i to its prediction at j: a rotation, or a
    # reflection (rotation after conjugation) where the line field flips.
    transport = np.empty((len(i), 2, 2))
    transport[:, 0, 0], transport[:, 0, 1] = c, -s
    transport[:, 1, 0], transport[:, 1, 1] = np.where(same, s, -s), np.where(same, c, -c)
    rows, cols, values = [], [], []
    for p in range(2):
        rows += [i + p * n, j + p * n]
        cols += [i + p * n, j + p * n]
        values += [w, w]
        for q in range(2):
            rows += [j + p * n, i + q * n]
            cols += [i + q * n, j + p * n]
            values += [-w * transport[:, p, q]] * 2
    energy = sparse.csc_matrix((np.concatenate(values), (np.concatenate(rows), np.concatenate(cols))),
                               shape=(2 * n, 2 * n))
    area = np.linalg.norm(np.cross(vertices[faces[:, 1]] - vertices[faces[:, 0]],
                                   vertices[faces[:, 2]] - vertices[faces[:, 0]]), axis=1) / 6.0
    mass = np.zeros(n)
    for k in range(3):
        np.add.at(mass, faces[:, k], area)
    mass = np.concatenate([mass, mass])
    # Inverse iteration towards the smallest eigenvector; a small shift keeps the factor regular
    # where the field is integrable and the energy's minimum is zero.
    shift = 1e-6 * energy.diagonal().mean() / mass.mean()
    factor = sparse_linalg.splu((energy + sparse.diags(shift * mass)).tocsc(), permc_spec="COLAMD")
    psi = np.random.default_rng(0).standard_normal(2 * n)
    for _ in range(30):
        psi = factor.solve(mass * psi)
        psi /= np.sqrt(psi @ (mass * psi))
    return np.arctan2(psi[n:], psi[:n]), np.hypot(psi[:n], psi[n:])


def write_coloured_ply(path, vertices, faces, rgb):
    table = np.zeros(len(vertices), dtype=[("x", "<f8"), ("y", "<f8"), ("z", "<f8"),
                                           ("red", "u1"), ("green", "u1"), ("blue", "u1")])
    for k, name in enumerate("xyz"):
        table[name] = vertices[:, k]
    for k, name in enumerate(("red", "green", "blue")):
        table[name] = np.clip(np.rint(rgb[:, k] * 255), 0, 255)
    records = np.zeros(len(faces), dtype=[("n", "u1"), ("v", "<i4", 3)])
    records["n"], records["v"] = 3, faces
    header = ("ply\nformat binary_little_endian 1.0\nelement vertex %d\nproperty double x\nproperty double y\n"
              "property double z\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n"
              "element face %d\nproperty list uchar int vertex_indices\nend_header\n" % (len(vertices), len(faces)))
    with open(path, "wb") as f:
        f.write(header.encode())
        f.write(table.tobytes())
        f.write(records.tobytes())


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("painted")
    parser.add_argument("field")
    parser.add_argument("stats")
    parser.add_argument("output")
    parser.add_argument("--period", type=float, default=8.0, help="the stripes' period in sample pixels")
    args = parser.parse_args()
    vertices, faces, _ = read_ply(args.painted)
    field = np.loadtxt(args.field).reshape(-1, 3)
    if len(field) != len(vertices):
        sys.exit("%s: %d directions for %d vertices" % (args.field, len(field), len(vertices)))
    pixels_per_unit = json.load(open(args.stats))["pixels_per_unit"]
    phase, amplitude = stripe_phase(vertices, faces, field, 2.0 * np.pi * pixels_per_unit / args.period)
    t = (0.5 + 0.5 * np.sin(phase))[:, None]
    write_coloured_ply(args.output, vertices, faces, t * STRIPE_DARK + (1 - t) * STRIPE_LIGHT)
    print(json.dumps({"vertices": len(vertices), "amplitude_median": float(np.median(amplitude))}))


if __name__ == "__main__":
    main()
