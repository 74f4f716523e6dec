"""The examples' one render setting: Cycles on the CPU at 24 samples under a grey world, the
default scene's camera and light placed as asked, one still written."""
import bpy


def render_still(out, size, camera_location, camera_rotation, light_energy, light_location=None):
    scene = bpy.context.scene
    scene.render.engine = "CYCLES"
    scene.cycles.device = "CPU"
    scene.cycles.samples = 24
    scene.cycles.use_denoising = False  # Debian's Blender is built without OpenImageDenoise
    scene.render.resolution_x, scene.render.resolution_y = size
    camera = bpy.data.objects["Camera"]
    camera.location, camera.rotation_euler = camera_location, camera_rotation
    light = bpy.data.objects["Light"]
    light.data.energy = light_energy
    if light_location is not None:
        light.location = light_location
    scene.world.color = (0.6, 0.62, 0.65)
    scene.render.filepath = out
    bpy.ops.render.render(write_still=True)
