"""The Python module against the command line: the same seed gives the same vertices and faces
(read from the CLI's PLY by a parser written here), progress and cancel, errors as exceptions,
numpy dtypes and shapes. Run by ctest with PYTHONPATH at build/python and MESHQUILT_CLI set."""
import os
import json
import math
import struct
import subprocess
import tempfile
import threading
import time

import numpy as np
import pytest

import meshquilt

CLI = os.environ["MESHQUILT_CLI"]
SOURCE = os.environ["MESHQUILT_SOURCE_DIR"]


def read_ply(path):
    data = open(path, "rb").read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode().split("\n")
    assert header[1] == "format binary_little_endian 1.0"
    elements, current = [], None
    for line in header:
        words = line.split()
        if words and words[0] == "element":
            current = [words[1], int(words[2]), []]
            elements.append(current)
        elif words and words[0] == "property":
            current[2].append(words[1:])
    codes = {"double": "d", "float": "f", "int": "i", "uchar": "B"}
    offset, out = end, {}
    for name, count, properties in elements:
        rows = []
        for _ in range(count):
            row = []
            for p in properties:
                if p[0] == "list":
                    n = data[offset]
                    offset += 1
                    row.append(struct.unpack_from("<%di" % n, data, offset))
                    offset += 4 * n
                else:
                    row.append(struct.unpack_from("<" + codes[p[0]], data, offset)[0])
                    offset += struct.calcsize(codes[p[0]])
            rows.append(row)
        out[name] = ([p[-1] for p in properties], rows)
    return out


def cli_synth(*args):
    with tempfile.TemporaryDirectory() as folder:
        path = os.path.join(folder, "out.ply")
        done = subprocess.run([CLI, "synth", "--progress", "none", "--backend", "cpu", *args, "-o", path],
                              capture_output=True, text=True)
        assert done.returncode == 0, done.stderr
        ply = read_ply(path)
    names, vertices = ply["vertex"]
    fnames, faces = ply["face"]
    v = np.array([row[:3] for row in vertices], dtype=np.float64)
    f = np.array([row[0] for row in faces], dtype=np.int32)
    element = np.array([row[fnames.index("element")] for row in faces], dtype=np.int32)
    source = np.array([row[fnames.index("source")] for row in faces], dtype=np.int32)
    return v, f, element, source


def read_off(path):
    words = open(path).read().split()
    assert words[0] == "OFF"
    nv, nf = int(words[1]), int(words[2])
    v = np.array(words[4:4 + 3 * nv], dtype=np.float64).reshape(nv, 3)
    f = np.array(words[4 + 3 * nv:4 + 3 * nv + 4 * nf], dtype=np.int32).reshape(nf, 4)[:, 1:]
    return v, f


def test_a_plane_equals_the_command_line():
    result = meshquilt.synth(plane=(2, 2), seed=1, backend="cpu")
    v, f, element, source = cli_synth("--plane", "2x2", "--seed", "1")
    assert result.vertices.dtype == np.float64 and result.vertices.shape == v.shape
    assert result.faces.dtype == np.int32 and result.faces.shape == f.shape
    assert np.array_equal(result.vertices, v)
    assert np.array_equal(result.faces, f)
    assert np.array_equal(result.element, element)
    assert np.array_equal(result.source, source)
    assert result.stats["faces"] == len(f)


def test_a_base_and_a_swatch_equal_the_command_line():
    base = read_off(os.path.join(SOURCE, "data", "sphere.off"))
    mail = meshquilt.swatch("chainmail", preset="small")
    with tempfile.TemporaryDirectory() as folder:
        swatch_path = os.path.join(folder, "mail.ply")
        subprocess.run([CLI, "swatch", "chainmail", "--preset", "small", "-o", swatch_path], check=True,
                       capture_output=True)
        result = meshquilt.synth(mail, base=base, scale=0.3, seed=3, backend="cpu", keep_texture=True)
        texture_path = os.path.join(folder, "t.mqt")
        v, f, element, source = cli_synth("--swatch", swatch_path, "--base", os.path.join(SOURCE, "data", "sphere.off"),
                                          "--scale", "0.3", "--seed", "3", "--write-texture", texture_path)
        assert result.texture == open(texture_path, "rb").read()
    assert np.array_equal(result.vertices, v)
    assert np.array_equal(result.faces, f)
    assert np.array_equal(result.element, element)


def cli_stats(*args):
    with tempfile.TemporaryDirectory() as folder:
        stats = os.path.join(folder, "stats.json")
        done = subprocess.run([CLI, "synth", "--progress", "none", "--backend", "cpu", *args, "--stats", stats, "-o",
                               os.path.join(folder, "out.ply")], capture_output=True, text=True)
        assert done.returncode == 0, done.stderr
        return json.load(open(stats))


def key_paths(tree, prefix=""):
    paths = set()
    for key, value in tree.items():
        paths.add(prefix + key)
        if isinstance(value, dict):
            paths |= key_paths(value, prefix + key + ".")
    return paths


def test_synth_stats_have_the_command_lines_keys_and_values():
    plane = meshquilt.synth(plane=(2, 2), seed=1, backend="cpu").stats
    cli_plane = cli_stats("--plane", "2x2", "--seed", "1")
    assert key_paths(plane) == key_paths(cli_plane)
    base = read_off(os.path.join(SOURCE, "data", "sphere.off"))
    curved = meshquilt.synth(base=base, scale=0.5, seed=2, backend="cpu").stats
    cli_curved = cli_stats("--base", os.path.join(SOURCE, "data", "sphere.off"), "--scale", "0.5", "--seed", "2")
    assert key_paths(curved) == key_paths(cli_curved)
    for stats, cli in ((plane, cli_plane), (curved, cli_curved)):
        for key in ("faces", "vertices", "elements", "patches", "stitched_pairs", "lattice_copies", "holes"):
            assert stats[key] == cli[key], key


def test_a_swatch_and_base_wound_inward_are_repaired_as_the_command_line_repairs_them():
    base = read_off(os.path.join(SOURCE, "data", "sphere.off"))
    mail = meshquilt.swatch("chainmail", preset="small")
    inward_base = (base[0], base[1][:, ::-1].copy())
    inward_mail = (mail.vertices, mail.faces[:, ::-1].copy())
    result = meshquilt.synth(inward_mail, base=inward_base, scale=0.3, seed=3, backend="cpu")
    clean = meshquilt.synth(mail, base=base, scale=0.3, seed=3, backend="cpu")
    repairs = result.stats["repairs"]
    assert repairs["swatch"]["rewound_faces"] == len(mail.faces)
    assert repairs["base"]["rewound_faces"] == len(base[1])
    assert all(count == 0 for count in clean.stats["repairs"]["swatch"].values())
    assert result.stats["faces"] > 0 and abs(result.stats["faces"] - clean.stats["faces"]) <= 0.2 * clean.stats["faces"]


def test_a_drawn_field_equals_the_command_lines_field_file():
    base = read_off(os.path.join(SOURCE, "data", "sphere.off"))
    points = np.array([[0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, -1.0, 0.0]])
    directions = np.array([[1.0, 1.0, 0.0], [0.0, 0.0, 1.0], [1.0, 0.0, 1.0]])
    result = meshquilt.synth(base=base, scale=0.3, seed=2, backend="cpu", field=(points, directions))
    with tempfile.TemporaryDirectory() as folder:
        field_path = os.path.join(folder, "field.json")
        with open(field_path, "w") as out:
            json.dump({"directions": [{"point": p.tolist(), "direction": d.tolist()} for p, d in zip(points, directions)]},
                      out)
        v, f, element, _ = cli_synth("--base", os.path.join(SOURCE, "data", "sphere.off"), "--scale", "0.3", "--seed", "2",
                                     "--field", field_path)
    assert np.array_equal(result.vertices, v)
    assert np.array_equal(result.faces, f)
    assert result.stats["faces"] == len(f)
    # Without the field the job is another one.
    assert not np.array_equal(meshquilt.synth(base=base, scale=0.3, seed=2, backend="cpu").vertices, v)


def test_paint_equals_the_command_line():
    base = read_off(os.path.join(SOURCE, "data", "sphere.off"))
    rng = np.random.default_rng(4)
    pixels = rng.integers(0, 256, size=(10, 12, 3), dtype=np.uint8)
    result = meshquilt.paint(base, pixels / 255.0, scale=0.5, coherence=0.5, seed=3, backend="cpu")
    with tempfile.TemporaryDirectory() as folder:
        image_path, out_path = os.path.join(folder, "sample.ppm"), os.path.join(folder, "out.ply")
        with open(image_path, "wb") as out:
            out.write(b"P6\n12 10\n255\n" + pixels.tobytes())
        stats_path = os.path.join(folder, "stats.json")
        done = subprocess.run([CLI, "paint", "--base", os.path.join(SOURCE, "data", "sphere.off"), "--image", image_path,
                               "--scale", "0.5", "--coherence", "0.5", "--seed", "3", "--backend", "cpu", "--progress",
                               "none", "-o", out_path, "--stats", stats_path],
                              capture_output=True, text=True)
        assert done.returncode == 0, done.stderr
        ply = read_ply(out_path)
        cli_stats_of_paint = json.load(open(stats_path))
    assert key_paths(result.stats) == key_paths(cli_stats_of_paint)
    assert all(result.stats[k] == cli_stats_of_paint[k] for k in ("vertices", "faces", "levels", "visits", "sample"))
    names, vertices = ply["vertex"]
    v = np.array([row[:3] for row in vertices], dtype=np.float64)
    colours = np.array([[row[names.index(c)] for c in ("red", "green", "blue")] for row in vertices], dtype=np.uint8)
    assert result.colors.dtype == np.uint8 and result.colors.shape == (len(v), 3)
    assert np.array_equal(result.vertices, v)
    assert np.array_equal(result.colors, colours)
    assert len(np.unique(result.colors, axis=0)) > 20
    assert result.stats["vertices"] == len(v) and result.stats["levels"] > 0
    with pytest.raises(meshquilt.Error, match="image"):
        meshquilt.paint(base, pixels, scale=0.5)  # bytes, not colours in [0, 1]
    # Shrunk to 6 pixels across (5 down): half the pixels per unit for the same scale.
    shrunk = meshquilt.paint(base, pixels / 255.0, scale=0.5, sample_width=6, backend="cpu")
    assert shrunk.stats["pixels_per_unit"] == pytest.approx(0.5 * result.stats["pixels_per_unit"])
    with pytest.raises(meshquilt.Error, match="sample_width|sample-width"):
        meshquilt.paint(base, pixels / 255.0, scale=0.5, sample_width=13)


def test_painted_colours_are_written_read_back_and_rendered_as_the_command_line_does():
    base = read_off(os.path.join(SOURCE, "data", "sphere.off"))
    pixels = np.random.default_rng(8).random((8, 8, 3))
    painted = meshquilt.paint(base, pixels, scale=0.5, seed=2, backend="cpu")
    with tempfile.TemporaryDirectory() as folder:
        ply = os.path.join(folder, "painted.ply")
        meshquilt.write(painted, ply)
        back = meshquilt.read(ply)
        assert np.array_equal(back.colors, painted.colors)
        assert np.allclose(back.vertices, painted.vertices)
        pictures = {}
        for up in ("y", "z"):
            mine, theirs = os.path.join(folder, "module_%s.png" % up), os.path.join(folder, "cli_%s.png" % up)
            meshquilt.render(painted, mine, width=160, height=120, mode="colors", view="front", up=up)
            done = subprocess.run([CLI, "render", ply, "--mode", "colors", "--view", "front", "--up", up, "--size",
                                   "160x120", "-o", theirs], capture_output=True, text=True)
            assert done.returncode == 0, done.stderr
            pictures[up] = open(mine, "rb").read()
            assert pictures[up] == open(theirs, "rb").read()
        assert pictures["y"] != pictures["z"]
        with pytest.raises(meshquilt.Error, match="colors"):
            meshquilt.write(meshquilt.Mesh(vertices=painted.vertices, faces=painted.faces,
                                           colors=painted.colors[:-1]), ply)
        with pytest.raises(meshquilt.Error, match="--up"):
            meshquilt.render(painted, os.path.join(folder, "x.png"), up="w")


def test_a_close_up_equals_the_command_lines():
    # Two tetrahedra far apart: a close-up of one draws it alone, byte for byte as the CLI does.
    tetra = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], float)
    faces = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]], np.int32)
    mesh = meshquilt.Mesh(vertices=np.vstack([tetra, tetra + [5, 0, 0]]), faces=np.vstack([faces, faces + 4]))
    with tempfile.TemporaryDirectory() as folder:
        ply = os.path.join(folder, "two.ply")
        meshquilt.write(mesh, ply)
        mine, theirs, whole = (os.path.join(folder, n) for n in ("mine.png", "theirs.png", "whole.png"))
        meshquilt.render(mesh, mine, width=120, height=90, around=(5.2, 0.2, 0.2), radius=1.5)
        done = subprocess.run([CLI, "render", ply, "--around", "5.2,0.2,0.2", "--radius", "1.5", "--size", "120x90",
                               "-o", theirs], capture_output=True, text=True)
        assert done.returncode == 0, done.stderr
        assert open(mine, "rb").read() == open(theirs, "rb").read()
        meshquilt.render(mesh, whole, width=120, height=90)
        assert open(mine, "rb").read() != open(whole, "rb").read()
        with pytest.raises(meshquilt.Error, match="no element"):
            meshquilt.render(mesh, os.path.join(folder, "x.png"), around=(20, 20, 20), radius=1.0)
        with pytest.raises(meshquilt.Error, match="around"):
            meshquilt.render(mesh, os.path.join(folder, "x.png"), around=(1, 2))


def cli_relief(*args, stats=None):
    with tempfile.TemporaryDirectory() as folder:
        out_path, stats_path = os.path.join(folder, "out.ply"), os.path.join(folder, "stats.json")
        done = subprocess.run([CLI, "relief", "--base", os.path.join(SOURCE, "data", "sphere.off"), "--backend", "cpu",
                               "--progress", "none", "-o", out_path, "--stats", stats_path]
                              + [a(folder) if callable(a) else a for a in args], capture_output=True, text=True)
        assert done.returncode == 0, done.stderr
        names, vertices = read_ply(out_path)["vertex"]
        if stats is not None:
            stats.update(json.load(open(stats_path)))
    return np.array([row[:3] for row in vertices], dtype=np.float64)


def test_relief_equals_the_command_line():
    base = read_off(os.path.join(SOURCE, "data", "sphere.off"))
    rng = np.random.default_rng(6)
    grey = rng.integers(0, 256, size=(10, 12), dtype=np.uint8)
    result = meshquilt.relief(base, grey / 255.0, height=0.05, scale=0.5, seed=3, backend="cpu")

    def write_pgm(folder):
        path = os.path.join(folder, "heights.pgm")
        with open(path, "wb") as out:
            out.write(b"P5\n12 10\n255\n" + grey.tobytes())
        return path

    v = cli_relief("--image", write_pgm, "--height", "0.05", "--scale", "0.5", "--seed", "3")
    assert np.array_equal(result.vertices, v)
    assert result.heights.shape == (len(v),) and result.heights.dtype == np.float64
    assert result.heights.min() >= 0.0 and result.heights.max() <= 0.05 + 1e-12
    assert result.heights.max() > 0.03  # raised, not left flat
    assert result.stats["height"] == 0.05 and result.stats["vertices"] == len(v)

    # A model with bumps of its own: its detail, at its own height, as `relief --from` takes it.
    mv, mf = base
    theta = np.arctan2(mv[:, 1], mv[:, 0])
    bumpy = mv * (1.0 + 0.04 * np.sin(6.0 * theta) * np.sin(5.0 * np.arccos(np.clip(mv[:, 2], -1, 1))))[:, None]

    def write_model(folder):
        path = os.path.join(folder, "bumpy.off")
        with open(path, "w") as out:
            out.write("OFF\n%d %d 0\n" % (len(bumpy), len(mf)))
            out.writelines("%.17g %.17g %.17g\n" % tuple(p) for p in bumpy)
            out.writelines("3 %d %d %d\n" % tuple(t) for t in mf)
        return path

    from_model = meshquilt.relief(base, model=(bumpy, mf), pixels=16, scale=0.5, seed=2, backend="cpu")
    cli_from_model = {}
    assert np.array_equal(from_model.vertices, cli_relief("--from", write_model, "--pixels", "16", "--scale", "0.5",
                                                          "--seed", "2", stats=cli_from_model))
    assert key_paths(from_model.stats) == key_paths(cli_from_model)
    assert from_model.stats["height"] == pytest.approx(cli_from_model["height"])
    taken = from_model.stats["from"]
    assert taken["detail_high"] > taken["detail_low"] and len(taken["region"]) == 4
    with pytest.raises(meshquilt.Error, match="one of"):
        meshquilt.relief(base, grey / 255.0, height=0.05, model=(bumpy, mf))
    with pytest.raises(meshquilt.Error, match="height"):
        meshquilt.relief(base, grey / 255.0)


def test_guidance_holds_a_drawn_direction_and_is_tangent():
    vertices, faces = read_off(os.path.join(SOURCE, "data", "sphere.off"))
    top = int(np.argmax(vertices[:, 2]))
    centres, directions = meshquilt.guidance((vertices, faces), field=([vertices[top]], [[1.0, 0.0, 0.0]]))
    assert centres.shape == (len(faces), 3) and directions.shape == (len(faces), 3)
    assert np.allclose(np.linalg.norm(directions, axis=1), 1.0)
    # Tangent: across the sphere's faces the field is normal to the face.
    a, b, c = (vertices[faces[:, k]] for k in range(3))
    normals = np.cross(b - a, c - a)
    normals /= np.linalg.norm(normals, axis=1)[:, None]
    assert np.abs(np.sum(normals * directions, axis=1)).max() < 1e-6
    # The faces round the top vertex run along x, as drawn there.
    around = np.any(faces == top, axis=1)
    assert np.abs(directions[around, 0]).min() > 0.9
    with pytest.raises(meshquilt.Error, match="direction 0: the direction is zero"):
        meshquilt.guidance((vertices, faces), field=([vertices[top]], [[0.0, 0.0, 0.0]]))
    with pytest.raises(meshquilt.Error, match="a field needs base"):
        meshquilt.synth(plane=(1, 1), field=([vertices[top]], [[1.0, 0.0, 0.0]]))
    with pytest.raises(meshquilt.Error, match="cone.spread"):
        meshquilt.synth(base=(vertices, faces), cone_spread=0.5)


def test_animate_equals_the_command_line_frame_for_frame():
    vine = meshquilt.swatch("vine", preset="small")
    frames = meshquilt.vine_frames(3, preset="small")
    result = meshquilt.synth(vine, plane=(1, 1), seed=1, backend="cpu")
    positions, dropped = meshquilt.animate(result, vine.vertices, frames)
    assert len(positions) == 3 and all(p.shape == result.vertices.shape for p in positions)
    kept_faces = ~np.isin(result.element, dropped)
    used = np.unique(result.faces[kept_faces])
    with tempfile.TemporaryDirectory() as folder:
        subprocess.run([CLI, "swatch", "vine", "--preset", "small", "--frames", "3", "-o",
                        os.path.join(folder, "vine.ply")], check=True, capture_output=True)
        # The command's swatch frames are the module's.
        for k, frame in enumerate(sorted(os.listdir(os.path.join(folder, "vine_frames")))):
            names, rows = read_ply(os.path.join(folder, "vine_frames", frame))["vertex"]
            assert np.array_equal(np.array([r[:3] for r in rows]), frames[k])
        v, f, _, _ = cli_synth("--swatch", os.path.join(folder, "vine.ply"), "--plane", "1x1", "--seed", "1",
                               "--provenance")
        assert np.array_equal(v, result.vertices)
        quilt = os.path.join(folder, "quilt.ply")
        subprocess.run([CLI, "synth", "--progress", "none", "--backend", "cpu", "--swatch",
                        os.path.join(folder, "vine.ply"), "--plane", "1x1", "--seed", "1", "--provenance", "-o", quilt],
                       check=True, capture_output=True)
        stats = os.path.join(folder, "animate.json")
        subprocess.run([CLI, "animate", "--quilt", quilt, "--swatch-frames", os.path.join(folder, "vine_frames"),
                        "--swatch", os.path.join(folder, "vine.ply"), "-o", os.path.join(folder, "out"),
                        "--stats", stats], check=True, capture_output=True)
        animation = meshquilt.animate(result, vine.vertices, frames)
        with open(stats) as f:
            cli_stats = json.load(f)
        assert set(animation.stats) == set(cli_stats)
        for key in ("frames", "elements", "dropped_meeting", "meeting_face_pairs"):
            assert animation.stats[key] == cli_stats[key], key
        for k in range(3):
            names, rows = read_ply(os.path.join(folder, "out", "frame_%04d.ply" % k))["vertex"]
            assert np.array_equal(np.array([r[:3] for r in rows]), positions[k][used])
    # A still swatch moves nothing.
    still, _ = meshquilt.animate(result, vine.vertices, [vine.vertices], keep_all=True)
    assert np.array_equal(still[0], result.vertices)
    with pytest.raises(meshquilt.Error, match="swatch frame 0: 3 vertices, not the swatch.s 200"):
        meshquilt.animate(result, vine.vertices, [vine.vertices[:3]])


def test_progress_rises_to_the_whole_and_cancel_stops_the_job():
    shares = []
    meshquilt.synth(plane=(2, 2), backend="cpu", fill_margin=0,
                    progress=lambda share, left: shares.append((share, left)))
    assert len(shares) > 3
    assert all(b[0] >= a[0] for a, b in zip(shares, shares[1:]))
    assert shares[-1][0] == pytest.approx(1.0)
    assert shares[-1][1] == pytest.approx(0.0, abs=1e-6)
    token = meshquilt.CancelToken()

    def stop_early(share, left):
        if share > 0.2:
            token.cancel()

    with pytest.raises(meshquilt.Cancelled):
        meshquilt.synth(plane=(3, 3), backend="cpu", progress=stop_early, cancel=token)

    def fail(share, left):
        raise KeyError("from the callback")

    with pytest.raises(KeyError):
        meshquilt.synth(plane=(2, 2), backend="cpu", progress=fail)


def test_paint_and_relief_report_progress_and_stop_when_cancelled():
    base = read_off(os.path.join(SOURCE, "data", "sphere.off"))
    pixels = np.random.default_rng(6).random((16, 16, 3))
    shares = []
    meshquilt.paint(base, pixels, scale=0.5, backend="cpu", progress=lambda share, left: shares.append((share, left)))
    assert len(shares) > 3
    assert all(b[0] >= a[0] for a, b in zip(shares, shares[1:]))
    assert shares[-1][0] == pytest.approx(1.0)
    token = meshquilt.CancelToken()
    seen = []

    def stop_early(share, left):
        seen.append(share)
        if share > 0.2:
            token.cancel()

    with pytest.raises(meshquilt.Cancelled):
        meshquilt.relief(base, pixels[:, :, 0], height=0.02, scale=0.5, backend="cpu", progress=stop_early,
                         cancel=token)
    assert seen[-1] < 1.0  # stopped before the end

    def fail(share, left):
        raise KeyError("from the callback")

    with pytest.raises(KeyError):
        meshquilt.paint(base, pixels, scale=0.5, backend="cpu", progress=fail)


def test_the_engine_runs_without_the_gil():
    ticks = []
    done = threading.Event()

    def job():
        meshquilt.synth(plane=(3, 3), backend="cpu")
        done.set()

    worker = threading.Thread(target=job)
    worker.start()
    while not done.is_set():
        ticks.append(time.monotonic())
        time.sleep(0.01)
    worker.join()
    assert len(ticks) > 10


def read_mesh_ply(path):
    ply = read_ply(path)
    v = np.array([row[:3] for row in ply["vertex"][1]], dtype=np.float64)
    f = np.array([row[0] for row in ply["face"][1]], dtype=np.int32)
    return v, f


@pytest.mark.parametrize("kind", [k["name"] for k in meshquilt.swatch_kinds()])
def test_every_registered_swatch_kind_equals_the_command_line(kind, tmp_path):
    info = next(k for k in meshquilt.swatch_kinds() if k["name"] == kind)
    assert info["options"] and set(info["defaults"]) <= {o["name"] for o in info["options"]}
    # The small preset with one integer option moved off its default, as both fronts take it.
    integer = next(o["name"] for o in info["options"] if o["type"] == "integer")
    value = int(info["small_defaults"][integer]) + (1 if integer != "rows" else 2)
    path = str(tmp_path / "s.ply")
    done = subprocess.run([CLI, "swatch", kind, "--preset", "small", "--seed", "3",
                           "--" + integer.replace("_", "-"), str(value), "-o", path], capture_output=True, text=True)
    made = None
    try:
        made = meshquilt.swatch(kind, preset="small", seed=3, **{integer: value})
    except meshquilt.Error as error:
        assert done.returncode == 6 and str(error).split(":")[-1] in done.stderr, (error, done.stderr)
        return
    assert done.returncode == 0, done.stderr
    v, f = read_mesh_ply(path)
    assert np.array_equal(made.faces, f)
    assert np.allclose(made.vertices, v, atol=1e-6)
    with pytest.raises(meshquilt.Error, match="whole number"):
        meshquilt.swatch(kind, preset="small", **{integer: value + 0.5})


def test_errors_carry_the_command_lines_message():
    with pytest.raises(meshquilt.Error, match="--plane"):
        meshquilt.synth(plane=(0, 2))
    with pytest.raises(meshquilt.Error, match=r"\(N, 3\)"):
        meshquilt.synth(base=(np.zeros((4, 2)), np.zeros((1, 3))))
    with pytest.raises(meshquilt.Error, match="index"):
        meshquilt.synth(base=(np.zeros((3, 3)), np.array([[0, 1, 7]])))
    with pytest.raises(meshquilt.Error, match="unknown option 'colour'"):
        meshquilt.swatch("chainmail", colour=3)
    with pytest.raises(TypeError):
        meshquilt.synth()


def test_edit_ages_and_keeps_the_rest():
    result = meshquilt.synth(plane=(2, 2), backend="cpu")
    kept = meshquilt.edit(result, age=0.1, seed=3)
    before, after = np.unique(result.element), np.unique(kept.element)
    assert len(before) - len(after) == math.floor(0.1 * len(before) + 0.5)  # halves away from zero
    assert set(after) <= set(before)
    report = meshquilt.inspect(kept)
    assert report["elements"] == len(after)
    assert report["closed_elements"] == len(after)


def test_edit_equals_the_command_line_with_its_stats(tmp_path):
    result = meshquilt.synth(plane=(2, 2), backend="cpu")
    path, out, stats = str(tmp_path / "r.ply"), str(tmp_path / "e.ply"), str(tmp_path / "e.json")
    meshquilt.write(result, path)
    lo, hi = result.vertices.min(axis=0), result.vertices.max(axis=0)
    box = list(lo) + list(lo + 0.3 * (hi - lo))
    sphere = list(hi) + [0.25 * float(np.linalg.norm(hi - lo))]
    subprocess.run([CLI, "edit", path, "-o", out, "--age", "0.05", "--seed", "4", "--remove-elements", "0-2",
                    "--remove-box", *map(repr, box), "--remove-sphere", *map(repr, sphere), "--color-by", "source",
                    "--stats", stats], check=True, capture_output=True)
    kept = meshquilt.edit(result, remove_elements=[0, 1, 2], remove_box=box, remove_sphere=sphere, age=0.05, seed=4,
                          color_by="source")
    with open(stats) as f:
        cli_stats = json.load(f)
    assert set(kept.stats) == set(cli_stats)
    for key in cli_stats:
        if key not in ("input", "output", "seconds"):
            assert kept.stats[key] == cli_stats[key], key
    assert cli_stats["removed_inside"] > 0 and cli_stats["removed_by_id"] == 3 and cli_stats["removed_aged"] > 0
    back = meshquilt.read(out)
    assert np.array_equal(back.vertices, kept.vertices) and np.array_equal(back.colors, kept.colors)
    with pytest.raises(meshquilt.Error, match="--remove-box: expected X0 Y0 Z0 X1 Y1 Z1, got 2 numbers"):
        meshquilt.edit(result, remove_box=[0, 1])
    with pytest.raises(meshquilt.Error, match="--color-by: expected element or source"):
        meshquilt.edit(result, color_by="face")


def test_write_then_read_gives_the_result_back(tmp_path):
    result = meshquilt.synth(plane=(1.5, 1.5), backend="cpu")
    meshquilt.write(result, str(tmp_path / "r.ply"))
    back = meshquilt.read(str(tmp_path / "r.ply"))
    assert np.array_equal(back.vertices, result.vertices)
    assert np.array_equal(back.faces, result.faces)
    assert np.array_equal(back.element, result.element)
    assert np.array_equal(back.source, result.source)
    meshquilt.write(result, str(tmp_path / "r.glb"))
    assert open(tmp_path / "r.glb", "rb").read(4) == b"glTF"
    with pytest.raises(meshquilt.Error, match="unknown mesh format"):
        meshquilt.write(result, str(tmp_path / "r.xyz"))
    with pytest.raises(meshquilt.Error, match="missing.ply"):
        meshquilt.read(str(tmp_path / "missing.ply"))


def test_embed_gives_the_result_back_and_follows_a_moved_base():
    base = read_off(os.path.join(SOURCE, "data", "sphere.off"))
    result = meshquilt.synth(meshquilt.swatch("chainmail", preset="small"), base=base, scale=0.4, backend="cpu",
                             keep_texture=True)
    same = meshquilt.embed(result.texture, base)
    assert np.array_equal(same.vertices, result.vertices) and np.array_equal(same.faces, result.faces)
    with tempfile.TemporaryDirectory() as folder:
        texture, stats = os.path.join(folder, "t.mqt"), os.path.join(folder, "e.json")
        with open(texture, "wb") as f:
            f.write(result.texture)
        subprocess.run([CLI, "embed", "--texture", texture, "--base", os.path.join(SOURCE, "data", "sphere.off"),
                        "-o", os.path.join(folder, "e.ply"), "--stats", stats], check=True, capture_output=True)
        with open(stats) as f:
            cli_stats = json.load(f)
    assert set(same.stats) == set(cli_stats)
    for key in ("faces", "vertices", "embed", "shell_reduced_vertices", "synthesis_map_elements"):
        assert same.stats[key] == cli_stats[key], key
    stretched = meshquilt.embed(result.texture, (base[0] * np.array([1.5, 1.0, 1.0]), base[1]))
    assert np.array_equal(stretched.faces, result.faces)
    assert stretched.vertices[:, 0].max() > 1.3 * result.vertices[:, 0].max()
    with pytest.raises(meshquilt.Error, match="base"):
        meshquilt.embed(result.texture, (base[0][:-1], base[1][:-1]))


def test_loom_equals_the_command_line(tmp_path):
    twill = meshquilt.swatch("weave", pattern="twill:2/2", warps=8, wefts=8)
    plain = meshquilt.swatch("weave", pattern="plain", warps=6, wefts=6)
    r, c = np.meshgrid(np.arange(10), np.arange(12), indexing="ij")
    warp_over = np.where(c < 6, (c + r) % 2 == 0, (c + r) % 4 < 2)
    result = meshquilt.loom(warp_over, [plain, twill], stations=4, sides=6)
    meshquilt.write(twill, str(tmp_path / "twill.ply"))
    meshquilt.write(plain, str(tmp_path / "plain.ply"))
    with open(tmp_path / "d.pbm", "w") as f:
        f.write("P1\n12 10\n" + "\n".join("".join("1" if v else "0" for v in row) for row in warp_over) + "\n")
    subprocess.run([CLI, "loom", "--design", str(tmp_path / "d.pbm"), "--exemplar", str(tmp_path / "plain.ply"),
                    "--exemplar", str(tmp_path / "twill.ply"), "--stations", "4", "--sides", "6", "-o",
                    str(tmp_path / "f.ply"), "--stats", str(tmp_path / "s.json"), "--progress", "none"], check=True,
                   capture_output=True)
    back = meshquilt.read(str(tmp_path / "f.ply"))
    assert np.array_equal(back.vertices, result.vertices) and np.array_equal(back.faces, result.faces)
    assert np.array_equal(back.element, result.element)
    with open(tmp_path / "s.json") as f:
        cli_stats = json.load(f)
    assert set(result.stats) == set(cli_stats)
    assert result.stats["loom"]["assignment"] == cli_stats["loom"]["assignment"]
    assert result.assignment.shape == (10, 12, 3)
    only = meshquilt.loom(warp_over, [plain, twill], assignment_only=True)
    assert np.array_equal(only.assignment, result.assignment) and len(only.faces) == 0
    with pytest.raises(meshquilt.Error, match="exemplar 0"):
        meshquilt.loom(warp_over, [meshquilt.swatch("chainmail", preset="small")])
