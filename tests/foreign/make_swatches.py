#!/usr/bin/env python3
"""Foreign swatches for meshquilt's tests, made without meshquilt's own swatch generators.

Usage:
  make_swatches.py --list
  make_swatches.py --family F --seed N -o OUT.ply [--format ascii|binary]

A swatch is built the way another tool would build it: each element a closed tube or torus
swept along a centre line, written as a plain PLY of vertices and triangles (no element ids).
Every family draws its sizes, tessellation, caps, rotation and noise from the seed, and is
refused and redrawn until no two elements come closer than their wires allow. Faces are turned
outward per element (positive enclosed volume). The border-cut family alone has open elements.

Needs numpy (Debian: python3-numpy).
"""

import argparse
import math
import struct
import sys

import numpy as np

# Clearance the elements keep beyond touching, in units of the wire radius.
CLEARANCE = 0.15
# Redraws of a family's parameters before giving up.
MAX_DRAWS = 400


class Element:
    """One closed (or cut open) piece: its mesh, and the centre lines with the radius of the wire
    around them. The mesh lies within `radius` of the polyline through `spine` (every ring of the
    sweep is a disc of that radius centred on the spine, and the hull of two discs lies in the
    capsule around their segment), which is what the clearance check relies on."""

    def __init__(self, vertices, faces, spine, radius, closed_spine):
        self.vertices = vertices
        self.faces = faces
        self.spine = spine
        self.radius = radius
        self.closed_spine = closed_spine


# ---------------------------------------------------------------------------------------------
# Sweeps


def _unit(v):
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def _sweep_frames(spine, closed):
    """Tangent, and two normals per spine point. The first normal stays horizontal so crimped
    yarns keep their sides level; a spine point with a vertical tangent falls back to +y."""
    if closed:
        tangent = np.roll(spine, -1, axis=0) - np.roll(spine, 1, axis=0)
    else:
        tangent = np.gradient(spine, axis=0)
    tangent = _unit(tangent)
    side = np.cross(np.array([0.0, 0.0, 1.0]), tangent)
    flat = np.linalg.norm(side, axis=1) < 1e-9
    side[flat] = np.cross(np.array([0.0, 1.0, 0.0]), tangent[flat])
    side = _unit(side)
    up = np.cross(tangent, side)
    return tangent, side, up


def _ring_strips(rings, sides, closed, wrap_shift=0):
    """Triangles joining consecutive rings of `sides` vertices, numbered ring by ring. Ring i+1
    is taken as turned half a step ahead of ring i, which is true of the twisted sweeps and harmless
    for the straight ones (it only picks the diagonal). Closing a loop, the first ring's vertex
    j + wrap_shift is the one that follows the last ring's vertex j."""
    i = np.arange(rings if closed else rings - 1)[:, None]
    j = np.arange(sides)[None, :]
    shift = np.where(i + 1 == rings, wrap_shift, 0)
    a = i * sides + j
    b = i * sides + (j + 1) % sides
    c = ((i + 1) % rings) * sides + (j + shift) % sides
    d = ((i + 1) % rings) * sides + (j + 1 + shift) % sides
    first = np.stack([a, b, c], axis=-1).reshape(-1, 3)
    second = np.stack([c, b, d], axis=-1).reshape(-1, 3)
    return np.concatenate([first, second])


def _outward(vertices, faces):
    v0, v1, v2 = (vertices[faces[:, k]] for k in range(3))
    volume = np.einsum("ij,ij->i", v0, np.cross(v1, v2)).sum() / 6.0
    return faces if volume > 0 else faces[:, ::-1].copy()


def sweep_loop(spine, radius, sides, twisted, squash=1.0):
    """A torus-like closed tube around a closed spine (#spine points, even when twisted).
    squash < 1 flattens the section along the second normal (oval wire)."""
    count = len(spine)
    assert not twisted or count % 2 == 0
    # Frames from the loop's own centre: a vertical loop has no level normal to follow.
    tangent = _unit(np.roll(spine, -1, axis=0) - np.roll(spine, 1, axis=0))
    side = _unit(spine - spine.mean(0))
    side = _unit(side - (side * tangent).sum(1, keepdims=True) * tangent)
    up = np.cross(tangent, side)
    step = 2.0 * math.pi / sides
    phase = (np.arange(count) * 0.5 * step if twisted else np.zeros(count))[:, None]
    angle = phase + np.arange(sides)[None, :] * step
    vertices = (spine[:, None, :] + radius * (np.cos(angle)[..., None] * side[:, None, :]
                                               + squash * np.sin(angle)[..., None] * up[:, None, :]))
    vertices = vertices.reshape(-1, 3)
    # Twisted half a step a ring, the loop comes back count/2 steps round.
    faces = _ring_strips(count, sides, closed=True, wrap_shift=(count // 2) % sides if twisted else 0)
    return Element(vertices, _outward(vertices, faces), spine, radius, closed_spine=True)


def sweep_yarn(spine, radius, sides, cap, cap_rings=3):
    """An open spine swept into a tube closed at both ends: cap 'flat' (a polygon fanned from one
    of its own vertices), 'fan' (triangles to a vertex on the spine's end) or 'hemi' (a dome of
    `cap_rings` shrinking rings and a tip)."""
    tangent, side, up = _sweep_frames(spine, closed=False)
    centres, sides_v, ups, radii = [spine], [side], [up], [np.full(len(spine), radius)]
    tips = [spine[0], spine[-1]]
    if cap == "hemi":
        lat = np.linspace(0.0, 0.5 * math.pi, cap_rings + 2)[1:-1]
        for end, sign in ((0, -1.0), (-1, 1.0)):
            offset = sign * radius * np.sin(lat)[:, None] * tangent[end]
            dome = spine[end] + offset
            if end == 0:
                dome = dome[::-1]
            grow = radius * np.cos(lat) if end == -1 else radius * np.cos(lat)[::-1]
            stack_at = 0 if end == 0 else len(centres)
            centres.insert(stack_at, dome)
            sides_v.insert(stack_at, np.repeat(side[end][None], len(lat), axis=0))
            ups.insert(stack_at, np.repeat(up[end][None], len(lat), axis=0))
            radii.insert(stack_at, grow)
        tips = [spine[0] - radius * tangent[0], spine[-1] + radius * tangent[-1]]
    centres, sides_v, ups, radii = (np.concatenate(x) for x in (centres, sides_v, ups, radii))
    rings = len(centres)
    step = 2.0 * math.pi / sides
    angle = np.arange(sides)[None, :] * step + np.zeros((rings, 1))
    ring_vertices = centres[:, None, :] + radii[:, None, None] * (
        np.cos(angle)[..., None] * sides_v[:, None, :] + np.sin(angle)[..., None] * ups[:, None, :])
    vertices = ring_vertices.reshape(-1, 3)
    faces = [_ring_strips(rings, sides, closed=False)]
    last = (rings - 1) * sides
    j = np.arange(sides)
    if cap == "flat":
        k = np.arange(1, sides - 1)
        faces.append(np.stack([np.zeros_like(k), k + 1, k], axis=1))
        faces.append(np.stack([np.full_like(k, last), last + k, last + k + 1], axis=1))
    else:
        base = len(vertices)
        vertices = np.concatenate([vertices, np.array(tips)])
        faces.append(np.stack([np.full(sides, base), (j + 1) % sides, j], axis=1))
        faces.append(np.stack([np.full(sides, base + 1), last + j, last + (j + 1) % sides], axis=1))
    faces = np.concatenate(faces)
    return Element(vertices, _outward(vertices, faces), spine, radius, closed_spine=False)


def circle(centre, normal, radius, count):
    """`count` points on a circle, starting from a horizontal direction when there is one."""
    normal = _unit(np.asarray(normal, dtype=float))
    first = np.cross(normal, [0.0, 0.0, 1.0])
    if np.linalg.norm(first) < 1e-9:
        first = np.array([1.0, 0.0, 0.0])
    first = _unit(first)
    second = np.cross(normal, first)
    # Half a step off the start, so no sample lies in a neighbour's plane by construction.
    t = (np.arange(count) + 0.5) * 2.0 * math.pi / count
    return np.asarray(centre, float) + radius * (np.cos(t)[:, None] * first + np.sin(t)[:, None] * second)


# ---------------------------------------------------------------------------------------------
# Checks


def _segments(element):
    points = element.spine
    ends = np.roll(points, -1, axis=0) if element.closed_spine else points[1:]
    starts = points if element.closed_spine else points[:-1]
    return starts, ends


def spine_gap(a, b, samples=6):
    """A lower bound on the distance between the capsule chains of two elements, less their
    radii: the spines are sampled every 1/samples of a segment, and each sample stands for the
    points within half that spacing of it along its segment."""
    def dense(element):
        s, e = _segments(element)
        t = (np.arange(samples) / samples)[None, :, None]
        points = (s[:, None, :] + t * (e - s)[:, None, :]).reshape(-1, 3)
        slack = 0.5 * np.linalg.norm(e - s, axis=1).max() / samples
        return points, slack

    pa, sa = dense(a)
    pb, sb = dense(b)
    lo = np.maximum(pa.min(0), pb.min(0)) - (a.radius + b.radius + 1.0)
    hi = np.minimum(pa.max(0), pb.max(0)) + (a.radius + b.radius + 1.0)
    if np.any(lo > hi):
        return np.inf
    best = np.inf
    for chunk in np.array_split(pa, max(1, len(pa) // 512)):
        d = np.sqrt(((chunk[:, None, :] - pb[None, :, :]) ** 2).sum(-1)).min()
        best = min(best, d)
    return best - sa - sb - a.radius - b.radius


def clear_of_each_other(elements, margin):
    """True when every pair of elements keeps `margin` between their wires."""
    boxes = [(e.spine.min(0) - e.radius, e.spine.max(0) + e.radius) for e in elements]
    for i in range(len(elements)):
        for j in range(i + 1, len(elements)):
            if np.any(boxes[i][0] > boxes[j][1] + margin) or np.any(boxes[j][0] > boxes[i][1] + margin):
                continue
            if spine_gap(elements[i], elements[j]) < margin:
                return False
    return True


def linked(loop, other):
    """Linking number of two closed spines, counted as the signed crossings of `other` through
    the flat disc bounded by `loop` (a planar circle in every mail here)."""
    centre = loop.spine.mean(0)
    normal = _unit(np.cross(loop.spine[1] - loop.spine[0], loop.spine[2] - loop.spine[0]))
    radius = np.linalg.norm(loop.spine[0] - centre)
    s, e = _segments(other)
    hs, he = (s - centre) @ normal, (e - centre) @ normal
    cross = (hs >= 0) != (he >= 0)
    t = hs[cross] / (hs[cross] - he[cross])
    hit = s[cross] + t[:, None] * (e[cross] - s[cross])
    inside = np.linalg.norm(hit - centre - ((hit - centre) @ normal)[:, None] * normal, axis=1) < radius
    return int(np.sign(he[cross] - hs[cross])[inside].sum())


# ---------------------------------------------------------------------------------------------
# Families


def _yarn_spine(start, end, rings, profile, rng, uneven):
    """Points from `start` to `end` (x-y), heights from profile(distance along), spaced evenly or,
    when uneven, by random steps from 0.4 to 1.6 of the mean."""
    if uneven:
        steps = rng.uniform(0.4, 1.6, rings - 1)
        t = np.concatenate([[0.0], np.cumsum(steps)]) / steps.sum()
    else:
        t = np.linspace(0.0, 1.0, rings)
    start, end = np.asarray(start, float), np.asarray(end, float)
    xy = start[None, :] + t[:, None] * (end - start)[None, :]
    z = profile(xy)
    return np.column_stack([xy, z])


def woven(p, rng):
    """Wires along x (wefts) and along y (warps) over and under each other at every crossing.
    p: count, pitch, radius, crimp, sharpness (0: a cosine; larger: flatter tops), sides,
    rings_per_pitch, extra (yarn length minus count pitches, in pitches), cap, uneven."""
    n, pitch, radius, crimp = p["count"], p["pitch"], p["radius"], p["crimp"]
    length = (n + p["extra"]) * pitch
    middle = 0.5 * (n - 1) * pitch
    rings = max(8, int(round(p["rings_per_pitch"] * length / pitch)) + 1)
    k = p["sharpness"]

    def wave(u, phase):
        c = np.cos(math.pi * u / pitch + phase)
        return crimp * (np.tanh(k * c) / math.tanh(k) if k > 0 else c)

    elements = []
    for j in range(n):
        spine = _yarn_spine((middle - 0.5 * length, j * pitch), (middle + 0.5 * length, j * pitch), rings,
                            lambda xy, j=j: wave(xy[:, 0], math.pi * j), rng, p["uneven"])
        elements.append(sweep_yarn(spine, radius, p["sides"], p["cap"]))
    for i in range(n):
        spine = _yarn_spine((i * pitch, middle - 0.5 * length), (i * pitch, middle + 0.5 * length), rings,
                            lambda xy, i=i: -wave(xy[:, 1], math.pi * i), rng, p["uneven"])
        elements.append(sweep_yarn(spine, radius, p["sides"], p["cap"]))
    return elements


def _length_mode(rng, overlap_max):
    mode = rng.choice(["whole", "overlap", "short"])
    if mode == "whole":
        return 0.0
    if mode == "overlap":
        return float(rng.uniform(0.05, overlap_max))
    return -float(rng.uniform(0.05, 0.3))


def wire_mesh(rng):
    pitch = float(rng.uniform(0.6, 1.6))
    radius = pitch * float(rng.uniform(0.04, 0.1))
    p = dict(count=int(rng.integers(8, 11)), pitch=pitch, radius=radius, sharpness=0.0,
             crimp=float(rng.uniform(max(1.25 * radius, radius + 0.03 * pitch), 0.2 * pitch)),
             sides=int(rng.integers(6, 17)), extra=_length_mode(rng, 0.8),
             cap=str(rng.choice(["flat", "fan", "hemi"])), uneven=bool(rng.random() < 0.5))
    fine = rng.random() < 0.5
    per_pitch = int(rng.integers(10, 15)) if fine else int(rng.integers(4, 7))
    # Keep the whole swatch near 40,000 faces: 2n yarns of (n + extra) pitches, 2 x sides a ring.
    budget = 40000 / (2 * p["count"] * (p["count"] + 1) * 2 * p["sides"])
    p["rings_per_pitch"] = max(3, min(per_pitch, int(budget)))
    return woven(p, rng), p


def plain_weave(rng):
    pitch = float(rng.uniform(0.8, 1.5))
    radius = pitch * float(rng.uniform(0.12, 0.17))
    p = dict(count=int(rng.integers(6, 9)), pitch=pitch, radius=radius,
             crimp=float(rng.uniform(1.15 * radius, min(1.5 * radius, 0.22 * pitch))),
             sharpness=float(rng.uniform(0.0, 2.0)), sides=int(rng.integers(8, 15)),
             rings_per_pitch=int(rng.integers(6, 11)), extra=_length_mode(rng, 0.5),
             cap=str(rng.choice(["flat", "fan", "hemi"])), uneven=bool(rng.random() < 0.3))
    return woven(p, rng), p


def issue_wire(rng):
    """The wire swatch of issue 41, exactly: no draw."""
    p = dict(count=9, pitch=1.0, radius=0.07, crimp=0.12, sharpness=0.0, sides=8, extra=0.6,
             cap="fan", uneven=False, rings_per_pitch=None)
    n, length = 9, 9.6
    middle = 4.0
    wave = lambda u, phase: 0.12 * np.cos(math.pi * u + phase)  # noqa: E731
    elements = []
    for j in range(n):
        spine = _yarn_spine((middle - 4.8, j), (middle + 4.8, j), 120, lambda xy, j=j: wave(xy[:, 0], math.pi * j),
                            rng, False)
        elements.append(sweep_yarn(spine, 0.07, 8, "fan"))
    for i in range(n):
        spine = _yarn_spine((i, middle - 4.8), (i, middle + 4.8), 120, lambda xy, i=i: -wave(xy[:, 1], math.pi * i),
                            rng, False)
        elements.append(sweep_yarn(spine, 0.07, 8, "fan"))
    return elements, p


def _ring_tessellation(rng):
    return dict(segments=2 * int(rng.integers(9, 17)), sides=int(rng.integers(6, 11)),
                twisted=bool(rng.random() < 0.7))


def mail_4in1(rng):
    """European 4-in-1: rows along x of rings leaning about y, alternate rows leaning the other
    way and shifted half a ring, each ring through two of the row above and two below. The ring
    of row k, column i links (k+1, i) and (k+1, i-1) for even k, (k+1, i) and (k+1, i+1) for odd
    k, and no other ring: checked by linking number for every pair."""
    rows, columns = int(rng.integers(4, 7)) // 2 * 2, int(rng.integers(4, 7))
    t = _ring_tessellation(rng)
    p = dict(rows=rows, columns=columns, ring_radius=1.0, wire=float(rng.uniform(0.12, 0.17)),
             pitch_x=float(rng.uniform(1.2, 1.6)), pitch_y=float(rng.uniform(1.15, 1.3)),
             tilt=float(rng.uniform(28.0, 42.0)), **t)
    elements, where = [], []
    for k in range(rows):
        lean = math.radians(p["tilt"]) * (1 if k % 2 == 0 else -1)
        normal = (math.sin(lean), 0.0, math.cos(lean))
        for i in range(columns):
            centre = (i * p["pitch_x"] + (0.5 * p["pitch_x"] if k % 2 else 0.0), k * p["pitch_y"], 0.0)
            spine = circle(centre, normal, 1.0, t["segments"])
            elements.append(sweep_loop(spine, p["wire"], t["sides"], t["twisted"]))
            where.append((k, i))

    def meant(a, b):
        (ka, ia), (kb, ib) = sorted([a, b])
        if kb != ka + 1:
            return False
        return ib in ((ia, ia - 1) if ka % 2 == 0 else (ia, ia + 1))

    return elements, p, lambda a, b: meant(where[a], where[b])


def mail_6in1(rng):
    """Japanese 6-in-1: flat rings on a hexagonal lattice, and an upright connector ring between
    every two neighbours, through both. Connectors link their two flat rings and nothing else."""
    columns, rows = int(rng.integers(4, 6)), int(rng.integers(4, 6))
    t = _ring_tessellation(rng)
    p = dict(columns=columns, rows=rows, flat_radius=1.0, flat_wire=float(rng.uniform(0.1, 0.16)),
             spacing=float(rng.uniform(2.35, 2.7)), connector_radius=float(rng.uniform(0.5, 0.75)),
             connector_wire=float(rng.uniform(0.07, 0.12)), **t)
    d = p["spacing"]
    centres = {}
    for r in range(rows):
        for c in range(columns):
            centres[(r, c)] = np.array([c * d + (0.5 * d if r % 2 else 0.0), r * d * math.sqrt(3) / 2, 0.0])
    elements, role = [], []
    for key, centre in centres.items():
        elements.append(sweep_loop(circle(centre, (0, 0, 1), 1.0, t["segments"]), p["flat_wire"], t["sides"],
                                   t["twisted"]))
        role.append(("flat", key))
    keys = list(centres)
    for a in range(len(keys)):
        for b in range(a + 1, len(keys)):
            ca, cb = centres[keys[a]], centres[keys[b]]
            if abs(np.linalg.norm(cb - ca) - d) > 1e-6:
                continue
            along = _unit(cb - ca)
            normal = np.cross(along, [0.0, 0.0, 1.0])
            segments = max(12, t["segments"] // 2 // 2 * 2)
            elements.append(sweep_loop(circle(0.5 * (ca + cb), normal, p["connector_radius"], segments),
                                       p["connector_wire"], max(6, t["sides"] - 2), t["twisted"]))
            role.append(("connector", (keys[a], keys[b])))

    def meant(a, b):
        (ra, ka), (rb, kb) = role[a], role[b]
        if ra == rb:
            return False
        flat, connector = (ka, kb) if ra == "flat" else (kb, ka)
        return flat in connector

    return elements, p, meant


def chains_2in2(rng):
    """Separate chains along x; each link is two parallel rings, links alternately lying flat and
    standing up, each ring through both rings of the links before and after it."""
    chains, links = int(rng.integers(3, 5)), int(rng.integers(6, 9))
    t = _ring_tessellation(rng)
    wire = float(rng.uniform(0.08, 0.13))
    p = dict(chains=chains, links=links, ring_radius=1.0, wire=wire,
             gap=2.0 * wire + float(rng.uniform(0.06, 0.15)), step=float(rng.uniform(1.35, 1.6)),
             chain_spacing=float(rng.uniform(2.7, 3.2)), **t)
    elements, where = [], []
    for c in range(chains):
        for k in range(links):
            for half in (-0.5, 0.5):
                if k % 2 == 0:
                    centre, normal = (k * p["step"], c * p["chain_spacing"], half * p["gap"]), (0, 0, 1)
                else:
                    centre, normal = (k * p["step"], c * p["chain_spacing"] + half * p["gap"], 0.0), (0, 1, 0)
                elements.append(sweep_loop(circle(centre, normal, 1.0, t["segments"]), wire, t["sides"],
                                           t["twisted"]))
                where.append((c, k))

    def meant(a, b):
        (ca, ka), (cb, kb) = where[a], where[b]
        return ca == cb and abs(ka - kb) == 1

    return elements, p, meant


def border_cut(rng):
    """Flat rings on a square grid, cut by a rectangle that passes through the outer rings: the
    rings it crosses are open, the rest closed."""
    count = int(rng.integers(4, 6))
    t = _ring_tessellation(rng)
    p = dict(count=count, wire=float(rng.uniform(0.15, 0.3)), spacing=float(rng.uniform(2.6, 3.2)),
             cut=float(rng.uniform(0.3, 0.7)), **t)
    elements = [sweep_loop(circle((i * p["spacing"], j * p["spacing"], 0.0), (0, 0, 1), 1.0, t["segments"]),
                           p["wire"], t["sides"], t["twisted"])
                for j in range(count) for i in range(count)]
    # The rectangle passes `cut` ring radii inside the outer rings' centres.
    lo, hi = p["cut"], (count - 1) * p["spacing"] - p["cut"]
    for e in elements:
        middle = e.vertices[e.faces].mean(axis=1)
        keep = np.all((middle[:, :2] >= lo) & (middle[:, :2] <= hi), axis=1)
        e.faces = e.faces[keep]
    return [e for e in elements if len(e.faces)], p


# name: (builder, one line for --list)
FAMILIES = {
    "wire-mesh": (wire_mesh, "crimped wire mesh: 8-10 wires each way, 6-16 sides, whole, overlapping or short lengths"),
    "plain-weave": (plain_weave, "plain weave of thick over-under yarns, cosine to flat-topped crimp"),
    "mail-4in1": (mail_4in1, "European 4-in-1 ring mail, twisted or straight ring tessellation"),
    "mail-6in1": (mail_6in1, "Japanese 6-in-1 mail: flat rings and upright connectors"),
    "chains-2in2": (chains_2in2, "separate 2-in-2 chains along x"),
    "border-cut": (border_cut, "flat rings cut open by the swatch border (open elements)"),
    "issue-wire": (issue_wire, "issue 41's wire: 9 x 9 wires, r 0.07, pitch 1, crimp 0.12, 9.6 long"),
}


def build(family, seed):
    """Draws the family's parameters from the seed until the elements clear each other (and, for
    the mails, link as meant), then applies the seed's rotation and noise. Returns (elements,
    parameters)."""
    rng = np.random.default_rng([seed, sum(map(ord, family))])
    builder = FAMILIES[family][0]
    for _ in range(MAX_DRAWS):
        made = builder(rng)
        elements, p = made[0], made[1]
        if family == "border-cut":
            break
        thinnest = min(e.radius for e in elements)
        if not clear_of_each_other(elements, CLEARANCE * thinnest):
            continue
        if len(made) == 3 and not links_as_meant(elements, made[2]):
            continue
        break
    else:
        raise SystemExit("make_swatches.py: %s seed %d: no clear draw in %d tries" % (family, seed, MAX_DRAWS))
    if family != "issue-wire":
        thinnest = min(e.radius for e in elements)
        jitter = float(rng.uniform(0.01, 0.04)) * thinnest if rng.random() < 0.5 else 0.0
        angle = float(rng.uniform(0.0, 360.0)) if rng.random() < 0.5 else 0.0
        for e in elements:
            e.vertices = e.vertices + rng.normal(0.0, jitter / 3.0, e.vertices.shape).clip(-jitter, jitter)
        turn(elements, angle)
        p.update(jitter=jitter, rotation=angle)
    return elements, p


def links_as_meant(elements, meant):
    centres = np.array([e.spine.mean(0) for e in elements])
    reach = 2.0 * max(np.linalg.norm(e.spine - e.spine.mean(0), axis=1).max() for e in elements)
    for a in range(len(elements)):
        near = np.nonzero(np.linalg.norm(centres - centres[a], axis=1) < reach)[0]
        for b in near[near > a]:
            if (linked(elements[a], elements[b]) != 0) != meant(a, int(b)):
                return False
    return True


def turn(elements, degrees):
    a = math.radians(degrees)
    rotation = np.array([[math.cos(a), -math.sin(a), 0.0], [math.sin(a), math.cos(a), 0.0], [0.0, 0.0, 1.0]])
    for e in elements:
        e.vertices = e.vertices @ rotation.T
        e.spine = e.spine @ rotation.T


def write_ply(path, elements, binary):
    vertices, faces, offset = [], [], 0
    for e in elements:
        vertices.append(e.vertices)
        faces.append(e.faces + offset)
        offset += len(e.vertices)
    vertices = np.concatenate(vertices).astype("<f4")
    faces = np.concatenate(faces).astype("<i4")
    header = ("ply\nformat %s 1.0\ncomment foreign swatch (tests/foreign/make_swatches.py)\n"
              "element vertex %d\nproperty float x\nproperty float y\nproperty float z\n"
              "element face %d\nproperty list uchar int vertex_indices\nend_header\n"
              % ("binary_little_endian" if binary else "ascii", len(vertices), len(faces)))
    with open(path, "wb") as out:
        out.write(header.encode("ascii"))
        if binary:
            rows = np.zeros(len(faces), dtype=[("n", "u1"), ("v", "<i4", 3)])
            rows["n"], rows["v"] = 3, faces
            out.write(vertices.tobytes())
            out.write(rows.tobytes())
        else:
            np.savetxt(out, vertices, fmt="%.7g")
            np.savetxt(out, np.column_stack([np.full(len(faces), 3), faces]), fmt="%d")
    return len(vertices), len(faces)


def main(argv):
    parser = argparse.ArgumentParser(description="Writes a foreign swatch for meshquilt's tests.")
    parser.add_argument("--list", action="store_true", help="list the families and exit")
    parser.add_argument("--family", choices=sorted(FAMILIES))
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("-o", "--output")
    parser.add_argument("--format", choices=["ascii", "binary", "seed"], default="seed",
                        help="PLY encoding; 'seed' picks one from the seed")
    args = parser.parse_args(argv)
    if args.list:
        for name, (_, text) in FAMILIES.items():
            print("%-12s %s" % (name, text))
        return 0
    if not args.family or not args.output:
        parser.error("--family and -o are required (or --list)")
    elements, p = build(args.family, args.seed)
    binary = args.format == "binary" or (args.format == "seed" and args.seed % 2 == 0)
    nv, nf = write_ply(args.output, elements, binary)
    shown = ", ".join("%s=%s" % (k, ("%.4g" % v) if isinstance(v, float) else v) for k, v in p.items())
    print("wrote %s: %d faces, %d vertices, %d elements (%s)" % (args.output, nf, nv, len(elements), shown))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
