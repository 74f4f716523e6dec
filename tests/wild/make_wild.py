#!/usr/bin/env python3
"""Meshes as other tools export them, for meshquilt's tests: each case a clean swatch or base
spoilt the way exporters, scanners and CAD tools spoil them, with random parameters and a seed,
written as OBJ, PLY, STL or OFF by writers of this file's own.

Usage:
  make_wild.py --list
  make_wild.py --seeds FIRST-LAST -o DIR     (every case; DIR/manifest.json describes them)
  make_wild.py --case ROLE/NAME --seed N -o DIR
  make_wild.py --issue-wires -o DIR           (the issue's two exported wire swatches)

Each manifest entry names the wild file, the clean file it was spoilt from (the same clean file
for every case of a role and seed), the role (swatch or base) and the documented outcome:
  repaired  synth quilts it as it does the clean file, reporting `repair` (a key of the stats
            JSON's `repairs`) as made at least once;
  accepted  synth quilts it as it does the clean file, no repair made;
  quilted   synth quilts it (it differs from the clean file on purpose: more parts, a hole);
  refused   synth exits with `exit` and a message containing `message`.
The table of cases is docs/swatches.md (swatches) and docs/cli.md (bases).

Shares no code with meshquilt's host/ library; the clean swatches are swept by
tests/foreign/make_swatches.py. Needs numpy (Debian: python3-numpy).
"""

import argparse
import json
import math
import struct
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "foreign"))
import make_swatches as foreign  # noqa: E402

FORMATS = ["obj", "ply", "stl", "off"]
# STL stores each face's corners apart; every reader joins equal ones, so a soup or an unused
# vertex cannot be told from the clean file there and those cases leave STL out.


class Mesh:
    def __init__(self, vertices, faces, parts):
        self.vertices = np.asarray(vertices, dtype=float)
        self.faces = np.asarray(faces, dtype=np.int64)
        self.parts = np.asarray(parts, dtype=np.int64)  # per face: which element or piece

    def copy(self):
        return Mesh(self.vertices.copy(), self.faces.copy(), self.parts.copy())


# ---------------------------------------------------------------------------------------------
# Clean inputs


def clean_swatch(seed):
    """A small crimped wire mesh (3-4 wires each way, 6-8 sides), drawn until its wires clear."""
    rng = np.random.default_rng([seed, 62])
    for _ in range(200):
        pitch = float(rng.uniform(0.8, 1.3))
        radius = pitch * float(rng.uniform(0.05, 0.09))
        p = dict(count=int(rng.integers(3, 5)), pitch=pitch, radius=radius, sharpness=0.0,
                 crimp=float(rng.uniform(max(1.3 * radius, radius + 0.03 * pitch), 0.2 * pitch)),
                 sides=int(rng.integers(6, 9)), extra=float(rng.uniform(0.1, 0.5)),
                 cap=str(rng.choice(["flat", "fan"])), uneven=False, rings_per_pitch=int(rng.integers(4, 7)))
        elements = foreign.woven(p, rng)
        if foreign.clear_of_each_other(elements, foreign.CLEARANCE * radius):
            break
    return joined(elements), p


def joined(elements):
    """One Mesh of swept elements, each face's part its element's index."""
    vertices, faces, parts, offset = [], [], [], 0
    for k, e in enumerate(elements):
        vertices.append(e.vertices)
        faces.append(e.faces + offset)
        parts.append(np.full(len(e.faces), k))
        offset += len(e.vertices)
    return Mesh(np.concatenate(vertices), np.concatenate(faces), np.concatenate(parts))


def icosphere(level):
    t = (1.0 + math.sqrt(5.0)) / 2.0
    v = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t), (0, -1, -t), (0, 1, -t),
         (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    f = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2), (10, 7, 6),
         (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10),
         (8, 6, 7), (9, 8, 1)]
    vertices = [np.array(p, float) / np.linalg.norm(p) for p in v]
    faces = f
    for _ in range(level):
        middle = {}

        def mid(a, b):
            key = (min(a, b), max(a, b))
            if key not in middle:
                p = vertices[a] + vertices[b]
                vertices.append(p / np.linalg.norm(p))
                middle[key] = len(vertices) - 1
            return middle[key]

        faces = [g for (a, b, c) in faces
                 for g in ((a, mid(a, b), mid(c, a)), (b, mid(b, c), mid(a, b)), (c, mid(c, a), mid(b, c)),
                           (mid(a, b), mid(b, c), mid(c, a)))]
    return np.array(vertices), np.array(faces)


def clean_base(seed):
    """An ellipsoid (an icosphere of 1,280 faces, stretched by 0.75-1.25 along each axis)."""
    rng = np.random.default_rng([seed, 63])
    vertices, faces = icosphere(3)
    axes = rng.uniform(0.75, 1.25, 3)
    return Mesh(vertices * axes, faces, np.zeros(len(faces), dtype=np.int64)), dict(axes=axes.round(3).tolist())


# ---------------------------------------------------------------------------------------------
# Spoilers: each returns the spoilt mesh and a note of what it did.


def shared_edges(mesh):
    """(face, local edge) pairs of interior edges, each edge once."""
    seen, out = {}, []
    for f, tri in enumerate(mesh.faces):
        for k in range(3):
            a, b = int(tri[k]), int(tri[(k + 1) % 3])
            key = (min(a, b), max(a, b))
            if key in seen:
                out.append(seen.pop(key))
            else:
                seen[key] = (f, k)
    return out


def winding_mixed(mesh, rng):
    share = float(rng.uniform(0.1, 0.9))
    flip = rng.random(len(mesh.faces)) < share
    mesh.faces[flip] = mesh.faces[flip][:, ::-1]
    return mesh, "%d faces of %d flipped at random" % (flip.sum(), len(flip))


def inward(mesh, rng):
    mesh.faces = mesh.faces[:, ::-1].copy()
    return mesh, "every face flipped"


def tubes_in_caps_out(mesh, rng, sides):
    """A wire's tube faces (the ring strips, first in each element) flipped, its caps kept."""
    flipped = 0
    for part in np.unique(mesh.parts):
        faces = np.nonzero(mesh.parts == part)[0]
        used = np.unique(mesh.faces[faces])
        rings = len(used) // sides
        tube = faces[:2 * sides * (rings - 1)]
        mesh.faces[tube] = mesh.faces[tube][:, ::-1]
        flipped += len(tube)
    return mesh, "%d tube faces flipped, caps kept" % flipped


def soup(mesh, rng):
    vertices = mesh.vertices[mesh.faces.reshape(-1)]
    order = rng.permutation(len(mesh.faces))
    faces = np.arange(3 * len(mesh.faces)).reshape(-1, 3)[order]
    vertices = vertices.reshape(-1, 3, 3)[order].reshape(-1, 3)
    return Mesh(vertices, np.arange(len(vertices)).reshape(-1, 3), mesh.parts[order]), "every face its own vertices"


def duplicate_faces(mesh, rng):
    count = max(1, int(len(mesh.faces) * rng.uniform(0.01, 0.05)))
    pick = rng.choice(len(mesh.faces), count, replace=False)
    extra = mesh.faces[pick].copy()
    reverse = rng.random(count) < 0.5
    extra[reverse] = extra[reverse][:, ::-1]
    mesh.faces = np.concatenate([mesh.faces, extra])
    mesh.parts = np.concatenate([mesh.parts, mesh.parts[pick]])
    return mesh, "%d faces repeated (%d reversed)" % (count, reverse.sum())


def t_junctions(mesh, rng, sliver=False):
    """On random interior edges a vertex added at a random point, used by one side only (the other
    side's face keeps the long edge: a T-junction); with `sliver`, a zero-area face fills it."""
    edges = shared_edges(mesh)
    count = max(1, min(len(edges) // 10, int(rng.integers(1, 12))))
    done, touched, vertices, faces, parts = 0, set(), list(mesh.vertices), list(map(list, mesh.faces)), list(mesh.parts)
    for i in rng.permutation(len(edges)):
        f, k = edges[i]
        tri = faces[f]
        a, b, c = tri[k], tri[(k + 1) % 3], tri[(k + 2) % 3]
        if f in touched:
            continue
        touched.add(f)
        s = float(rng.uniform(0.25, 0.75))
        m = len(vertices)
        vertices.append(vertices[a] * (1 - s) + vertices[b] * s)
        faces[f] = [a, m, c]
        faces.append([m, b, c])
        parts.append(parts[f])
        if sliver:
            faces.append([b, m, a])  # runs b -> a as the face across does not: zero area, closes the T
            parts.append(parts[f])
        done += 1
        if done == count:
            break
    return Mesh(vertices, faces, parts), "%d T-junctions%s" % (done, " filled by zero-area faces" if sliver else "")


def unused_far_vertices(mesh, rng):
    size = np.ptp(mesh.vertices, axis=0).max()
    count = int(rng.integers(1, 4))
    far = mesh.vertices.mean(0) + rng.normal(0.0, 1.0, (count, 3)) * size * float(rng.uniform(50, 5000))
    mesh.vertices = np.concatenate([mesh.vertices, far])
    return mesh, "%d vertices far away, used by no face" % count


def y_up(mesh, rng):
    # (x, y, z) -> (x, z, -y): a proper rotation taking z-up to y-up.
    mesh.vertices = np.column_stack([mesh.vertices[:, 0], mesh.vertices[:, 2], -mesh.vertices[:, 1]])
    return mesh, "turned to y-up"


def scaled(mesh, rng, low, high):
    exponent = float(rng.uniform(low, high))
    factor = 10.0 ** exponent
    offset = rng.normal(0.0, 1.0, 3) * factor * float(rng.uniform(0.0, 10.0))
    mesh.vertices = mesh.vertices * factor + offset
    return mesh, "scaled by %.3g, moved by %.3g" % (factor, np.linalg.norm(offset))


def millimetres(mesh, rng):
    mesh.vertices = mesh.vertices * 1000.0
    return mesh, "metres written as millimetres"


def far_offset(mesh, rng):
    offset = rng.uniform(-1.0, 1.0, 3) * 1e4
    mesh.vertices = mesh.vertices + offset
    return mesh, "moved %.3g away from the origin" % np.linalg.norm(offset)


def non_manifold_edge(mesh, rng):
    edges = shared_edges(mesh)
    f, k = edges[int(rng.integers(len(edges)))]
    a, b = mesh.faces[f][k], mesh.faces[f][(k + 1) % 3]
    centre = mesh.vertices[mesh.faces[f]].mean(0)
    normal = np.cross(mesh.vertices[b] - mesh.vertices[a], centre - mesh.vertices[a])
    tip = 0.5 * (mesh.vertices[a] + mesh.vertices[b]) + normal / max(np.linalg.norm(normal), 1e-12) * \
        np.linalg.norm(mesh.vertices[b] - mesh.vertices[a])
    mesh.vertices = np.concatenate([mesh.vertices, [tip]])
    mesh.faces = np.concatenate([mesh.faces, [[a, b, len(mesh.vertices) - 1]]])
    mesh.parts = np.concatenate([mesh.parts, [mesh.parts[f]]])
    return mesh, "a fin face on the edge of face %d" % f


def stray_face(mesh, rng):
    size = np.ptp(mesh.vertices, axis=0).max()
    corner = mesh.vertices.max(0) + size * float(rng.uniform(1e3, 1e5))
    tri = corner + rng.normal(0.0, 1.0, (3, 3)) * 0.01 * size
    n = len(mesh.vertices)
    mesh.vertices = np.concatenate([mesh.vertices, tri])
    mesh.faces = np.concatenate([mesh.faces, [[n, n + 1, n + 2]]])
    mesh.parts = np.concatenate([mesh.parts, [mesh.parts.max() + 1]])
    return mesh, "one small face far away"


def nan_vertex(mesh, rng):
    v = int(rng.integers(len(mesh.vertices)))
    mesh.vertices[v, int(rng.integers(3))] = float("nan")
    return mesh, "vertex %d has a NaN coordinate" % v


def bad_index(mesh, rng):
    f = int(rng.integers(len(mesh.faces)))
    mesh.faces[f, int(rng.integers(3))] = len(mesh.vertices) + int(rng.integers(0, 1000))
    return mesh, "face %d names a vertex past the last" % f


def no_faces(mesh, rng):
    mesh.faces = mesh.faces[:0]
    mesh.parts = mesh.parts[:0]
    return mesh, "vertices and no faces"


def loose_parts(mesh, rng):
    size = np.ptp(mesh.vertices, axis=0)
    second = mesh.vertices * float(rng.uniform(0.5, 0.9)) + np.array([size[0] * float(rng.uniform(1.3, 2.0)), 0, 0])
    n = len(mesh.vertices)
    mesh.vertices = np.concatenate([mesh.vertices, second])
    mesh.faces = np.concatenate([mesh.faces, mesh.faces + n])
    mesh.parts = np.concatenate([mesh.parts, mesh.parts + 1])
    return mesh, "a second, smaller piece beside it"


def open_hole(mesh, rng):
    direction = rng.normal(0.0, 1.0, 3)
    direction /= np.linalg.norm(direction)
    centres = mesh.vertices[mesh.faces].mean(1)
    centre = mesh.vertices.mean(0)
    heights = (centres - centre) @ direction
    cut = heights > np.quantile(heights, 1.0 - float(rng.uniform(0.03, 0.12)))
    mesh.faces, mesh.parts = mesh.faces[~cut], mesh.parts[~cut]
    return mesh, "%d faces cut out: a hole" % cut.sum()


def moebius(mesh, rng):
    n = 2 * int(rng.integers(8, 20))
    width = float(rng.uniform(0.2, 0.4))
    vertices, faces = [], []
    for i in range(n):
        u = 2.0 * math.pi * i / n
        for s in (-width, width):
            r = 1.0 + s * math.cos(u / 2.0)
            vertices.append((r * math.cos(u), r * math.sin(u), s * math.sin(u / 2.0)))
    for i in range(n):
        c, d = 2 * ((i + 1) % n), 2 * ((i + 1) % n) + 1
        if i == n - 1:
            c, d = d, c
        faces += [(2 * i, c, d), (2 * i, d, 2 * i + 1)]
    return Mesh(vertices, faces, np.zeros(len(faces))), "a Moebius strip of %d faces" % len(faces)


TEXT = ["obj", "ply", "off"]  # formats that can hold shared or unused vertices
# case: (spoiler, outcome, repair key or refusal message, exit code, formats allowed), for either role
BOTH = {
    "winding-mixed": (winding_mixed, "repaired", "rewound_faces", 0, FORMATS),
    "inward": (inward, "repaired", "rewound_faces", 0, FORMATS),
    "soup": (soup, "repaired", "welded_vertices", 0, TEXT),
    "duplicate-faces": (duplicate_faces, "repaired", "duplicate_faces", 0, FORMATS),
    "t-junctions": (t_junctions, "repaired", "t_junctions", 0, TEXT),
    "zero-area-faces": (lambda m, r: t_junctions(m, r, True), "repaired", "zero_area_faces", 0, TEXT),
    "unused-far-vertices": (unused_far_vertices, "repaired", "unused_vertices", 0, TEXT),
    "y-up": (y_up, "accepted", None, 0, FORMATS),
    "tiny": (lambda m, r: scaled(m, r, -5.0, -3.0), "accepted", None, 0, TEXT),
    "non-manifold-edge": (non_manifold_edge, "refused", "non-manifold edge", 5, FORMATS),
    "nan": (nan_vertex, "refused", "", 5, TEXT),
    "no-faces": (no_faces, "refused", "", 5, TEXT),
}
SWATCH_ONLY = {
    "tubes-in-caps-out": (None, "repaired", "rewound_faces", 0, FORMATS),
    "huge": (lambda m, r: scaled(m, r, 3.0, 5.0), "accepted", None, 0, TEXT),
    "stray-face": (stray_face, "refused", "lies far from the rest", 5, FORMATS),
    "bad-index": (bad_index, "refused", "", 5, TEXT),
}
BASE_ONLY = {
    "millimetres": (millimetres, "accepted", None, 0, FORMATS),
    "far-offset": (far_offset, "accepted", None, 0, TEXT),
    "loose-parts": (loose_parts, "quilted", None, 0, FORMATS),
    "open-hole": (open_hole, "quilted", None, 0, FORMATS),
    "stray-face": (stray_face, "refused", "lies", 5, FORMATS),
    "moebius": (moebius, "refused", "non-orientable", 5, FORMATS),
}
# (role, case): its entry
CASES = {**{("swatch", c): e for c, e in {**BOTH, **SWATCH_ONLY}.items()},
         **{("base", c): e for c, e in {**BOTH, **BASE_ONLY}.items()}}


# ---------------------------------------------------------------------------------------------
# Writers, as other tools write: OBJ with normals and groups, PLY ASCII or binary with extra
# properties, STL binary or ASCII (a soup, with facet normals), OFF.


def write_obj(path, mesh, rng):
    with open(path, "w") as out:
        out.write("# exported by a modelling tool\nmtllib wild.mtl\n")
        for p in mesh.vertices:
            out.write("v %.9g %.9g %.9g\n" % tuple(p))
        normals = rng.random() < 0.5
        if normals:
            out.write("vn 0 0 1\n")
        for part in np.unique(mesh.parts) if len(mesh.parts) else []:
            out.write("o part_%d\nusemtl wire\ns off\n" % part)
            for tri in mesh.faces[mesh.parts == part] + 1:
                out.write("f %d//1 %d//1 %d//1\n" % tuple(tri) if normals else "f %d %d %d\n" % tuple(tri))


def write_ply(path, mesh, rng):
    binary = rng.random() < 0.5
    double = rng.random() < 0.3
    normals = rng.random() < 0.5
    vertex_type = "double" if double else "float"
    header = ["ply", "format %s 1.0" % ("binary_little_endian" if binary else "ascii"), "comment wild export",
              "element vertex %d" % len(mesh.vertices)]
    header += ["property %s %s" % (vertex_type, a) for a in "xyz"]
    if normals:
        header += ["property float nx", "property float ny", "property float nz"]
    header += ["element face %d" % len(mesh.faces), "property list uchar int vertex_indices", "end_header"]
    columns = [mesh.vertices] + ([np.zeros((len(mesh.vertices), 3))] if normals else [])
    with open(path, "wb") as out:
        out.write(("\n".join(header) + "\n").encode("ascii"))
        if binary:
            for row in np.column_stack(columns) if len(mesh.vertices) else []:
                xyz = struct.pack("<3d" if double else "<3f", *row[:3])
                out.write(xyz + (struct.pack("<3f", *row[3:]) if normals else b""))
            for tri in mesh.faces:
                out.write(struct.pack("<B3i", 3, *tri))
        else:
            for row in np.column_stack(columns) if len(mesh.vertices) else []:
                out.write((" ".join("%.9g" % x for x in row) + "\n").encode("ascii"))
            for tri in mesh.faces:
                out.write(("3 %d %d %d\n" % tuple(tri)).encode("ascii"))


def write_stl(path, mesh, rng):
    corners = mesh.vertices[mesh.faces]
    normals = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
    length = np.linalg.norm(normals, axis=1, keepdims=True)
    normals = np.where(length > 0, normals / np.where(length > 0, length, 1), 0.0)
    if rng.random() < 0.5:
        with open(path, "wb") as out:
            out.write(b"binary STL from a CAD tool".ljust(80, b" "))
            out.write(struct.pack("<I", len(corners)))
            for n, c in zip(normals, corners):
                out.write(struct.pack("<12fH", *n, *c.reshape(-1), 0))
    else:
        with open(path, "w") as out:
            out.write("solid wild\n")
            for n, c in zip(normals, corners):
                out.write("  facet normal %.7g %.7g %.7g\n    outer loop\n" % tuple(n))
                for p in c:
                    out.write("      vertex %.9g %.9g %.9g\n" % tuple(p))
                out.write("    endloop\n  endfacet\n")
            out.write("endsolid wild\n")


def write_off(path, mesh, rng):
    with open(path, "w") as out:
        out.write("OFF\n# wild export\n%d %d 0\n" % (len(mesh.vertices), len(mesh.faces)))
        for p in mesh.vertices:
            out.write("%.9g %.9g %.9g\n" % tuple(p))
        for tri in mesh.faces:
            out.write("3 %d %d %d\n" % tuple(tri))


WRITERS = {"obj": write_obj, "ply": write_ply, "stl": write_stl, "off": write_off}


def write(path, mesh, rng):
    WRITERS[path.suffix[1:]](path, mesh, rng)


# ---------------------------------------------------------------------------------------------
# The two exported wire swatches of the issue on files as users export them: tubes wound inward,
# fan caps outward.


def issue_wire(which):
    """Wire 1: 9 x 9 wires of radius 0.07 at pitch 1, crimp 0.12, 8 sides, 9.6 long over a 9-pitch
    lattice. Wire 2: 7 x 7 at pitch 1.2, radius 0.05, crimp 0.09, 12 sides, 0.2 past the lattice at
    each end, each wire moved by a tiny random offset. Returns (elements, sides)."""
    n, pitch, radius, crimp, sides, past = (9, 1.0, 0.07, 0.12, 8, 0.3) if which == 1 else (7, 1.2, 0.05, 0.09, 12, 0.2)
    rng = np.random.default_rng([which, 62])
    length = n * pitch + 2 * past
    middle = 0.5 * (n - 1) * pitch
    rings = int(round(12.5 * length / pitch))
    elements = []
    for along_x in (True, False):
        for j in range(n):
            jitter = rng.normal(0.0, 1e-4 * pitch, 3) if which == 2 else np.zeros(3)
            phase = math.pi * j

            def profile(xy, phase=phase, along_x=along_x):
                u = xy[:, 0] if along_x else xy[:, 1]
                return (crimp if along_x else -crimp) * np.cos(math.pi * u / pitch + phase)

            start = (middle - 0.5 * length, j * pitch) if along_x else (j * pitch, middle - 0.5 * length)
            end = (middle + 0.5 * length, j * pitch) if along_x else (j * pitch, middle + 0.5 * length)
            spine = foreign._yarn_spine(start, end, rings, profile, rng, False) + jitter
            elements.append(foreign.sweep_yarn(spine, radius, sides, "fan"))
    return elements, sides


def write_issue_wires(out_dir):
    """wire_N.ply as exported (tubes in, caps out) and wire_N_consistent.ply, for N = 1, 2."""
    names = []
    for which in (1, 2):
        elements, sides = issue_wire(which)
        clean = joined(elements)
        wild, note = tubes_in_caps_out(clean.copy(), None, sides)
        rng = np.random.default_rng(which)
        write_off(out_dir / ("wire_%d_consistent.off" % which), clean, rng)
        write_obj(out_dir / ("wire_%d.obj" % which), wild, rng)
        names.append(("wire_%d.obj" % which, "wire_%d_consistent.off" % which, note))
    return names


# ---------------------------------------------------------------------------------------------


def make(role, case, seed, out_dir, index=0):
    spoiler, outcome, detail, exit_code, formats = CASES[(role, case)]
    clean, params = clean_swatch(seed) if role == "swatch" else clean_base(seed)
    clean_path = out_dir / ("clean_%s_%d.ply" % (role, seed))
    if not clean_path.exists():
        write_ply(clean_path, clean, np.random.default_rng([seed, 1]))
    rng = np.random.default_rng([seed, sum(map(ord, role + case))])
    fmt = formats[(seed + index) % len(formats)]
    if spoiler is None:
        wild, note = tubes_in_caps_out(clean.copy(), rng, params["sides"])
    else:
        wild, note = spoiler(clean.copy(), rng)
    path = out_dir / ("%s_%s_%d.%s" % (role, case, seed, fmt))
    write(path, wild, rng)
    entry = dict(role=role, case=case, seed=seed, file=path.name, clean=clean_path.name, outcome=outcome,
                 note=note, format=fmt)
    if outcome == "repaired":
        entry["repair"] = detail
    if outcome == "refused":
        entry.update(exit=exit_code, message=detail)
    return entry


def main(argv):
    parser = argparse.ArgumentParser(description="Writes meshes as other tools export them.")
    parser.add_argument("--list", action="store_true")
    parser.add_argument("--seeds", default="1-1", help="FIRST-LAST")
    parser.add_argument("--case", help="ROLE/CASE, e.g. swatch/soup")
    parser.add_argument("--seed", type=int)
    parser.add_argument("--issue-wires", action="store_true", help="the issue's two exported wire swatches instead")
    parser.add_argument("-o", "--output", help="folder")
    args = parser.parse_args(argv)
    if args.list:
        for (role, case), (_, outcome, detail, code, formats) in CASES.items():
            print("%-6s %-20s %-9s %s" % (role, case, outcome, detail or ""))
        return 0
    if not args.output:
        parser.error("-o is required")
    out_dir = Path(args.output)
    out_dir.mkdir(parents=True, exist_ok=True)
    if args.issue_wires:
        for wild, clean, note in write_issue_wires(out_dir):
            print("wrote %s (%s) and %s" % (wild, note, clean))
        return 0
    if args.case:
        role, case = args.case.split("/")
        seeds = [args.seed or 1]
        keys = [(role, case)]
    else:
        first, last = (int(x) for x in args.seeds.split("-"))
        seeds = range(first, last + 1)
        keys = list(CASES)
    entries = [make(role, case, seed, out_dir, index) for seed in seeds for index, (role, case) in enumerate(keys)]
    (out_dir / "manifest.json").write_text(json.dumps(entries, indent=1) + "\n")
    used = sorted({e["format"] for e in entries})
    print("wrote %d cases in %s (formats %s)" % (len(entries), out_dir, ", ".join(used)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
