"""Our .glb files through Blender's own glTF importer, headless:
    blender -b --factory-startup --python-exit-code 1 --python test_gltf_import.py -- MESHQUILT WORK_DIR DATA_DIR
A synthesized chain mail, the same aged and recoloured by `edit`, and the frames `animate` writes
for a swaying vine, and a sphere painted with its colours baked into a texture (`paint --atlas`)
are imported; each must come in with the counts meshquilt reported, the
recoloured one with its colours (one per face), the frames with the same counts and moving
vertices. Blender 3.4's importer keeps no custom attributes, so `_ELEMENT` and `_SOURCE` are
reported, not required (the independent reader in tests/cli checks them)."""
import json
import subprocess
import sys
from pathlib import Path

import numpy

# Debian's Blender 3.4 importer still names numpy.bool, which newer numpy removed.
if not hasattr(numpy, "bool"):
    numpy.bool = bool

import bpy  # noqa: E402

meshquilt, work, data = sys.argv[sys.argv.index("--") + 1:][:3]
work, data = Path(work), Path(data)
work.mkdir(parents=True, exist_ok=True)


def check(condition, what):
    if not condition:
        raise AssertionError(what)
    print("ok:", what)


def cli(*args):
    done = subprocess.run([meshquilt, *map(str, args)], capture_output=True, text=True)
    if done.returncode != 0:
        raise AssertionError("meshquilt %s: exit %d\n%s" % (" ".join(map(str, args)), done.returncode, done.stderr))


def imported(path):
    """The one mesh object Blender's importer makes of `path`, in an empty scene."""
    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.ops.import_scene.gltf(filepath=str(path))
    meshes = [o for o in bpy.data.objects if o.type == "MESH"]
    check(len(meshes) == 1, "%s imports as one mesh object" % path.name)
    return meshes[0].data


def positions(mesh):
    flat = numpy.zeros(3 * len(mesh.vertices))
    mesh.vertices.foreach_get("co", flat)
    return flat.reshape(-1, 3)


# A synthesized chain mail.
cli("swatch", "chainmail", "--preset", "small", "-o", work / "mail.ply")
cli("synth", "--swatch", work / "mail.ply", "--plane", "1x1", "--progress", "none", "--backend", "cpu",
    "-o", work / "out.glb", "--stats", work / "out.json")
stats = json.loads((work / "out.json").read_text())
mesh = imported(work / "out.glb")
check(len(mesh.polygons) == stats["faces"] and len(mesh.vertices) == stats["vertices"],
      "synth's .glb: %d faces and %d vertices, as synth reported" % (len(mesh.polygons), len(mesh.vertices)))
names = {a.name for a in mesh.attributes}
print("custom attributes kept by this Blender's importer:", sorted(n for n in names if n.startswith("_")) or "none")

# Aged and recoloured by source.
cli("synth", "--swatch", work / "mail.ply", "--plane", "1x1", "--progress", "none", "--backend", "cpu",
    "-o", work / "out.ply")
cli("edit", work / "out.ply", "-o", work / "aged.glb", "--age", 0.2, "--seed", 3, "--color-by", "source",
    "--stats", work / "aged.json")
aged_stats = json.loads((work / "aged.json").read_text())
aged = imported(work / "aged.glb")
kept_share = aged_stats["kept"] / aged_stats["elements"]
check(len(aged.polygons) == round(stats["faces"] * kept_share),
      "edit's .glb: %d faces, the kept %d of %d elements" % (len(aged.polygons), aged_stats["kept"], aged_stats["elements"]))
check(len(aged.color_attributes) == 1, "its vertex colours come in as a colour attribute")
colours = aged.color_attributes[0]
loop_colours = numpy.zeros(4 * len(colours.data))
colours.data.foreach_get("color", loop_colours)
loop_colours = loop_colours.reshape(-1, 4)
if colours.domain == "CORNER":
    per_face = [loop_colours[p.loop_start:p.loop_start + p.loop_total] for p in aged.polygons]
else:
    per_face = [loop_colours[list(p.vertices)] for p in aged.polygons]
check(all(numpy.ptp(c, axis=0).max() < 1e-6 for c in per_face), "every face has one colour")
check(len({tuple(numpy.round(c[0], 4)) for c in per_face}) > 1, "the sources have different colours")

# Colour painted over the sphere and baked into a texture over its charts.
cli("paint", "--base", data / "sphere.off", "--image", data / "bricks.ppm", "--scale", 0.3, "--atlas", 128,
    "--backend", "cpu", "-o", work / "painted.glb", "--stats", work / "painted.json")
painted_stats = json.loads((work / "painted.json").read_text())
painted = imported(work / "painted.glb")
check(len(painted.polygons) == painted_stats["atlas"]["faces"],
      "paint --atlas's .glb: the base's %d faces" % len(painted.polygons))
check(len(painted.uv_layers) == 1, "its texture coordinates come in as a UV map")
uv = numpy.zeros(2 * len(painted.uv_layers[0].data))
painted.uv_layers[0].data.foreach_get("uv", uv)
check(uv.min() >= 0.0 and uv.max() <= 1.0 and numpy.ptp(uv) > 0.5, "the UVs spread over the unit square")
images = [n.image for m in painted.materials for n in m.node_tree.nodes if n.type == "TEX_IMAGE" and n.image]
check(len(images) == 1 and tuple(images[0].size) == (128, 128), "its material shows the 128 x 128 texture")
pixels = numpy.array(images[0].pixels[:]).reshape(-1, 4)
check(numpy.ptp(pixels[:, 0]) > 0.3, "the texture holds the bricks, not one colour")


cli("swatch", "vine", "--preset", "small", "--frames", 3, "-o", work / "vine.ply")
cli("synth", "--swatch", work / "vine.ply", "--plane", "1x1", "--progress", "none", "--backend", "cpu",
    "--provenance", "-o", work / "vine_out.ply")
cli("animate", "--quilt", work / "vine_out.ply", "--swatch-frames", work / "vine_frames", "--swatch", work / "vine.ply",
    "--format", "glb", "-o", work / "vine_anim")
frames = sorted((work / "vine_anim").glob("frame_*.glb"))
check(len(frames) == 3, "animate wrote 3 .glb frames")
counts = set()
for f in frames:
    frame = imported(f)  # the scene is emptied for each, so counts are taken at once
    counts.add((len(frame.vertices), len(frame.polygons)))
check(len(counts) == 1, "every frame imports with the same counts %s" % counts)
first, second = (positions(imported(f)) for f in frames[:2])
check(numpy.abs(first - second).max() > 1e-3, "the vine moves from frame to frame")
