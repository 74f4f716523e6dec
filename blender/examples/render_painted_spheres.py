"""Paints a UV sphere from data/bricks.ppm through the add-on's "Paint from image", raises the
same bricks as a relief on a second one, and renders both with Cycles on the CPU (the picture in
docs/blender.md):
    blender -b --factory-startup --python render_painted_spheres.py -- MODULE_FOLDER SOURCE OUT.png"""
import os
import sys

import addon_utils
import bpy
import numpy as np

module_folder, source, out = sys.argv[sys.argv.index("--") + 1:][:3]
sys.path.insert(0, os.path.join(source, "blender"))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cycles_still import render_still  # noqa: E402

addon_utils.enable("meshquilt_blender", default_set=True)
bpy.context.preferences.addons["meshquilt_blender"].preferences.module_path = module_folder


def read_ppm(path):
    """A binary PPM (P6, 8-bit) as height x width x 3 in [0, 1], row 0 at the top."""
    data = open(path, "rb").read()
    words, at = [], 0
    while len(words) < 4:
        while data[at:at + 1].isspace():
            at += 1
        end = at
        while not data[end:end + 1].isspace():
            end += 1
        words.append(data[at:end])
        at = end
    width, height = int(words[1]), int(words[2])
    return np.frombuffer(data, np.uint8, width * height * 3, at + 1).reshape(height, width, 3) / 255.0


bricks = read_ppm(os.path.join(source, "data", "bricks.ppm"))
image = bpy.data.images.new("bricks", bricks.shape[1], bricks.shape[0])
rgba = np.ones(bricks.shape[:2] + (4,))
rgba[..., :3] = bricks
image.pixels.foreach_set(rgba[::-1].ravel().astype(np.float32))  # Blender keeps the bottom row first

bpy.data.objects.remove(bpy.data.objects["Cube"])
settings = bpy.context.scene.meshquilt
settings.paint_image, settings.paint_scale, settings.seed = image, 0.3, 1
spheres = []
for x, height in ((-1.15, 0.0), (1.15, 0.04)):
    bpy.ops.mesh.primitive_uv_sphere_add(segments=48, ring_count=24, radius=1.0, location=(x, 0.0, 0.0))
    base = bpy.context.active_object
    settings.relief_height = height
    assert bpy.ops.meshquilt.paint() == {"FINISHED"}
    spheres.append(bpy.data.objects[base.name + ("_relief" if height > 0.0 else "_painted")])
    bpy.data.objects.remove(base)
clay = bpy.data.materials.new("clay")
clay.diffuse_color = (0.72, 0.45, 0.33, 1.0)
clay.use_nodes = True
clay.node_tree.nodes["Principled BSDF"].inputs["Base Color"].default_value = (0.72, 0.45, 0.33, 1.0)
spheres[1].data.materials.append(clay)
spheres[0].data.polygons.foreach_set("use_smooth", [True] * len(spheres[0].data.polygons))

render_still(out, (800, 420), (0.0, -6.4, 2.2), (1.25, 0.0, 0.0), 1000, (2.0, -4.0, 5.0))
