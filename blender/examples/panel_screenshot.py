"""Runs the add-on's Create in Blender's window (under Xvfb), the modal way an artist does, and
takes a screenshot of the panel and the result (the picture in docs/blender.md):
    blender -b --factory-startup --python-expr "import bpy; bpy.ops.wm.save_as_mainfile(filepath='start.blend')"
    xvfb-run -s "-screen 0 1280x1280x24" blender --factory-startup start.blend --python panel_screenshot.py -- \
        MODULE_FOLDER SOURCE OUT.png
(a file named on the command line keeps the first-run splash screen away)."""
import os
import sys

import addon_utils
import bpy

module_folder, source, out = sys.argv[sys.argv.index("--") + 1:][:3]
sys.path.insert(0, os.path.join(source, "blender"))
addon_utils.enable("meshquilt_blender", default_set=True)
bpy.context.preferences.addons["meshquilt_blender"].preferences.module_path = module_folder
state = {"started": False, "waited": 0}
# Blender 3.4 cannot choose a sidebar tab from Python: show the panel in the tab that opens first.
import meshquilt_blender  # noqa: E402

bpy.utils.unregister_class(meshquilt_blender.VIEW3D_PT_meshquilt)
meshquilt_blender.VIEW3D_PT_meshquilt.bl_category = "Item"
meshquilt_blender.VIEW3D_PT_meshquilt.bl_order = -100  # above the Transform panel
bpy.utils.register_class(meshquilt_blender.VIEW3D_PT_meshquilt)


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
            for r in area.regions:
                if r.type == "UI" and hasattr(r, "active_panel_category"):
                    r.active_panel_category = "meshquilt"
            settings = bpy.context.scene.meshquilt
            settings.swatch_kind, settings.small, settings.scale = "chainmail", True, 0.35
            bpy.context.view_layer.objects.active = bpy.data.objects["Cube"]
            bpy.ops.meshquilt.create("INVOKE_DEFAULT")
            state["started"] = True
            return 0.5
        if "Cube_quilt" not in bpy.data.objects and state["waited"] < 240:
            state["waited"] += 1
            return 0.5
        bpy.data.objects["Cube"].hide_set(True)
        for obj in bpy.data.objects:
            obj.select_set(obj.name == "Cube_quilt")
        bpy.context.view_layer.objects.active = bpy.data.objects["Cube_quilt"]
        bpy.ops.view3d.view_selected()
        bpy.ops.screen.screenshot(filepath=out)
    print("modal Create finished:", "Cube_quilt" in bpy.data.objects)
    bpy.ops.wm.quit_blender()
    return None


bpy.app.timers.register(step, first_interval=2.0)
