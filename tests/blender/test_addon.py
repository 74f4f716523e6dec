"""The add-on in real Blender, headless:
    blender -b --factory-startup --python-exit-code 1 --python test_addon.py -- MODULE_FOLDER SOURCE MESHQUILT
It enables the add-on, quilts the default cube with the small chain mail through the job object
and the Create operator, and through the executable where the module is missing, checks the new object against the module's own result, cancels a job
and finds the scene unchanged, follows the base after it is stretched, selects elements at random, follows the cube's shape-key animation as shape keys, follows a guide
curve drawn over the base and previews its field, plays the built-in vine's sway as shape keys,
adds each sample scene and weaves the sample torus along its guide, paints the cube from an image
and raises it as a relief (and cancels a paint job), and parses the extension manifest."""
import os
import sys
import tomllib

import addon_utils
import bpy
import numpy as np

module_folder, source, executable = sys.argv[sys.argv.index("--") + 1:][:3]
sys.path.insert(0, os.path.join(source, "blender"))


def check(condition, what):
    if not condition:
        raise AssertionError(what)
    print("ok:", what)


addon_utils.enable("meshquilt_blender", default_set=True)
check("meshquilt_blender" in bpy.context.preferences.addons, "the add-on is enabled")
import meshquilt_blender  # noqa: E402

bpy.context.preferences.addons["meshquilt_blender"].preferences.module_path = module_folder
meshquilt = meshquilt_blender.job.import_module(module_folder)
check(meshquilt is not None, "the module is found through the preference's folder")

cube = bpy.data.objects["Cube"]
bpy.context.view_layer.objects.active = cube
settings = bpy.context.scene.meshquilt
settings.swatch_kind, settings.small, settings.scale, settings.seed = "chainmail", True, 0.4, 2

# The job object gives the module's own result.
job = meshquilt_blender.make_job(bpy.context, cube).start()
check(job.wait(600) and job.error is None, "a job quilts the cube")
vertices, faces = meshquilt_blender.mesh_arrays(cube)
expected = meshquilt.synth(meshquilt.swatch("chainmail", preset="small"), base=(vertices, faces), scale=0.4, seed=2)
check(np.array_equal(job.result["faces"], expected.faces), "the job's faces are the module's")
job_texture = job.result["texture"]

# Without the module the job runs the executable and reads its PLY: the same faces.
fallback = meshquilt_blender.job.QuiltJob((vertices, faces), swatch_kind="chainmail", swatch_options={"preset": "small"},
                                         scale=0.4, seed=2, executable=executable)
fallback.module, fallback._token = None, None
check(fallback.start().wait(600) and fallback.error is None, "the executable quilts the cube: " + str(fallback.error))
check(np.array_equal(fallback.result["faces"], expected.faces) and np.array_equal(fallback.result["element"],
                                                                                  expected.element),
      "the executable's result is the module's")

# Create (run to the end without a window) adds one object with the attributes.
before = set(bpy.data.objects.keys())
check(bpy.ops.meshquilt.create() == {"FINISHED"}, "Create finishes")
added = [bpy.data.objects[name] for name in set(bpy.data.objects.keys()) - before]
check(len(added) == 1, "Create adds one object")
mesh = added[0].data
check(len(mesh.polygons) == len(expected.faces), "its face count is the result's")
element = np.empty(len(mesh.polygons), dtype=np.int32)
mesh.attributes["element"].data.foreach_get("value", element)
source_ids = np.empty(len(mesh.polygons), dtype=np.int32)
mesh.attributes["source"].data.foreach_get("value", source_ids)
check(np.array_equal(element, expected.element) and np.array_equal(source_ids, expected.source),
      "face attributes element and source are the result's")
check([m.name for m in mesh.materials] == ["meshquilt chainmail"], "the built-in mail wears its metal")

# A cancelled job leaves nothing: no result, no new object.
count = len(bpy.data.objects)
settings.scale = 0.15
job = meshquilt_blender.make_job(bpy.context, cube).start()
job.cancel()
check(job.wait(600) and job.cancelled and job.result is None, "a cancelled job ends with no result")
check(len(bpy.data.objects) == count, "the scene is unchanged")

# Selecting a share of the elements at random (the paper's aging, by deleting them).
bpy.context.view_layer.objects.active = added[0]
settings.select_share = 0.25
bpy.ops.meshquilt.select(mode="RANDOM")
selected = np.empty(len(mesh.polygons), dtype=bool)
mesh.polygons.foreach_get("select", selected)
chosen = np.unique(element[selected])
check(len(chosen) == round(0.25 * len(np.unique(element))), "a quarter of the elements are selected")
check(np.all(np.isin(element, chosen) == selected), "whole elements are selected")

# Follow the base: the cube stretched, the layer placed over it again without synthesizing.
quilt_obj = added[0]
for v in cube.data.vertices:
    v.co.x *= 1.3
bpy.context.view_layer.objects.active = quilt_obj
check(bpy.ops.meshquilt.follow_base() == {"FINISHED"}, "Follow the base finishes")
moved = np.empty(len(quilt_obj.data.vertices) * 3)
quilt_obj.data.vertices.foreach_get("co", moved)
stretched = meshquilt.embed(job_texture, meshquilt_blender.mesh_arrays(cube))
check(np.allclose(moved.reshape(-1, 3), stretched.vertices, atol=1e-5), "the layer follows the stretched cube")
check(not np.allclose(moved.reshape(-1, 3), expected.vertices, atol=1e-3), "and has moved with it")

# The cube animated by a shape key (stretched along x from frame 1 to 3): the layer follows it as
# shape keys, each frame the module's embed over the cube as it is then.
stretch_key = cube.shape_key_add(name="Basis"), cube.shape_key_add(name="stretch")
for v in stretch_key[1].data:
    v.co.x *= 1.3
for frame, value in ((1, 0.0), (3, 1.0)):
    stretch_key[1].value = value
    stretch_key[1].keyframe_insert("value", frame=frame)
bpy.context.scene.frame_start, bpy.context.scene.frame_end = 1, 3
bpy.context.scene.frame_set(1)
quilt_obj.data.vertices.foreach_set("co", expected.vertices.ravel())
bpy.context.view_layer.objects.active = quilt_obj
check(bpy.ops.meshquilt.follow_frames() == {"FINISHED"}, "Follow the base's animation finishes")
keys = quilt_obj.data.shape_keys.key_blocks
check([k.name for k in keys] == ["Basis", "frame_1", "frame_2", "frame_3"], "one shape key a frame")
for frame in (1, 2, 3):
    bpy.context.scene.frame_set(frame)
    at_frame = meshquilt.embed(job_texture, meshquilt_blender.mesh_arrays(cube, bpy.context.evaluated_depsgraph_get()))
    co = np.empty(3 * len(keys[frame].data))
    keys[frame].data.foreach_get("co", co)
    check(np.allclose(co.reshape(-1, 3), at_frame.vertices, atol=1e-5), "frame %d is embed over the cube then" % frame)
check(abs(keys["frame_3"].value - 1.0) < 1e-6 and abs(keys["frame_2"].value) < 1e-6, "scene frame 3 plays its key")
bpy.context.scene.frame_set(1)
bpy.context.view_layer.objects.active = cube
bpy.ops.object.shape_key_remove(all=True)

# A guide curve drawn across the cube's top, diagonally: its strokes land on the surface and
# orient the swatch; the job's result is the module's with that field, and the preview draws it.
for v in cube.data.vertices:
    v.co.x /= 1.3
bpy.context.view_layer.objects.active = cube
curve_data = bpy.data.curves.new("guide", type="CURVE")
spline = curve_data.splines.new("POLY")
spline.points.add(3)
for k, point in enumerate(spline.points):
    t = -0.8 + 1.6 * k / 3
    point.co = (t, t, 1.3, 1.0)
guide = bpy.data.objects.new("guide", curve_data)
bpy.context.collection.objects.link(guide)
settings.guide_object, settings.scale = guide, 0.4
bpy.context.view_layer.objects.active = cube
job = meshquilt_blender.make_job(bpy.context, cube)
points, directions = job.field
check(len(points) == 3 and np.allclose(points[:, 2], 1.0) and np.abs(points[:, :2]).max() < 1.0,
      "the guide's three segments land on the cube's top")
check(np.allclose(directions[:, 0], directions[:, 1]) and np.allclose(directions[:, 2], 0.0),
      "each runs along the curve")
check(job.start().wait(600) and job.error is None, "a guided job quilts the cube")
vertices, faces = meshquilt_blender.mesh_arrays(cube)
# The panel holds the scale as a float (0.4000000059604645): the module is given that one.
guided = meshquilt.synth(meshquilt.swatch("chainmail", preset="small"), base=(vertices, faces), scale=settings.scale, seed=2,
                         field=(points, directions))
check(np.array_equal(job.result["faces"], guided.faces) and np.allclose(job.result["vertices"], guided.vertices, atol=1e-5),
      "the guided job is the module's with that field")
check(not np.array_equal(guided.vertices, expected.vertices), "and another result than without it")
check(bpy.ops.meshquilt.preview_field() == {"FINISHED"}, "Preview field finishes")
preview = bpy.data.objects["Cube_field"].data
centres, field_directions = meshquilt.guidance((vertices, faces), field=(points, directions))
check(len(preview.edges) == len(centres) and len(preview.vertices) == 2 * len(centres), "one line per face")
top = centres[:, 2] > 0.99
# Held at the cube's nearest corners, so within about 18 degrees (the default field, along an axis,
# is 45 degrees off).
check(np.abs(field_directions[top] @ np.array([1.0, 1.0, 0.0]) / np.sqrt(2.0)).min() > 0.95,
      "on the top the field runs along the guide")
settings.guide_object = None

# The built-in vine quilted over the cube plays its sway as shape keys, keyed in turn.
settings.swatch_kind, settings.frames, settings.scale = "vine", 4, 0.4
bpy.context.view_layer.objects.active = cube
before = set(bpy.data.objects.keys())
check(bpy.ops.meshquilt.create() == {"FINISHED"}, "Create quilts the cube with the vine")
vine_obj = bpy.data.objects[(set(bpy.data.objects.keys()) - before).pop()]
check("origin" in vine_obj.data.attributes, "the result keeps each vertex's swatch vertex")

def stored(mesh):
    """The object's mesh as the operator reads it: single-precision positions, its own faces."""
    co = np.empty(3 * len(mesh.vertices))
    mesh.vertices.foreach_get("co", co)
    tris = np.empty(3 * len(mesh.polygons), dtype=np.int32)
    mesh.polygons.foreach_get("vertices", tris)
    ids = {name: np.empty(len(mesh.attributes[name].data), dtype=np.int32) for name in ("element", "origin")}
    for name, values in ids.items():
        mesh.attributes[name].data.foreach_get("value", values)
    return meshquilt.Mesh(co.reshape(-1, 3), tris.reshape(-1, 3), element=ids["element"], origin=ids["origin"])


as_stored = stored(vine_obj.data)
bpy.context.view_layer.objects.active = vine_obj
check(bpy.ops.meshquilt.animate() == {"FINISHED"}, "Animate finishes")
frames, dropped = meshquilt.animate(as_stored, meshquilt.swatch("vine", preset="small").vertices,
                                    meshquilt.vine_frames(4, preset="small"))
used = np.unique(as_stored.faces[~np.isin(as_stored.element, dropped)])
keys = vine_obj.data.shape_keys.key_blocks
check(len(keys) == 5 and len(vine_obj.data.vertices) == len(used),
      "a basis and 4 frames; %d elements that meet in some frame removed" % len(dropped))
for k in range(4):
    co = np.empty(3 * len(keys[k + 1].data))
    keys[k + 1].data.foreach_get("co", co)
    check(np.allclose(co.reshape(-1, 3), frames[k][used], atol=1e-6), "frame %d is the module's" % k)
bpy.context.scene.frame_set(3)
check(abs(keys["frame_2"].value - 1.0) < 1e-6 and abs(keys["frame_1"].value) < 1e-6, "scene frame 3 plays frame 2")

# Each sample scene adds its base, ready for Create; the woven torus with its guide circle.
for sample, kind in (("MAIL_SPHERE", "chainmail"), ("WEAVE_TORUS", "weave"), ("VINE_PLANE", "vine")):
    before = set(bpy.data.objects.keys())
    check(bpy.ops.meshquilt.sample_scene(sample=sample) == {"FINISHED"}, "sample %s is added" % sample)
    added = set(bpy.data.objects.keys()) - before
    base = bpy.context.active_object
    check(base.name in added and base.type == "MESH" and settings.swatch_kind == kind
          and bpy.ops.meshquilt.create.poll(), "its base is active and the panel set for %s" % kind)
check(settings.guide_object is None, "only the torus has a guide")
bpy.ops.meshquilt.sample_scene(sample="WEAVE_TORUS")
torus = bpy.context.active_object
points, directions = meshquilt_blender.guide_field(settings.guide_object, torus)
radial = points[:, :2] / np.linalg.norm(points[:, :2], axis=1)[:, None]
check(np.abs(np.sum(radial * directions[:, :2], axis=1) / np.linalg.norm(directions, axis=1)).max() < 0.2,
      "the torus's guide runs round its hole")
settings.small, settings.scale = True, 0.45
check(bpy.ops.meshquilt.create() == {"FINISHED"}, "Create weaves the torus along its guide")
settings.guide_object = None

# Paint from image: an image made here painted over the cube as the module paints it, then raised.
cube = bpy.data.objects["Cube"]
bpy.context.view_layer.objects.active = cube
rgb = np.random.default_rng(3).integers(0, 256, size=(12, 16, 3)) / 255.0  # row 0 at the top
image = bpy.data.images.new("meshquilt_sample", 16, 12)
rgba = np.ones((12, 16, 4))
rgba[..., :3] = rgb
image.pixels.foreach_set(rgba[::-1].ravel().astype(np.float32))  # Blender keeps the bottom row first
read_back = meshquilt_blender.image_array(image)
check(np.abs(read_back - rgb).max() < 1e-6, "the image is read with row 0 at the top")
settings.paint_image, settings.paint_scale, settings.seed, settings.relief_height = image, 0.5, 4, 0.0
check(settings.paint_pixels == 128, "images wider than 128 pixels are shrunk by default")
before = set(bpy.data.objects.keys())
check(bpy.ops.meshquilt.paint() == {"FINISHED"}, "Paint finishes")
painted = [bpy.data.objects[name] for name in set(bpy.data.objects.keys()) - before]
check(len(painted) == 1, "Paint adds one object")
expected = meshquilt.paint(meshquilt_blender.mesh_arrays(cube), read_back, scale=0.5, seed=4)
mesh = painted[0].data
co = np.empty(len(mesh.vertices) * 3)
mesh.vertices.foreach_get("co", co)
check(len(mesh.vertices) == len(expected.vertices) and np.allclose(co.reshape(-1, 3), expected.vertices, atol=1e-6),
      "the painted object has the module's vertices")
linear = np.empty(len(mesh.vertices) * 4)
mesh.color_attributes["meshquilt_colour"].data.foreach_get("color", linear)
linear = linear.reshape(-1, 4)[:, :3]
srgb = np.where(linear <= 0.0031308, 12.92 * linear, 1.055 * np.power(linear, 1 / 2.4) - 0.055)
check(np.abs(np.rint(255 * srgb) - expected.colors).max() <= 1 and len(np.unique(expected.colors, axis=0)) > 20,
      "its colour attribute holds the module's colours")
check(mesh.materials[0].node_tree.nodes["Color Attribute"].layer_name == "meshquilt_colour",
      "its material shows them")
settings.relief_height = 0.05
check(bpy.context.view_layer.objects.active.name.endswith("painted"), "the painted object is the active one")
bpy.context.view_layer.objects.active = cube
before = set(bpy.data.objects.keys())
check(bpy.ops.meshquilt.paint() == {"FINISHED"}, "Paint raises a relief")
raised = [bpy.data.objects[name] for name in set(bpy.data.objects.keys()) - before][0].data
expected = meshquilt.relief(meshquilt_blender.mesh_arrays(cube), read_back, height=0.05, scale=0.5, seed=4)
heights = np.empty(len(raised.vertices))
raised.attributes["meshquilt_height"].data.foreach_get("value", heights)
check(np.allclose(heights, expected.heights, atol=1e-6) and heights.max() > 0.03, "the relief has the module's heights")
settings.relief_height, settings.paint_pixels = 0.0, 8
bpy.context.view_layer.objects.active = cube
before = set(bpy.data.objects.keys())
check(bpy.ops.meshquilt.paint() == {"FINISHED"}, "Paint from the image shrunk to 8 pixels")
shrunk = [bpy.data.objects[name] for name in set(bpy.data.objects.keys()) - before][0].data
expected = meshquilt.paint(meshquilt_blender.mesh_arrays(cube), read_back, scale=0.5, seed=4, sample_width=8)
whole = meshquilt.paint(meshquilt_blender.mesh_arrays(cube), read_back, scale=0.5, seed=4)
check(len(shrunk.vertices) == len(expected.vertices) and len(expected.vertices) < len(whole.vertices),
      "the shrunk image is painted at its own pixels per unit")
settings.paint_pixels = 128
# A paint job cancelled from its progress ends with no result; one left alone reports its share.
job = meshquilt_blender.job.PaintJob(meshquilt, meshquilt_blender.mesh_arrays(cube), read_back, 0.5, 4)
job._progress = lambda share, left, job=job: (job.cancel() if share > 0.3 else None)
check(job.start().wait(600) and job.cancelled and job.result is None and job.error is None,
      "a cancelled paint job ends with no result")
job = meshquilt_blender.job.PaintJob(meshquilt, meshquilt_blender.mesh_arrays(cube), read_back, 0.5, 4)
check(job.start().wait(600) and job.error is None and job.share == 1.0 and len(job.result.vertices) > 0,
      "a paint job reports its progress to the end")
settings.paint_image = None
before = set(bpy.data.objects.keys())
try:
    bpy.ops.meshquilt.paint()
    refused = ""
except RuntimeError as e:  # an operator's ERROR report reaches a script as an exception
    refused = str(e)
check("choose an image" in refused and set(bpy.data.objects.keys()) == before,
      "Paint without an image reports it and changes nothing")

manifest = tomllib.load(open(os.path.join(source, "blender", "meshquilt_blender", "blender_manifest.toml"), "rb"))
check(manifest["type"] == "add-on" and manifest["id"] == "meshquilt", "the extension manifest parses")
print("blender add-on: all checks passed")
