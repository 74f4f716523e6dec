#!/usr/bin/env python3
"""Reads the .glb files meshquilt writes with a parser written here from the glTF 2.0
specification (struct and json only), and checks them against the PLY written from the same
result, read by a second parser written here: counts, positions, per-face element and source,
vertex colours, and what the specification requires of a valid file.

usage: glb_reader_test.py MESHQUILT SCRATCH_DIR
"""
import json
import math
import os
import struct
import subprocess
import sys

COMPONENT = {5126: ("f", 4), 5125: ("I", 4), 5123: ("H", 2), 5121: ("B", 1)}
WIDTH = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4}


def read_glb(path):
    data = open(path, "rb").read()
    magic, version, length = struct.unpack_from("<III", data, 0)
    assert magic == 0x46546C67, f"{path}: not glTF binary"
    assert version == 2 and length == len(data), f"{path}: version {version}, length {length} of {len(data)}"
    json_length, json_type = struct.unpack_from("<II", data, 12)
    assert json_type == 0x4E4F534A and json_length % 4 == 0
    gltf = json.loads(data[20:20 + json_length].decode("utf-8"))
    offset = 20 + json_length
    bin_length, bin_type = struct.unpack_from("<II", data, offset)
    assert bin_type == 0x004E4942 and bin_length % 4 == 0
    binary = data[offset + 8:offset + 8 + bin_length]
    assert gltf["asset"]["version"] == "2.0"
    assert gltf["buffers"][0]["byteLength"] <= bin_length

    def accessor(index):
        a = gltf["accessors"][index]
        view = gltf["bufferViews"][a["bufferView"]]
        code, size = COMPONENT[a["componentType"]]
        width = WIDTH[a["type"]]
        start = view.get("byteOffset", 0) + a.get("byteOffset", 0)
        assert start % size == 0, "accessor not aligned to its component size"
        count = a["count"]
        assert start + count * width * size <= view.get("byteOffset", 0) + view["byteLength"]
        flat = struct.unpack_from("<" + code * (count * width), binary, start)
        return [flat[i * width:(i + 1) * width] for i in range(count)], a

    primitive = gltf["meshes"][0]["primitives"][0]
    assert primitive.get("mode", 4) == 4
    attributes = {}
    for name, index in primitive["attributes"].items():
        values, a = accessor(index)
        if name == "POSITION":  # min and max are required for positions
            for k in range(3):
                assert abs(min(v[k] for v in values) - a["min"][k]) <= 1e-6 * (1 + abs(a["min"][k]))
                assert abs(max(v[k] for v in values) - a["max"][k]) <= 1e-6 * (1 + abs(a["max"][k]))
        attributes[name] = values
    indices, a = accessor(primitive["indices"])
    assert a["componentType"] in (5125, 5123, 5121)
    indices = [i[0] for i in indices]
    assert len(indices) % 3 == 0
    assert all(0 <= i < len(attributes["POSITION"]) for i in indices)
    return attributes, [tuple(indices[k:k + 3]) for k in range(0, len(indices), 3)]


def read_ply(path):
    data = open(path, "rb").read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode().split("\n")
    assert header[1] == "format binary_little_endian 1.0"
    elements, current = [], None
    for line in header:
        words = line.split()
        if words and words[0] == "element":
            current = (words[1], int(words[2]), [])
            elements.append(current)
        elif words and words[0] == "property":
            current[2].append(words[1:])
    types = {"double": "d", "float": "f", "int": "i", "uchar": "B", "uint": "I"}
    offset, vertices, faces = end, [], []
    for name, count, properties in elements:
        for _ in range(count):
            row = {}
            for p in properties:
                if p[0] == "list":
                    n = struct.unpack_from("<B", data, offset)[0]
                    offset += 1
                    row[p[-1]] = struct.unpack_from("<" + "i" * n, data, offset)
                    offset += 4 * n
                else:
                    code = types[p[0]]
                    row[p[-1]] = struct.unpack_from("<" + code, data, offset)[0]
                    offset += struct.calcsize(code)
            (vertices if name == "vertex" else faces).append(row)
    assert offset == len(data)
    return vertices, faces


def srgb_to_linear(c):
    s = c / 255.0
    return s / 12.92 if s <= 0.04045 else ((s + 0.055) / 1.055) ** 2.4


def compare(glb, ply, colours):
    attributes, triangles = read_glb(glb)
    vertices, faces = read_ply(ply)
    assert len(triangles) == len(faces), f"{len(triangles)} triangles against {len(faces)} faces"
    for name in ("_ELEMENT", "_SOURCE") + (("COLOR_0",) if colours else ()):
        assert name in attributes, f"{glb}: no {name}"
    worst = 0.0
    for t, f in zip(triangles, faces):
        for corner, v in zip(t, f["vertex_indices"]):
            p, q = attributes["POSITION"][corner], vertices[v]
            worst = max(worst, abs(p[0] - q["x"]), abs(p[1] - q["y"]), abs(p[2] - q["z"]))
            assert attributes["_ELEMENT"][corner][0] == f["element"], "element differs"
            assert attributes["_SOURCE"][corner][0] == f["source"], "source differs"
            if colours:
                for k, key in enumerate(("red", "green", "blue")):
                    assert abs(attributes["COLOR_0"][corner][k] - srgb_to_linear(q[key])) < 1e-6
    scale = max(max(abs(v["x"]), abs(v["y"]), abs(v["z"])) for v in vertices)
    assert worst <= 1e-6 * scale, f"positions differ by {worst}"
    elements = {attributes["_ELEMENT"][t[0]][0] for t in triangles}
    return len(triangles), len(elements)


def run(*args):
    done = subprocess.run(list(args), capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"{' '.join(args)} failed ({done.returncode}): {done.stderr.strip()}")


def main():
    meshquilt, scratch = sys.argv[1], sys.argv[2]
    os.makedirs(scratch, exist_ok=True)
    ply = os.path.join(scratch, "plane.ply")
    run(meshquilt, "synth", "--plane", "1.5x1.5", "--backend", "cpu", "--progress", "none", "-o", ply)
    glb = os.path.join(scratch, "plane.glb")
    run(meshquilt, "synth", "--plane", "1.5x1.5", "--backend", "cpu", "--progress", "none", "-o", glb)
    faces, elements = compare(glb, ply, colours=False)
    # edit: recoloured by source and aged, both formats from one input.
    for ext in ("ply", "glb"):
        run(meshquilt, "edit", ply, "-o", os.path.join(scratch, f"edited.{ext}"), "--age", "0.2", "--seed", "5",
            "--color-by", "source", "--palette", "ff0000,00ff80,2040c0")
    edited_faces, edited_elements = compare(os.path.join(scratch, "edited.glb"), os.path.join(scratch, "edited.ply"),
                                            colours=True)
    assert edited_elements == round(0.8 * elements), (edited_elements, elements)
    assert edited_faces < faces
    print(f"glb: {faces} faces, {elements} elements; edited {edited_faces} faces, {edited_elements} elements")


if __name__ == "__main__":
    main()
