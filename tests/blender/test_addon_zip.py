"""The add-on as an artist installs it: the zip of scripts/blender_addon.sh, with the module inside.
    blender -b --factory-startup --python-exit-code 1 --python test_addon_zip.py -- ZIP
Run with BLENDER_USER_SCRIPTS set to an empty folder. Installing and enabling the zip needs no
module folder: the module is found inside the add-on and quilts the default cube. Without the
module and without the executable, a job says which preferences to set. A relative module folder
is taken relative to the current folder, "//" relative to the .blend."""
import os
import sys

import addon_utils
import bpy

archive = sys.argv[sys.argv.index("--") + 1]


def check(condition, what):
    if not condition:
        raise AssertionError(what)
    print("ok:", what)


bpy.ops.preferences.addon_install(filepath=archive)
addon_utils.enable("meshquilt_blender", default_set=True)
import meshquilt_blender  # noqa: E402

check(os.path.realpath(meshquilt_blender.__file__).startswith(os.path.realpath(os.environ["BLENDER_USER_SCRIPTS"])),
      "the add-on is installed from the zip")
check(bpy.context.preferences.addons["meshquilt_blender"].preferences.module_path == "", "no module folder is set")
module = meshquilt_blender.job.import_module("")
check(module is not None and os.path.realpath(module.__file__).startswith(
    os.path.realpath(meshquilt_blender.job.BUNDLED)), "the module is the one inside the add-on")

cube = bpy.data.objects["Cube"]
bpy.context.view_layer.objects.active = cube
settings = bpy.context.scene.meshquilt
settings.small, settings.scale = True, 0.4
check(bpy.ops.meshquilt.create() == {"FINISHED"} and len(bpy.context.active_object.data.polygons) > 0,
      "Create quilts the cube")

job = meshquilt_blender.job.QuiltJob(meshquilt_blender.mesh_arrays(cube), swatch_options={"preset": "small"},
                                     scale=0.4, module_path="build/python", executable="no-such-meshquilt")
job.module, job._token = None, None
job.start().wait(60)
check(job.error is not None and "Module folder" in str(job.error) and "no-such-meshquilt" in str(job.error),
      "without module and executable a job names the preferences: " + str(job.error))
check(meshquilt_blender.job.module_folder("build/python") == os.path.join(os.getcwd(), "build", "python"),
      "a relative module folder is taken from the current folder")
print("all checks passed")
