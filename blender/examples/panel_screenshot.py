"""Runs the add-on's Create in Blender's window (under Xvfb), the modal way an artist does, over a
UV sphere with the full-size chain mail, and takes two screenshots (the pictures in
docs/blender.md): the run in progress, its share in the status bar, and the panel and the result
once it is done:
    blender -b --factory-startup --python-expr "import bpy; bpy.ops.wm.save_as_mainfile(filepath='start.blend')"
    xvfb-run -s "-screen 0 1280x1280x24" blender --factory-startup start.blend --python panel_screenshot.py -- \
        MODULE_FOLDER SOURCE OUT.png PROGRESS.png
(a file named on the command line keeps the first-run splash screen away)."""
import os
import sys

import addon_utils
import bpy

module_folder, source, out, progress_out = sys.argv[sys.argv.index("--") + 1:][:4]
sys.path.insert(0, os.path.join(source, "blender"))
addon_utils.enable("meshquilt_blender", default_set=True)
bpy.context.preferences.addons["meshquilt_blender"].preferences.module_path = module_folder
state = {"started": False, "waited": 0}
# Blender 3.4 cannot choose a sidebar tab from Python: show the panel in the tab that opens first.
import meshquilt_blender  # noqa: E402

panels = [cls for cls in meshquilt_blender.classes if issubclass(cls, bpy.types.Panel)]
for cls in reversed(panels):
    bpy.utils.unregister_class(cls)
for cls in panels:
    cls.bl_category = "Item"
meshquilt_blender.VIEW3D_PT_meshquilt.bl_order = -100  # above the Transform panel
for cls in panels:
    bpy.utils.register_class(cls)


def view3d():
    window = bpy.context.window_manager.windows[0]
    for area in window.screen.areas:
        if area.type == "VIEW_3D":
            region = next(r for r in area.regions if r.type == "WINDOW")
            return window, area, region
    raise RuntimeError("no 3D view")


def step():
    window, area, region = view3d()
    with bpy.context.temp_override(window=window, area=area, region=region):
        if not state["started"]:
            area.spaces[0].show_region_ui = True
            bpy.data.objects.remove(bpy.data.objects["Cube"])
            bpy.ops.mesh.primitive_uv_sphere_add(radius=1.0, segments=32, ring_count=16)
            bpy.ops.object.shade_smooth()
            bpy.context.active_object.name = "Sphere"
            settings = bpy.context.scene.meshquilt
            settings.swatch_kind, settings.small, settings.scale = "chainmail", False, 0.2
            bpy.ops.view3d.view_selected()
            bpy.ops.meshquilt.create("INVOKE_DEFAULT")
            state["started"] = True
            return 1.5
        if not state.get("progress"):
            bpy.ops.wm.redraw_timer(type="DRAW_WIN_SWAP", iterations=1)
            bpy.ops.screen.screenshot(filepath=progress_out)
            print("in progress:", bpy.context.scene.meshquilt.job_running)
            state["progress"] = True
            return 0.5
        if "Sphere_quilt" not in bpy.data.objects and state["waited"] < 480:
            state["waited"] += 1
            return 0.5
        bpy.data.objects["Sphere"].hide_set(True)
        bpy.ops.view3d.view_selected()
        bpy.ops.wm.redraw_timer(type="DRAW_WIN_SWAP", iterations=1)
        bpy.ops.screen.screenshot(filepath=out)
    print("modal Create finished:", "Sphere_quilt" in bpy.data.objects)
    bpy.ops.wm.quit_blender()
    return None


bpy.app.timers.register(step, first_interval=2.0)
