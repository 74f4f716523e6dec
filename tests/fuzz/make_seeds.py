#!/usr/bin/env python3
"""Writes the seed corpus of the fuzz targets (tests/fuzz/corpus/TARGET/): small valid files of
every format and variant the readers accept. Re-run after adding a variant; the files are
committed, so fuzzing and the replay test need no Python."""
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))
# A closed tetrahedron with thickness in every direction (a valid swatch) and a slab of two
# tetrahedra as a second element.
V = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 0.3)]
F = [(0, 2, 1), (0, 1, 3), (1, 2, 3), (0, 3, 2)]
V2 = V + [(x + 2, y, z) for x, y, z in V]
F2 = F + [(a + 4, b + 4, c + 4) for a, b, c in F]
E2 = [0] * 4 + [1] * 4


def put(target, name, data):
    os.makedirs(os.path.join(HERE, "corpus", target), exist_ok=True)
    with open(os.path.join(HERE, "corpus", target, name), "wb") as f:
        f.write(data if isinstance(data, bytes) else data.encode())


def obj(vs, fs, groups=None, style="plain"):
    out = ["# seed\n"] + ["v %g %g %g\n" % v for v in vs]
    last = None
    for i, (a, b, c) in enumerate(fs):
        if groups and groups[i] != last:
            last = groups[i]
            out.append("g element_%d\n" % last)
        if style == "plain":
            out.append("f %d %d %d\n" % (a + 1, b + 1, c + 1))
        elif style == "slashes":
            out.append("f %d/1/1 %d//2 %d/3\n" % (a + 1, b + 1, c + 1))
        else:  # negative, relative to the vertices read so far
            n = len(vs)
            out.append("f %d %d %d\n" % (a - n, b - n, c - n))
    return "".join(out)


def off(vs, fs, keyword="OFF"):
    out = [keyword + "\n# comment\n%d %d 0\n" % (len(vs), len(fs))]
    for v in vs:
        out.append("%g %g %g%s\n" % (v + ((" 1 0 0 1") if keyword == "COFF" else "",)))
    for a, b, c in fs:
        out.append("3 %d %d %d\n" % (a, b, c))
    return "".join(out)


def ply_ascii(vs, fs, elements=None, extra=False):
    head = ["ply\nformat ascii 1.0\ncomment seed\nelement vertex %d\nproperty float x\nproperty float y\nproperty float z\n" % len(vs)]
    if extra:
        head.append("property float nx\nproperty uchar red\n")
    head.append("element face %d\nproperty list uchar int vertex_indices\n" % len(fs))
    if elements:
        head.append("property int element\n")
    head.append("end_header\n")
    body = []
    for v in vs:
        body.append("%g %g %g%s\n" % (v + (" 0.5 200" if extra else "",)))
    for i, (a, b, c) in enumerate(fs):
        body.append("3 %d %d %d%s\n" % (a, b, c, " %d" % elements[i] if elements else ""))
    return "".join(head + body)


def ply_binary(vs, fs, little=True, elements=None, extra=False, quads=False):
    e = "<" if little else ">"
    head = "ply\nformat binary_%s_endian 1.0\nelement vertex %d\nproperty double x\nproperty double y\nproperty double z\n" % (
        "little" if little else "big", len(vs))
    if extra:
        head += "property float confidence\nproperty list uchar float texture\n"
    head += "element face %d\nproperty list uchar uint vertex_indices\n" % len(fs)
    if elements:
        head += "property int element\n"
    if extra:
        head += "element edge 1\nproperty int vertex1\nproperty int vertex2\n"
    head += "end_header\n"
    body = b""
    for v in vs:
        body += struct.pack(e + "ddd", *v)
        if extra:
            body += struct.pack(e + "fB", 1.0, 2) + struct.pack(e + "ff", 0.25, 0.75)
    for i, f in enumerate(fs):
        body += struct.pack(e + "B", 3) + struct.pack(e + "III", *f)
        if elements:
            body += struct.pack(e + "i", elements[i])
    if extra:
        body += struct.pack(e + "ii", 0, 1)
    return head.encode() + body


def stl_ascii(vs, fs):
    out = ["solid seed\n"]
    for f in fs:
        out.append("facet normal 0 0 1\n outer loop\n")
        for i in f:
            out.append("  vertex %g %g %g\n" % vs[i])
        out.append(" endloop\nendfacet\n")
    out.append("endsolid seed\n")
    return "".join(out)


def stl_binary(vs, fs):
    out = b"binary seed".ljust(80, b" ") + struct.pack("<I", len(fs))
    for f in fs:
        out += struct.pack("<fff", 0, 0, 1)
        for i in f:
            out += struct.pack("<fff", *vs[i])
        out += struct.pack("<H", 0)
    return out


meshes = {
    "obj": [("tetra.obj", obj(V, F)), ("groups.obj", obj(V2, F2, E2)), ("slashes.obj", obj(V, F, style="slashes")),
            ("negative.obj", obj(V, F, style="negative")),
            ("quad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nf 1 2 3 4\nf 1 2 5\nf 2 3 5\nf 3 4 5\nf 4 1 5\n")],
    "ply": [("ascii.ply", ply_ascii(V, F)), ("ascii_elements.ply", ply_ascii(V2, F2, E2)),
            ("ascii_extra.ply", ply_ascii(V, F, extra=True)), ("binary_le.ply", ply_binary(V, F, True)),
            ("binary_be.ply", ply_binary(V, F, False)), ("binary_le_extra.ply", ply_binary(V2, F2, True, E2, extra=True)),
            ("binary_be_extra.ply", ply_binary(V2, F2, False, E2, extra=True))],
    "off": [("tetra.off", off(V, F)), ("coff.off", off(V, F, "COFF")),
            ("inline_counts.off", "OFF 4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 0.3\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n"),
            ("slab.off", off(V2, F2))],
    "stl": [("ascii.stl", stl_ascii(V, F)), ("binary.stl", stl_binary(V, F)), ("binary_slab.stl", stl_binary(V2, F2))],
}
for target, files in meshes.items():
    for name, data in files:
        put(target, name, data)
# The swatch target: one byte picks the format (0 obj, 1 ply, 2 off, 3 stl), then the file.
for index, target in enumerate(["obj", "ply", "off", "stl"]):
    for name, data in meshes[target][:3]:
        put("swatch", name, bytes([index]) + (data if isinstance(data, bytes) else data.encode()))
# The base target: the same, and bases as exporters spoil them (prepare_base repairs these).
for index, target in enumerate(["obj", "ply", "off", "stl"]):
    for name, data in meshes[target][:3]:
        put("base", name, bytes([index]) + (data if isinstance(data, bytes) else data.encode()))
put("base", "flipped_face.off", bytes([2]) + off(V, [F[0], F[1][::-1]] + list(F[2:])).encode())
put("base", "duplicate_face.off", bytes([2]) + off(V, list(F) + [F[0]]).encode())
put("base", "t_junction.off", bytes([2]) + "OFF\n6 8 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n0.5 0 0\n5 5 5\n"
    "3 0 2 4\n3 4 2 1\n3 0 4 3\n3 4 1 3\n3 1 2 3\n3 0 3 2\n3 0 1 4\n3 5 5 5\n".encode())

put("netpbm", "p1.pbm", "P1\n# comment\n4 2\n0110\n1 0 0 1\n")
put("netpbm", "p2.pgm", "P2\n3 2\n255\n0 128 255\n10 20 30\n")
put("netpbm", "p3.ppm", "P3\n2 1\n255\n255 0 0 0 255 0\n")
put("netpbm", "p4.pbm", b"P4\n10 2\n" + bytes([0b10101010, 0b11000000, 0b01010101, 0b00000000]))
put("netpbm", "p5.pgm", b"P5\n3 2\n255\n" + bytes([0, 100, 255, 7, 8, 9]))
put("netpbm", "p5_16bit.pgm", b"P5 2 1 65535\n" + bytes([0xFF, 0xFF, 0x01, 0x00]))
put("netpbm", "p6.ppm", b"P6\n2 1\n255\n" + bytes([255, 0, 0, 0, 0, 255]))

# The guidance-field target: JSON field files against the fuzz body's tetrahedron (vertices 0-3).
# Files named bad_* are rejected with an InputError; every other one must parse.
fields = {
    "vertex.json": '{"directions": [{"vertex": 1, "direction": [1, 0, 0]}]}\n',
    "point.json": '{"directions": [{"point": [0.9, 0.1, 0.0], "direction": [0, 1, 0]}]}\n',
    "mixed.json": '{\n  "directions": [\n    {"vertex": 0, "direction": [1.5e0, -2, 0.25]},\n'
                  '    {"point": [-1E-3, 2.0, 0.3], "direction": [0, 0, 1]},\n'
                  '    {"vertex": 3, "point": [0, 0, 0], "direction": [1, 1, 1]}\n  ]\n}\n',
    "all_vertices.json": '{"directions": [' + ", ".join(
        '{"vertex": %d, "direction": [%d, 1, 0]}' % (v, v + 1) for v in range(4)) + ']}',
    "repeated.json": '{"directions": [{"vertex": 2, "direction": [1, 0, 0]}, {"vertex": 2, "direction": [0, 1, 0]}]}',
    "empty.json": '{"directions": []}',
    "extremes.json": '{"directions": [{"vertex": 0, "direction": [1e308, -1e308, 5e-324]}, '
                     '{"point": [1e300, -1e300, 0], "direction": [0, 0, 1e-150]}]}',
    # Nonzero but its length underflows: read as a zero direction today.
    "bad_underflow.json": '{"directions": [{"vertex": 0, "direction": [0, 0, 4.9e-324]}]}',
    "extra_keys.json": '{"comment": "caf\\u00e9 \\"field\\"", "version": null, "flags": [true, false, {}],'
                       ' "directions": [{"vertex": 1, "direction": [0, 0, 1], "weight": -0.5, "note": [[]]}]}',
    "bad_vertex.json": '{"directions": [{"vertex": 99, "direction": [1, 0, 0]}]}',
    "bad_zero.json": '{"directions": [{"vertex": 0, "direction": [0, 0, 0]}]}',
    "bad_json.json": '{"directions": [{"vertex": 0, "direction": [1, 0,',
}
for name, data in fields.items():
    put("field", name, data)
