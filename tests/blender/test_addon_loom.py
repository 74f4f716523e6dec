"""The add-on's loom in real Blender, headless:
    blender -b --factory-startup --python-exit-code 1 --python test_addon_loom.py -- MODULE_FOLDER SOURCE
A design image made in Blender, woven from a collection of two exemplar objects and from the
built-in exemplars: each Weave adds one fabric object, selected and active, with the faces the
module gives for the same inputs, one closed yarn per warp and weft, and is one undo step."""
import os
import sys

import addon_utils
import bpy
import numpy as np

module_folder, source = sys.argv[sys.argv.index("--") + 1:][:2]
sys.path.insert(0, os.path.join(source, "blender"))


def check(condition, what):
    if not condition:
        raise AssertionError(what)
    print("ok:", what)


addon_utils.enable("meshquilt_blender", default_set=True)
import meshquilt_blender  # noqa: E402

bpy.context.preferences.addons["meshquilt_blender"].preferences.module_path = module_folder
meshquilt = meshquilt_blender.job.import_module(module_folder)
check("UNDO" in meshquilt_blender.MESHQUILT_OT_loom.bl_options, "Weave registers an undo step")
for obj in list(bpy.data.objects):
    bpy.data.objects.remove(obj)

# A 10 x 12 design: plain on the left, twill 2/2 on the right; dark where the warp lies over.
rows, columns = 10, 12
r, c = np.meshgrid(np.arange(rows), np.arange(columns), indexing="ij")
warp_over = np.where(c < 6, (c + r) % 2 == 0, (c + r) % 4 < 2)
image = bpy.data.images.new("design", columns, rows)
pixels = np.ones((rows, columns, 4))
pixels[..., :3] = np.where(warp_over, 0.0, 1.0)[..., None]
image.pixels.foreach_set(pixels[::-1].astype(np.float32).ravel())  # Blender keeps the bottom row first

exemplars = bpy.data.collections.new("exemplars")
bpy.context.scene.collection.children.link(exemplars)
for name, pattern, n in (("plain", "plain", 6), ("twill", "twill:2/2", 8)):
    weave = meshquilt.swatch("weave", pattern=pattern, warps=n, wefts=n)
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata(weave.vertices.tolist(), [], weave.faces.tolist())
    exemplars.objects.link(bpy.data.objects.new(name, mesh))

settings = bpy.context.scene.meshquilt
settings.loom_design, settings.loom_exemplars, settings.loom_sides, settings.loom_stations = image, exemplars, 6, 4
bpy.ops.ed.undo_push(message="before")
before = set(bpy.data.objects.keys())
# As a button press runs it: with its undo step (a script's call pushes none unless asked).
check(bpy.ops.meshquilt.loom("EXEC_DEFAULT", True) == {"FINISHED"}, "Weave finishes")
added = [bpy.data.objects[name] for name in set(bpy.data.objects.keys()) - before]
check(len(added) == 1, "one object added")
fabric = added[0]
check(fabric.select_get() and bpy.context.view_layer.objects.active == fabric, "the fabric is selected and active")
want = meshquilt.loom(warp_over, [meshquilt.swatch("weave", pattern=p, warps=n, wefts=n)
                                  for p, n in (("plain", 6), ("twill:2/2", 8))], stations=4, sides=6)
check(len(fabric.data.polygons) == len(want.faces), "the module's faces (%d)" % len(want.faces))
element = np.empty(len(fabric.data.polygons), dtype=np.int32)
fabric.data.attributes["element"].data.foreach_get("value", element)
check(np.array_equal(element, want.element), "each face keeps its yarn")
check(len(np.unique(element)) == rows + columns, "one yarn per warp and weft")

bpy.ops.ed.undo()
check(set(bpy.data.objects.keys()) == before, "one undo removes the fabric")

settings = bpy.context.scene.meshquilt  # undo reloads the data
settings.loom_exemplars = None
check(bpy.ops.meshquilt.loom() == {"FINISHED"}, "Weave with the built-in exemplars")
settings.loom_design = None
count = len(bpy.data.objects)
try:
    bpy.ops.meshquilt.loom()
    message = ""
except RuntimeError as error:  # a script sees the operator's error report as an exception
    message = str(error)
check("choose a design image" in message and len(bpy.data.objects) == count, "no design: a message, nothing added")
print("all loom checks passed")
