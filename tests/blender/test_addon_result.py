"""The add-on's result as an artist gets it, in real Blender, headless:
    blender -b --factory-startup --python-exit-code 1 --python test_addon_result.py -- MODULE_FOLDER SOURCE WORK
A swatch object carrying a UV map, a named material and smooth faces quilts a sphere: the result
wears that UV map (each face's UVs those of the swatch triangle it came from), that material and
smooth shading, and is the selected, active object. Create is one undo step: after moving the
sphere and Create, one undo leaves the moved sphere and no result. The built-in chain mail over
the sphere (the default job) comes back smooth in its metal, and the .blend holding it is at most
1.15x the size of the same file with the result's mesh alone. A base deleted while the job runs
ends the job with a message and nothing added."""
import os
import sys

import addon_utils
import bpy
import numpy as np

module_folder, source, work = sys.argv[sys.argv.index("--") + 1:][:3]
sys.path.insert(0, os.path.join(source, "blender"))
os.makedirs(work, exist_ok=True)


def check(condition, what):
    if not condition:
        raise AssertionError(what)
    print("ok:", what)


addon_utils.enable("meshquilt_blender", default_set=True)
import meshquilt_blender  # noqa: E402

bpy.context.preferences.addons["meshquilt_blender"].preferences.module_path = module_folder
meshquilt = meshquilt_blender.job.import_module(module_folder)
check(meshquilt is not None, "the module is found")
check("UNDO" in meshquilt_blender.MESHQUILT_OT_create.bl_options, "Create registers an undo step")

for obj in list(bpy.data.objects):
    bpy.data.objects.remove(obj)

# The swatch as an artist would make it: the small chain mail with a planar UV map, a "Gold"
# material and smooth faces.
mail = meshquilt.swatch("chainmail", preset="small")
swatch_mesh = bpy.data.meshes.new("mail")
swatch_mesh.from_pydata(mail.vertices.tolist(), [], mail.faces.tolist())
uv = swatch_mesh.uv_layers.new(name="Planar")
loop_vertices = np.empty(len(swatch_mesh.loops), dtype=np.int32)
swatch_mesh.loops.foreach_get("vertex_index", loop_vertices)
extent = np.ptp(mail.vertices[:, :2], axis=0)
planar = (mail.vertices[loop_vertices, :2] - mail.vertices[:, :2].min(0)) / extent
uv.data.foreach_set("uv", planar.ravel())
gold = bpy.data.materials.new("Gold")
swatch_mesh.materials.append(gold)
swatch_mesh.polygons.foreach_set("use_smooth", np.ones(len(swatch_mesh.polygons), dtype=bool))
swatch_obj = bpy.data.objects.new("mail", swatch_mesh)
bpy.context.collection.objects.link(swatch_obj)

bpy.ops.mesh.primitive_uv_sphere_add(radius=1.0, segments=24, ring_count=12)
sphere = bpy.context.active_object
settings = bpy.context.scene.meshquilt
settings.swatch_object, settings.scale, settings.seed = swatch_obj, 0.4, 1
bpy.ops.ed.undo_push(message="before")

# Move the sphere (an undo step of its own), then Create.
sphere.location.x = 3.0
bpy.ops.ed.undo_push(message="move")
before = set(bpy.data.objects.keys())
# As a button press runs it: with its undo step (a script's call pushes none unless asked).
check(bpy.ops.meshquilt.create("EXEC_DEFAULT", True) == {"FINISHED"}, "Create finishes")
added = [bpy.data.objects[name] for name in set(bpy.data.objects.keys()) - before]
check(len(added) == 1, "Create adds one object")
result = added[0]
check(bpy.context.view_layer.objects.active == result and result.select_get()
      and not sphere.select_get(), "the result is the selected, active object")
mesh = result.data
check([m.name for m in mesh.materials] == ["Gold"], "the result wears the swatch's material")
smooth = np.empty(len(mesh.polygons), dtype=bool)
mesh.polygons.foreach_get("use_smooth", smooth)
check(smooth.all(), "the result is smooth shaded")
check(mesh.uv_layers.get("Planar") is not None, "the result has the swatch's UV map")

# Each face's UVs are those of a swatch triangle (up to the order of its corners), for nearly all
# faces: the rest are seams where stitched pieces meet.
result_uv = np.empty(2 * len(mesh.loops))
mesh.uv_layers["Planar"].data.foreach_get("uv", result_uv)
result_uv = np.round(result_uv.reshape(-1, 3, 2), 6)
swatch_uv = np.round(planar.reshape(-1, 3, 2), 6)
known = {tuple(sorted(map(tuple, t))) for t in swatch_uv}
share = np.mean([tuple(sorted(map(tuple, t))) in known for t in result_uv])
check(share > 0.9, "%.3f of the faces carry a swatch triangle's UVs" % share)

# One undo: the result goes, the sphere stays where it was moved (undo reloads the data, so
# objects are found again by name).
sphere_name = sphere.name
bpy.ops.ed.undo()
sphere = bpy.data.objects[sphere_name]
settings = bpy.context.scene.meshquilt
check(set(bpy.data.objects.keys()) == before, "one undo removes the result alone")
check(abs(sphere.location.x - 3.0) < 1e-9, "and keeps the move before it")

# The default job: the built-in chain mail, full size, over the sphere at 0.2.
settings.swatch_object, settings.small, settings.scale = None, False, 0.2
bpy.context.view_layer.objects.active = sphere
guess = meshquilt_blender.estimate(bpy.context)
check(bpy.ops.meshquilt.create("EXEC_DEFAULT", True) == {"FINISHED"}, "the default job finishes")
default = bpy.context.view_layer.objects.active
made = len(default.data.polygons)
check(meshquilt_blender._measures.get("faces_per_second", 0) > 0, "the pace of the run is kept for the next estimate")
check(guess is not None and 0.5 * made <= guess[0] <= 2.0 * made,
      "the estimate before Create (%s faces) is within 2x of what it made (%d)" % (guess and guess[0], made))

# Update: the result's job again with changed settings, in the same object; one undo brings the
# old texture back. Recall puts the result's settings back in the panel.
name = default.name
settings.scale = 0.3
check(bpy.ops.meshquilt.update("EXEC_DEFAULT", True) == {"FINISHED"}, "Update finishes")
default = bpy.data.objects[name]
check(bpy.context.view_layer.objects.active == default and len(default.data.polygons) < made
      and abs(default["meshquilt_job"]["scale"] - 0.3) < 1e-6, "Update quilts again in place at the new scale")
bpy.ops.ed.undo()
default = bpy.data.objects[name]
settings = bpy.context.scene.meshquilt
check(len(default.data.polygons) == made, "one undo brings the result before Update back")
settings.scale = 0.7
bpy.context.view_layer.objects.active = default
check(bpy.ops.meshquilt.recall() == {"FINISHED"} and abs(settings.scale - 0.2) < 1e-6,
      "Recall puts the result's settings in the panel")
sphere = bpy.data.objects[sphere_name]
check(default != sphere and default.data.materials[0].name == "meshquilt chainmail"
      and default.data.materials[0].metallic == 1.0, "the built-in mail comes in metal")
smooth = np.empty(len(default.data.polygons), dtype=bool)
default.data.polygons.foreach_get("use_smooth", smooth)
check(smooth.all(), "and smooth")
check("meshquilt_texture_file" in default and os.path.isfile(bpy.path.abspath(default["meshquilt_texture_file"])),
      "its texture is kept in a file, not in the .blend")
with_result = os.path.join(work, "with_result.blend")
bpy.ops.wm.save_as_mainfile(filepath=with_result)
for key in list(default.keys()):
    del default[key]
mesh_alone = os.path.join(work, "mesh_alone.blend")
bpy.ops.wm.save_as_mainfile(filepath=mesh_alone)
ratio = os.path.getsize(with_result) / os.path.getsize(mesh_alone)
check(ratio <= 1.15, "the .blend holding the result is %.3f x the one with its mesh alone" % ratio)

# A base deleted while the job runs: the job ends with a message and adds nothing.
bpy.context.view_layer.objects.active = sphere
operator = meshquilt_blender.MESHQUILT_OT_create
count = len(bpy.data.objects)
job = meshquilt_blender.make_job(bpy.context, sphere).start()
job.wait(600)


class Reports:
    def __init__(self):
        self.lines = []

    def report(self, kind, text):
        self.lines.append(text)


reports = Reports()
stand_in = type("StandIn", (), {"report": reports.report, "_base": sphere, "_look": None, "_kind": "chainmail"})()
bpy.data.objects.remove(sphere)
check(operator._apply(stand_in, bpy.context, job.result) == {"CANCELLED"} and len(bpy.data.objects) == count - 1,
      "a deleted base ends the job with nothing added: " + "; ".join(reports.lines))
print("all checks passed")
