"""Quilts a UV sphere with the small chain mail through the add-on and renders the result as it
comes (smooth, in the add-on's metal) with Cycles on the CPU (the picture in docs/blender.md):
    blender -b --factory-startup --python render_quilted_sphere.py -- MODULE_FOLDER SOURCE OUT.png"""
import os
import sys

import addon_utils
import bpy

module_folder, source, out = sys.argv[sys.argv.index("--") + 1:][:3]
sys.path.insert(0, os.path.join(source, "blender"))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cycles_still import render_still  # noqa: E402

addon_utils.enable("meshquilt_blender", default_set=True)
bpy.context.preferences.addons["meshquilt_blender"].preferences.module_path = module_folder

bpy.data.objects.remove(bpy.data.objects["Cube"])
bpy.ops.mesh.primitive_uv_sphere_add(segments=48, ring_count=24, radius=1.0)
base = bpy.context.active_object
base.data.materials.append(bpy.data.materials.new("base"))
base.data.materials[0].diffuse_color = (0.15, 0.12, 0.1, 1.0)
settings = bpy.context.scene.meshquilt
settings.swatch_kind, settings.small, settings.scale, settings.seed = "chainmail", True, 0.25, 1
assert bpy.ops.meshquilt.create() == {"FINISHED"}
quilt = bpy.data.objects[base.name + "_quilt"]
assert quilt.data.materials[0].name == "meshquilt chainmail"  # rendered in the add-on's own metal

render_still(out, (640, 480), (3.2, -3.2, 2.2), (1.1, 0.0, 0.785), 1500)
