#!/usr/bin/env python3
"""A plain-weave exemplar made without meshquilt: numpy tubes with an elliptical section in the
vertical plane across each yarn, cosine crimp, fan caps, written as OBJ without groups (yarns are
its connected components). Its pitch, radius, sides and samples differ from `meshquilt swatch
weave`'s.

    make_exemplar.py OUT.obj [--yarns N] [--pitch P] [--sides K] [--samples M] [--tilt DEGREES]
"""
import argparse

import numpy as np


def tube(centre, side, sides, radius, height):
    """Rings in the vertical plane across the run: centre (S, 3), side (3,) the sideways axis."""
    up = np.array([0.0, 0.0, 1.0])
    angles = 2 * np.pi * np.arange(sides) / sides
    rings = centre[:, None, :] + radius * np.cos(angles)[None, :, None] * side + height * np.sin(angles)[None, :, None] * up
    vertices = np.concatenate([rings.reshape(-1, 3), centre[:1], centre[-1:]])
    s, k = np.meshgrid(np.arange(len(centre) - 1), np.arange(sides), indexing="ij")
    a, b = s * sides + k, s * sides + (k + 1) % sides
    c, d = a + sides, b + sides
    faces = [np.stack([a, c, d], -1).reshape(-1, 3), np.stack([a, d, b], -1).reshape(-1, 3)]
    head, tail = len(vertices) - 2, len(vertices) - 1
    last = (len(centre) - 1) * sides
    ring = np.arange(sides)
    faces.append(np.stack([np.full(sides, head), (ring + 1) % sides, ring], -1))
    faces.append(np.stack([np.full(sides, tail), last + ring, last + (ring + 1) % sides], -1))
    return vertices, np.concatenate(faces)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("out")
    parser.add_argument("--yarns", type=int, default=8)
    parser.add_argument("--pitch", type=float, default=1.7)
    parser.add_argument("--sides", type=int, default=10)
    parser.add_argument("--samples", type=int, default=7)
    parser.add_argument("--tilt", type=float, default=0.0)
    args = parser.parse_args()
    n, p = args.yarns, args.pitch
    amplitude, radius, height = 0.3 * p, 0.2 * p, 0.16 * p
    run = np.linspace(0.0, n * p, n * args.samples + 1)
    wave = amplitude * np.cos(np.pi * (run / p - 0.5))
    parts = []
    for i in range(n):  # warp i along y at x = (i + 1/2) p, over weft j where i + j is even
        centre = np.stack([np.full_like(run, (i + 0.5) * p), run, (-1) ** i * wave], -1)
        parts.append(tube(centre, np.array([1.0, 0.0, 0.0]), args.sides, radius, height))
    for j in range(n):  # weft j along x at y = (j + 1/2) p
        centre = np.stack([run, np.full_like(run, (j + 0.5) * p), -((-1) ** j) * wave], -1)
        parts.append(tube(centre, np.array([0.0, 1.0, 0.0]), args.sides, radius, height))
    t = np.radians(args.tilt)
    turn = np.array([[np.cos(t), -np.sin(t), 0.0], [np.sin(t), np.cos(t), 0.0], [0.0, 0.0, 1.0]])
    with open(args.out, "w") as f:
        offset = 0
        lines = []
        for vertices, faces in parts:
            lines += ["v %.9f %.9f %.9f" % tuple(turn @ v) for v in vertices]
        for vertices, faces in parts:
            lines += ["f %d %d %d" % tuple(face + offset + 1) for face in faces]
            offset += len(vertices)
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
