"""meshquilt in Blender: a panel in the 3D view's sidebar that quilts the active mesh with a
swatch (a mesh object or a built-in one), off the main thread, with progress and Esc to cancel
(the one-window quilter of the Arachne plug-in design)."""

bl_info = {
    "name": "meshquilt",
    "author": "meshquilt developers",
    "version": (0, 1, 0),
    "blender": (3, 4, 0),
    "location": "View3D > Sidebar > meshquilt",
    "description": "Grow chain mail, weaves, fruit and vines over a mesh by mesh quilting",
    "category": "Mesh",
}

import hashlib
import os
import tempfile

import bmesh
import bpy
import numpy as np
from mathutils import Vector

from . import job as quilt_job

BUILT_IN = [("chainmail", "Chain mail", "4-in-1 rings"), ("weave", "Weave", "plain weave"),
            ("wire", "Wire", "sparse crimped wire"), ("fruit", "Fruit", "apple-like blobs"),
            ("nuts", "Nuts", "hex nuts"), ("vine", "Vine", "swaying stalks")]


class MeshquiltPreferences(bpy.types.AddonPreferences):
    bl_idname = __package__
    module_path: bpy.props.StringProperty(name="Module folder", subtype="DIR_PATH",
                                          description="Folder holding the Python package meshquilt (build/python)")
    executable: bpy.props.StringProperty(name="meshquilt executable", default="meshquilt", subtype="FILE_PATH",
                                         description="Run when the module cannot be imported")

    def draw(self, context):
        self.layout.prop(self, "module_path")
        self.layout.prop(self, "executable")


class MeshquiltSettings(bpy.types.PropertyGroup):
    swatch_object: bpy.props.PointerProperty(name="Swatch", type=bpy.types.Object,
                                             poll=lambda self, obj: obj.type == "MESH",
                                             description="A mesh object as the swatch; empty: a built-in one")
    swatch_kind: bpy.props.EnumProperty(name="Built-in", items=BUILT_IN, default="chainmail")
    small: bpy.props.BoolProperty(name="Test-sized", default=False,
                                  description="The built-in swatch's small preset, for quick trials")
    scale: bpy.props.FloatProperty(name="Scale", default=0.15, min=0.001, max=10.0,
                                   description="Swatch's longer side over the base's bounding-box diagonal")
    seed: bpy.props.IntProperty(name="Seed", default=1, min=0)
    minimize_distortion: bpy.props.BoolProperty(name="Minimize distortion", default=True)
    shell_height: bpy.props.FloatProperty(name="Shell height", default=0.0, min=0.0,
                                          description="Layer height in base units (0: the swatch's own)")
    select_share: bpy.props.FloatProperty(name="Share", default=0.1, min=0.0, max=1.0)
    job_running: bpy.props.BoolProperty(name="Running", default=False, options={"SKIP_SAVE"})
    job_progress: bpy.props.FloatProperty(name="Done", default=0.0, min=0.0, max=100.0, subtype="PERCENTAGE",
                                          options={"SKIP_SAVE"}, description="Share of the running job done")
    frames: bpy.props.IntProperty(name="Frames", default=12, min=1, max=1000,
                                  description="Frames of the built-in vine's sway cycle")
    paint_image: bpy.props.PointerProperty(name="Image", type=bpy.types.Image,
                                           description="The sample painted over the active mesh (Turk 2001)")
    paint_scale: bpy.props.FloatProperty(name="Image scale", default=0.25, min=0.001, max=10.0,
                                         description="The image's width over the base's bounding-box diagonal")
    paint_pixels: bpy.props.IntProperty(name="Image pixels", default=128, min=0, max=4096,
                                        description="Shrink a wider image to this many pixels across first (a box "
                                                    "filter), so a photo fits the vertices paint allows; 0: as it is")
    relief_height: bpy.props.FloatProperty(name="Relief height", default=0.0, min=0.0,
                                           description="Raise the image's luma (white high) by this many base "
                                                       "units instead of colouring; 0: colour only")
    guide_object: bpy.props.PointerProperty(
        name="Guide", type=bpy.types.Object, poll=lambda self, obj: obj.type in {"CURVE", "GPENCIL"},
        description="A curve or grease-pencil object whose strokes, drawn over the base, orient the "
                    "swatch; empty: the default field")
    loom_design: bpy.props.PointerProperty(
        name="Design", type=bpy.types.Image,
        description="The weave design, a pixel a crossing: dark where the warp (column) lies over the weft (row)")
    loom_exemplars: bpy.props.PointerProperty(
        name="Exemplars", type=bpy.types.Collection,
        description="A collection of woven swatch objects; empty: built-in plain, twill 2/2 and satin 4/1")
    loom_method: bpy.props.EnumProperty(
        name="Method", default="structured",
        items=[("structured", "Structured", "most consistent blocks, then the most continuous yarns"),
               ("greedy", "Greedy", "most consistent blocks, ties at random"),
               ("naive", "Naive", "any block with the right yarn on top")])
    loom_weaves: bpy.props.StringProperty(
        name="Weaves", default="",
        description="Read the design's colours as weaves: RRGGBB=plain,RRGGBB=twill:2/2,...; empty: dark and light")
    loom_sides: bpy.props.IntProperty(name="Yarn sides", default=8, min=3, max=64)
    loom_stations: bpy.props.IntProperty(name="Samples per crossing", default=8, min=2, max=64, step=2)


def settings_of(context):
    return context.scene.meshquilt


def preferences(context):
    addon = context.preferences.addons.get(__package__)
    return addon.preferences if addon else None


def module_or_report(operator, context, what):
    """The Python module from the preferences' folder, or None after reporting that `what` needs it."""
    prefs = preferences(context)
    module = quilt_job.import_module(prefs.module_path if prefs else "")
    if module is None:
        operator.report({"ERROR"}, "meshquilt: %s needs the Python module: set Preferences > Add-ons > meshquilt > "
                                   "Module folder (build/python of a build), or install the zip of "
                                   "scripts/blender_addon.sh" % what)
    return module


def mesh_arrays(obj, depsgraph=None):
    """World-space vertices and triangles of a mesh object (evaluated when a depsgraph is given)."""
    source = obj.evaluated_get(depsgraph) if depsgraph else obj
    mesh = source.to_mesh()
    mesh.calc_loop_triangles()
    vertices = np.empty(len(mesh.vertices) * 3)
    mesh.vertices.foreach_get("co", vertices)
    vertices = vertices.reshape(-1, 3)
    matrix = np.array(obj.matrix_world)
    vertices = vertices @ matrix[:3, :3].T + matrix[:3, 3]
    faces = np.empty(len(mesh.loop_triangles) * 3, dtype=np.int32)
    mesh.loop_triangles.foreach_get("vertices", faces)
    source.to_mesh_clear()
    return vertices, faces.reshape(-1, 3)


def stroke_polylines(guide, depsgraph=None):
    """World-space point lists of a guide object's strokes: a curve's splines as Blender tessellates
    them, or a grease-pencil object's strokes in the current frame."""
    matrix = np.array(guide.matrix_world)
    lines = []
    if guide.type == "GPENCIL":
        for layer in guide.data.layers:
            frame = layer.active_frame
            for stroke in (frame.strokes if frame else []):
                lines.append(np.array([tuple(p.co) for p in stroke.points], dtype=np.float64).reshape(-1, 3))
    else:
        source = guide.evaluated_get(depsgraph) if depsgraph else guide
        mesh = source.to_mesh()
        points = np.empty(len(mesh.vertices) * 3)
        mesh.vertices.foreach_get("co", points)
        points = points.reshape(-1, 3)
        # Each edge of the tessellated curve is a piece of a stroke, in the spline's order.
        lines += [points[list(edge.vertices)] for edge in mesh.edges]
        source.to_mesh_clear()
    return [line @ matrix[:3, :3].T + matrix[:3, 3] for line in lines if len(line) >= 2]


def guide_field(guide, base, depsgraph=None):
    """(points, directions) for synth's field: each stroke segment's midpoint moved onto the base
    (its closest point) with the segment's direction, in world space; None without segments."""
    to_local = base.matrix_world.inverted()
    to_world = base.matrix_world
    points, directions = [], []
    for line in stroke_polylines(guide, depsgraph):
        for a, b in zip(line[:-1], line[1:]):
            if np.linalg.norm(b - a) == 0.0:
                continue
            found, location, _, _ = base.closest_point_on_mesh(to_local @ Vector(0.5 * (a + b)))
            if not found:
                continue
            points.append(tuple(to_world @ location))
            directions.append(tuple(b - a))
    if not points:
        return None
    return np.array(points, dtype=np.float64), np.array(directions, dtype=np.float64)


def swatch_look(obj):
    """How a swatch object looks, per triangle of mesh_arrays(obj): its vertices, UVs of the active
    UV map (None without one), material slot and smooth flag; with its materials and UV map name."""
    mesh = obj.data
    mesh.calc_loop_triangles()
    count = len(mesh.loop_triangles)
    vertices = np.empty(3 * count, dtype=np.int32)
    mesh.loop_triangles.foreach_get("vertices", vertices)
    materials = np.empty(count, dtype=np.int32)
    mesh.loop_triangles.foreach_get("material_index", materials)
    smooth = np.empty(count, dtype=bool)
    mesh.loop_triangles.foreach_get("use_smooth", smooth)
    uvs, uv_name = None, None
    if mesh.uv_layers.active is not None:
        loops = np.empty(3 * count, dtype=np.int32)
        mesh.loop_triangles.foreach_get("loops", loops)
        per_loop = np.empty(2 * len(mesh.loops))
        mesh.uv_layers.active.data.foreach_get("uv", per_loop)
        uvs = per_loop.reshape(-1, 2)[loops].reshape(count, 3, 2)
        uv_name = mesh.uv_layers.active.name
    return {"vertices": vertices.reshape(count, 3), "uvs": uvs, "uv_name": uv_name, "material": materials,
            "smooth": smooth, "materials": [slot.material for slot in obj.material_slots]}


# Materials of the built-in kinds: base colour, metallic, roughness.
BUILT_IN_LOOKS = {"chainmail": ((0.62, 0.62, 0.64), 1.0, 0.3), "wire": ((0.7, 0.7, 0.72), 1.0, 0.35),
                  "nuts": ((0.55, 0.55, 0.57), 1.0, 0.4), "weave": ((0.55, 0.33, 0.2), 0.0, 0.8),
                  "fruit": ((0.6, 0.08, 0.05), 0.0, 0.35), "vine": ((0.18, 0.42, 0.12), 0.0, 0.6),
                  "heightfield": ((0.7, 0.66, 0.6), 0.0, 0.7)}


def built_in_material(kind):
    """One shared material a built-in kind wears (made once per file)."""
    name = "meshquilt " + kind
    material = bpy.data.materials.get(name)
    if material is None:
        colour, metallic, roughness = BUILT_IN_LOOKS.get(kind, BUILT_IN_LOOKS["heightfield"])
        material = bpy.data.materials.new(name)
        material.diffuse_color = colour + (1.0,)
        material.metallic, material.roughness = metallic, roughness
        material.use_nodes = True
        principled = material.node_tree.nodes["Principled BSDF"]
        principled.inputs["Base Color"].default_value = colour + (1.0,)
        principled.inputs["Metallic"].default_value = metallic
        principled.inputs["Roughness"].default_value = roughness
    return material


def dress(mesh, faces, origins, look):
    """The swatch's look on a result: each face whose corners came from one swatch triangle takes
    that triangle's UVs, material and smooth flag; any other (a seam where pieces were stitched)
    takes, per corner, a UV of the swatch vertex it came from, and the material and smooth flag of
    a triangle at its first corner's swatch vertex."""
    tri = look["vertices"]
    count = int(tri.max()) + 1 if len(tri) else 0
    corner = np.asarray(origins)[faces]  # (F, 3) swatch vertices
    def key(t):
        t = np.sort(t, axis=1).astype(np.int64)
        return (t[:, 0] * count + t[:, 1]) * count + t[:, 2]
    swatch_keys = key(tri)
    order = np.argsort(swatch_keys)
    at = np.searchsorted(swatch_keys[order], key(corner))
    at = np.minimum(at, len(order) - 1)
    match = swatch_keys[order][at] == key(corner)
    source_tri = np.where(match, order[at], -1)
    # Per swatch vertex, one triangle and corner that holds it (the fallback).
    vertex_tri = np.zeros(count, dtype=np.int64)
    vertex_corner = np.zeros(count, dtype=np.int64)
    for k in range(3):
        vertex_tri[tri[:, k]] = np.arange(len(tri))
        vertex_corner[tri[:, k]] = k
    fallback = vertex_tri[corner[:, 0]]
    face_tri = np.where(match, source_tri, fallback)
    if look["materials"]:
        for material in look["materials"]:
            mesh.materials.append(material)
        mesh.polygons.foreach_set("material_index", look["material"][face_tri].astype(np.int32))
    mesh.polygons.foreach_set("use_smooth", look["smooth"][face_tri])
    if look["uvs"] is not None:
        uvs = np.empty((len(faces), 3, 2))
        for k in range(3):
            # The matching corner of the swatch triangle; else the swatch vertex's own UV.
            same = tri[source_tri] == corner[:, k:k + 1]
            which = np.argmax(same, axis=1)
            exact = look["uvs"][source_tri, which]
            loose = look["uvs"][vertex_tri[corner[:, k]], vertex_corner[corner[:, k]]]
            uvs[:, k] = np.where((match & same.any(axis=1))[:, None], exact, loose)
        layer = mesh.uv_layers.new(name=look["uv_name"] or "UVMap")
        layer.data.foreach_set("uv", uvs.ravel())


def texture_folder():
    """Where texture files go: beside the saved .blend (`//meshquilt/`), else Blender's temporary
    folder (kept while Blender runs)."""
    if bpy.data.filepath:
        return "//meshquilt"
    return os.path.join(bpy.app.tempdir or tempfile.gettempdir(), "meshquilt")


def store_texture(obj, data):
    """Writes the layer in texture space to a file and remembers its path on `obj` (never the bytes:
    they would make the .blend several times larger)."""
    folder = texture_folder()
    os.makedirs(bpy.path.abspath(folder), exist_ok=True)
    # Named by content too: after Update and an undo, the restored result finds its own layer.
    path = "%s/%s_%s.mqt" % (folder, bpy.path.clean_name(obj.name), hashlib.sha1(data).hexdigest()[:12])
    with open(bpy.path.abspath(path), "wb") as out:
        out.write(data)
    obj["meshquilt_texture_file"] = path


def load_texture(obj):
    with open(bpy.path.abspath(obj["meshquilt_texture_file"]), "rb") as file:
        return file.read()


def make_job(context, base):
    s, prefs = settings_of(context), preferences(context)
    swatch = mesh_arrays(s.swatch_object) if s.swatch_object else None
    field = guide_field(s.guide_object, base) if s.guide_object else None
    return quilt_job.QuiltJob(mesh_arrays(base), swatch=swatch, swatch_kind=s.swatch_kind,
                              swatch_options={"preset": "small"} if s.small else {}, scale=s.scale, seed=s.seed,
                              minimize_distortion=s.minimize_distortion, shell_height=s.shell_height,
                              module_path=prefs.module_path if prefs else "",
                              executable=prefs.executable if prefs else "meshquilt", field=field)


def add_result_object(context, base, result, suffix="quilt", look=None, kind=None):
    """The result as a new object beside the base (named `suffix` alone without one), selected and
    active, with face attributes `element` and `source`: dressed in the swatch object's UVs,
    materials and shading (`look`), or in the built-in `kind`'s material and smooth, or else one
    material per source."""
    vertices, faces = result["vertices"], result["faces"]
    mesh = bpy.data.meshes.new(base.name + "_" + suffix if base is not None else suffix)
    mesh.vertices.add(len(vertices))
    mesh.vertices.foreach_set("co", np.asarray(vertices, dtype=np.float64).ravel())
    mesh.loops.add(faces.size)
    mesh.loops.foreach_set("vertex_index", np.asarray(faces, dtype=np.int32).ravel())
    mesh.polygons.add(len(faces))
    mesh.polygons.foreach_set("loop_start", np.arange(0, faces.size, 3, dtype=np.int32))
    mesh.polygons.foreach_set("loop_total", np.full(len(faces), 3, dtype=np.int32))
    for name in ("element", "source"):
        if result.get(name) is not None:
            attribute = mesh.attributes.new(name, "INT", "FACE")
            attribute.data.foreach_set("value", np.asarray(result[name], dtype=np.int32))
    if result.get("origin") is not None:
        # The swatch vertex each vertex came from, for playing a swatch animation on it.
        attribute = mesh.attributes.new("origin", "INT", "POINT")
        attribute.data.foreach_set("value", np.asarray(result["origin"], dtype=np.int32))
    if look is not None and result.get("origin") is not None:
        dress(mesh, np.asarray(faces), result["origin"], look)
    elif kind is not None:
        mesh.materials.append(built_in_material(kind))
        mesh.polygons.foreach_set("use_smooth", np.ones(len(faces), dtype=bool))
    elif result.get("source") is not None:
        sources = np.unique(result["source"])
        for k, s in enumerate(sources):
            material = bpy.data.materials.new("%s_source_%d" % (mesh.name, s))
            hue = (0.618034 * k) % 1.0
            material.diffuse_color = (0.4 + 0.5 * abs(np.sin(6.283 * hue)), 0.4 + 0.5 * abs(np.sin(6.283 * (hue + 0.33))),
                                      0.4 + 0.5 * abs(np.sin(6.283 * (hue + 0.66))), 1.0)
            mesh.materials.append(material)
        index = np.searchsorted(sources, result["source"]).astype(np.int32)
        mesh.polygons.foreach_set("material_index", index)
    mesh.update()
    mesh.validate()
    obj = bpy.data.objects.new(mesh.name, mesh)
    context.collection.objects.link(obj)
    if result.get("texture"):
        # The layer in texture space, so that it can follow the base after a pose or a sculpt.
        store_texture(obj, result["texture"])
        obj["meshquilt_base"] = base.name
    for other in context.selected_objects:
        other.select_set(False)
    obj.select_set(True)
    context.view_layer.objects.active = obj
    return obj


class JobOperator:
    """Runs the job `_start` gives off the main thread, with its progress in the status bar; Esc
    cancels it and leaves the scene as it was. Without a window (scripts, background) it runs to
    the end. `_apply` adds what the job made."""

    _timer = None
    _job = None

    def invoke(self, context, event):
        self._job = self._start(context)
        if self._job is None:
            return {"CANCELLED"}
        wm = context.window_manager
        self._timer = wm.event_timer_add(0.2, window=context.window)
        wm.progress_begin(0, 100)
        wm.modal_handler_add(self)
        s = settings_of(context)
        s.job_running, s.job_progress = True, 0.0
        return {"RUNNING_MODAL"}

    def execute(self, context):
        self._job = self._start(context)
        if self._job is None:
            return {"CANCELLED"}
        self._job.wait()
        return self._finish(context)

    def modal(self, context, event):
        wm = context.window_manager
        if event.type == "ESC":
            self._job.cancel()
            self._job.wait()
            return self._finish(context)
        if event.type == "TIMER":
            wm.progress_update(int(100 * self._job.share))
            settings_of(context).job_progress = 100.0 * self._job.share
            for area in context.screen.areas if context.screen else []:
                if area.type == "VIEW_3D":
                    area.tag_redraw()
            left = self._job.seconds_left
            context.workspace.status_text_set("meshquilt: %d%%%s. Esc to cancel" % (
                100 * self._job.share, ", %.0f s left" % left if left >= 0 else ""))
            if self._job.done.is_set():
                return self._finish(context)
        return {"PASS_THROUGH"}

    def _finish(self, context):
        if self._job.result is not None and self._job.seconds > 0.0 and isinstance(self._job.result, dict):
            # This machine's pace, for the next estimate of time.
            _measures["faces_per_second"] = len(self._job.result["faces"]) / self._job.seconds
        wm = context.window_manager
        if self._timer is not None:
            wm.event_timer_remove(self._timer)
            wm.progress_end()
            context.workspace.status_text_set(None)
            settings_of(context).job_running = False
        if self._job.cancelled:
            self.report({"INFO"}, "meshquilt: cancelled; nothing changed")
            return {"CANCELLED"}
        if self._job.error:
            self.report({"ERROR"}, "meshquilt: %s" % self._job.error)
            return {"CANCELLED"}
        return self._apply(context, self._job.result)


def still_there(obj):
    """Whether a Blender object captured earlier still exists (it may be deleted while a job runs)."""
    try:
        return obj is not None and obj.name in bpy.data.objects
    except ReferenceError:
        return False


class MESHQUILT_OT_create(JobOperator, bpy.types.Operator):
    """Quilt the active mesh with the swatch; Esc cancels and leaves the scene as it was"""
    bl_idname = "meshquilt.create"
    bl_label = "Create"
    bl_options = {"REGISTER", "UNDO"}

    _base = None
    _look = None
    _kind = None

    @classmethod
    def poll(cls, context):
        return context.active_object is not None and context.active_object.type == "MESH"

    def _start(self, context):
        self._base = context.active_object
        s = settings_of(context)
        self._look = swatch_look(s.swatch_object) if s.swatch_object else None
        self._kind = None if s.swatch_object else s.swatch_kind
        return make_job(context, self._base).start()

    def _apply(self, context, result):
        if not still_there(self._base):
            self.report({"WARNING"}, "meshquilt: the base was deleted while quilting; nothing added")
            return {"CANCELLED"}
        obj = add_result_object(context, self._base, result, look=self._look, kind=self._kind)
        remember_job(obj, context)
        self.report({"INFO"}, "meshquilt: %d faces in %s" % (len(result["faces"]), obj.name))
        return {"FINISHED"}


# The panel's settings a result remembers, so that Update can show and re-run its job.
JOB_SETTINGS = ("swatch_kind", "small", "scale", "seed", "minimize_distortion", "shell_height")


def remember_job(obj, context):
    """The job's settings on the result, a few numbers and names (never meshes)."""
    s = settings_of(context)
    obj["meshquilt_job"] = {name: getattr(s, name) for name in JOB_SETTINGS}
    obj["meshquilt_job"]["swatch_object"] = s.swatch_object.name if s.swatch_object else ""
    obj["meshquilt_job"]["guide_object"] = s.guide_object.name if s.guide_object else ""


def is_result(obj):
    return obj is not None and "meshquilt_job" in obj


class MESHQUILT_OT_recall(bpy.types.Operator):
    """Put the active result's settings back in the panel, to change them before Update"""
    bl_idname = "meshquilt.recall"
    bl_label = "Recall its settings"
    bl_options = {"REGISTER", "UNDO"}

    @classmethod
    def poll(cls, context):
        return is_result(context.active_object)

    def execute(self, context):
        s, job = settings_of(context), context.active_object["meshquilt_job"]
        for name in JOB_SETTINGS:
            setattr(s, name, job[name])
        s.swatch_object = bpy.data.objects.get(job["swatch_object"]) if job["swatch_object"] else None
        s.guide_object = bpy.data.objects.get(job["guide_object"]) if job["guide_object"] else None
        return {"FINISHED"}


class MESHQUILT_OT_update(JobOperator, bpy.types.Operator):
    """Quilt the active result's base again with the panel's settings and put the new texture in
    the result itself (its transform, modifiers and name stay); one undo step, Esc cancels"""
    bl_idname = "meshquilt.update"
    bl_label = "Update"
    bl_options = {"REGISTER", "UNDO"}

    _result = None
    _base = None
    _look = None
    _kind = None

    @classmethod
    def poll(cls, context):
        obj = context.active_object
        return is_result(obj) and obj.get("meshquilt_base") in bpy.data.objects

    def _start(self, context):
        self._result = context.active_object
        self._base = bpy.data.objects[self._result["meshquilt_base"]]
        s = settings_of(context)
        self._look = swatch_look(s.swatch_object) if s.swatch_object else None
        self._kind = None if s.swatch_object else s.swatch_kind
        return make_job(context, self._base).start()

    def _apply(self, context, result):
        if not still_there(self._base) or not still_there(self._result):
            self.report({"WARNING"}, "meshquilt: the base or the result was deleted meanwhile; nothing changed")
            return {"CANCELLED"}
        # Built as a new object, then its mesh moved into the result and the stand-in removed.
        made = add_result_object(context, self._base, result, look=self._look, kind=self._kind)
        old = self._result.data
        self._result.data = made.data
        self._result.data.name = old.name
        if "meshquilt_texture_file" in made:
            self._result["meshquilt_texture_file"] = made["meshquilt_texture_file"]
        bpy.data.objects.remove(made)
        if old.users == 0:
            bpy.data.meshes.remove(old)
        remember_job(self._result, context)
        for other in context.selected_objects:
            other.select_set(False)
        self._result.select_set(True)
        context.view_layer.objects.active = self._result
        self.report({"INFO"}, "meshquilt: %s updated, %d faces" % (self._result.name, len(result["faces"])))
        return {"FINISHED"}


_measures = {}


def _measured(key, compute):
    """compute() once per key: the panel redraws often, and swatches and bases rarely change."""
    if key not in _measures:
        if len(_measures) > 64:
            _measures.clear()
        _measures[key] = compute()
    return _measures[key]


def _area(vertices, faces):
    return 0.5 * np.linalg.norm(np.cross(vertices[faces[:, 1]] - vertices[faces[:, 0]],
                                         vertices[faces[:, 2]] - vertices[faces[:, 0]]), axis=1).sum()


def estimate(context):
    """(faces, elements or None) a Create would make with the panel's settings over the active
    mesh: the swatch's faces (and elements) times the base's area over the swatch's x-y area at
    the scale. None where it cannot be told (no module for a built-in swatch)."""
    s, base = settings_of(context), context.active_object
    if s.swatch_object:
        swatch_key = ("object", s.swatch_object.name, len(s.swatch_object.data.polygons))

        def measure_swatch():
            vertices, faces = mesh_arrays(s.swatch_object)
            return len(faces), None, np.sort(np.ptp(vertices, axis=0))
    else:
        module = quilt_job.import_module(preferences(context).module_path if preferences(context) else "")
        if module is None:
            return None
        swatch_key = ("kind", s.swatch_kind, s.small)

        def measure_swatch():
            made = module.swatch(s.swatch_kind, preset="small" if s.small else "default")
            return len(made.faces), len(np.unique(made.element)), np.sort(np.ptp(made.vertices, axis=0))
    faces, elements, extent = _measured(swatch_key, measure_swatch)
    area, diagonal = _measured(("base", base.name, base.data.name, len(base.data.polygons)),
                               lambda: (lambda v, f: (_area(v, f), np.linalg.norm(np.ptp(v, axis=0))))(
                                   *mesh_arrays(base)))
    if faces == 0 or extent[2] <= 0.0 or extent[1] <= 0.0:
        return None
    factor = s.scale * diagonal / extent[2]  # the longer side becomes scale x the diagonal
    copies = area / (extent[1] * extent[2] * factor * factor)
    return int(faces * copies), (int(elements * copies) if elements else None)


def image_array(image):
    """A Blender image's pixels as an (H, W, 3) array in [0, 1], row 0 at the top (Blender keeps
    the bottom row first); 8-bit images as stored (sRGB), as the command line reads a PNG."""
    width, height = image.size
    pixels = np.empty(width * height * 4, dtype=np.float32)
    image.pixels.foreach_get(pixels)
    return np.clip(pixels.reshape(height, width, 4)[::-1, :, :3].astype(np.float64), 0.0, 1.0)


def srgb_to_linear(c):
    return np.where(c <= 0.04045, c / 12.92, ((c + 0.055) / 1.055) ** 2.4)


def add_painted_object(context, base, result, name):
    """The painted (or raised) base as a new object: a painted one with its colours as the point
    colour attribute `meshquilt_colour`, shown by its material; a raised one with each vertex's
    height as the point attribute `meshquilt_height`."""
    obj = add_result_object(context, base, {"vertices": result.vertices, "faces": result.faces}, name)
    mesh = obj.data
    if result.colors is not None:
        colours = np.ones((len(result.vertices), 4))
        colours[:, :3] = srgb_to_linear(result.colors / 255.0)
        attribute = mesh.color_attributes.new("meshquilt_colour", "BYTE_COLOR", "POINT")
        attribute.data.foreach_set("color", colours.ravel())
        material = bpy.data.materials.new(mesh.name)
        material.use_nodes = True
        nodes = material.node_tree.nodes
        colour = nodes.new("ShaderNodeVertexColor")
        colour.layer_name = "meshquilt_colour"
        material.node_tree.links.new(colour.outputs["Color"], nodes["Principled BSDF"].inputs["Base Color"])
        mesh.materials.append(material)
    if result.heights is not None:
        attribute = mesh.attributes.new("meshquilt_height", "FLOAT", "POINT")
        attribute.data.foreach_set("value", np.asarray(result.heights, dtype=np.float64))
    mesh.update()
    return obj


class MESHQUILT_OT_paint(JobOperator, bpy.types.Operator):
    """Colour the active mesh from the image, swept along the guide's field (Turk 2001); with a
    relief height, raise the image's luma over it instead (a new object either way). Esc cancels"""
    bl_idname = "meshquilt.paint"
    bl_label = "Paint from image"
    bl_options = {"REGISTER", "UNDO"}

    _base = None
    _relief = False

    @classmethod
    def poll(cls, context):
        return context.active_object is not None and context.active_object.type == "MESH"

    def _start(self, context):
        s = settings_of(context)
        if s.paint_image is None:
            self.report({"ERROR"}, "meshquilt: choose an image to paint from")
            return None
        if s.paint_image.size[0] == 0:
            self.report({"ERROR"}, "meshquilt: Blender cannot read the image '%s' (%s); use PNG or JPEG"
                        % (s.paint_image.name, s.paint_image.filepath or "no file"))
            return None
        module = module_or_report(self, context, "painting")
        if module is None:
            return None
        self._base = context.active_object
        self._relief = s.relief_height > 0.0
        field = guide_field(s.guide_object, self._base) if s.guide_object else None
        width = s.paint_image.size[0]
        sample_width = s.paint_pixels if 0 < s.paint_pixels < width else 0
        return quilt_job.PaintJob(module, mesh_arrays(self._base), image_array(s.paint_image), s.paint_scale, s.seed,
                                  field=field, relief_height=s.relief_height, sample_width=sample_width).start()

    def _apply(self, context, result):
        if not still_there(self._base):
            self.report({"WARNING"}, "meshquilt: the base was deleted while painting; nothing added")
            return {"CANCELLED"}
        obj = add_painted_object(context, self._base, result, "relief" if self._relief else "painted")
        self.report({"INFO"}, "meshquilt: %d vertices in %s" % (len(result.vertices), obj.name))
        return {"FINISHED"}


def loom_exemplars(module, collection):
    """The exemplar meshes: the collection's mesh objects, or built-in plain, twill 2/2 and 5-end
    satin weaves."""
    if collection is not None:
        objects = [obj for obj in collection.all_objects if obj.type == "MESH"]
        if objects:
            return [mesh_arrays(obj) for obj in objects]
    return [module.swatch("weave", pattern=p, warps=n, wefts=n)
            for p, n in (("plain", 6), ("twill:2/2", 8), ("satin:4/1", 10))]


class MESHQUILT_OT_loom(bpy.types.Operator):
    """Weave the design image at yarn level from the exemplars (Zhao et al. 2012): a new fabric
    object, each warp and weft one closed yarn"""
    bl_idname = "meshquilt.loom"
    bl_label = "Weave"
    bl_options = {"REGISTER", "UNDO"}

    def execute(self, context):
        s = settings_of(context)
        if s.loom_design is None:
            self.report({"ERROR"}, "meshquilt: choose a design image to weave")
            return {"CANCELLED"}
        if s.loom_design.size[0] == 0:
            self.report({"ERROR"}, "meshquilt: Blender cannot read the image '%s' (%s); use PNG"
                        % (s.loom_design.name, s.loom_design.filepath or "no file"))
            return {"CANCELLED"}
        module = module_or_report(self, context, "weaving")
        if module is None:
            return {"CANCELLED"}
        try:
            result = module.loom(image_array(s.loom_design), loom_exemplars(module, s.loom_exemplars),
                                 method=s.loom_method, seed=s.seed, stations=s.loom_stations - s.loom_stations % 2,
                                 sides=s.loom_sides, weaves=s.loom_weaves)
        except module.Error as error:
            self.report({"ERROR"}, "meshquilt: %s" % error)
            return {"CANCELLED"}
        obj = add_result_object(context, None, {"vertices": result.vertices, "faces": result.faces,
                                                "element": result.element}, "fabric", kind="weave")
        obj.location = context.scene.cursor.location
        if result.colors is not None:
            mesh = obj.data
            colours = np.ones((len(result.vertices), 4))
            colours[:, :3] = srgb_to_linear(result.colors / 255.0)
            mesh.color_attributes.new("meshquilt_colour", "BYTE_COLOR", "POINT").data.foreach_set(
                "color", colours.ravel())
        scores = result.stats["loom"]["assignment"]
        self.report({"INFO"}, "meshquilt: %s: %d yarns, %.0f%% of crossings consistent, %.0f%% continuous"
                    % (obj.name, result.stats["elements"], 100 * scores["consistent"],
                       100 * scores["continuous"]))
        return {"FINISHED"}


class MESHQUILT_OT_select(bpy.types.Operator):
    """Select the faces of some elements of a quilted object: by id, by source or at random by share
    (delete them to age the result, Figure 9 of the paper)"""
    bl_idname = "meshquilt.select"
    bl_label = "Select elements"
    bl_options = {"REGISTER", "UNDO"}

    mode: bpy.props.EnumProperty(items=[("RANDOM", "At random", ""), ("ID", "By id", ""), ("SOURCE", "By source", "")])
    value: bpy.props.IntProperty(name="Id or source", default=0)

    @classmethod
    def poll(cls, context):
        obj = context.active_object
        return obj is not None and obj.type == "MESH" and "element" in obj.data.attributes

    def execute(self, context):
        mesh = context.active_object.data
        element = np.empty(len(mesh.polygons), dtype=np.int32)
        mesh.attributes["element"].data.foreach_get("value", element)
        if self.mode == "RANDOM":
            ids = np.unique(element)
            rng = np.random.default_rng(settings_of(context).seed)
            chosen = rng.choice(ids, size=int(round(settings_of(context).select_share * len(ids))), replace=False)
            selected = np.isin(element, chosen)
        elif self.mode == "ID":
            selected = element == self.value
        else:
            source = np.empty(len(mesh.polygons), dtype=np.int32)
            mesh.attributes["source"].data.foreach_get("value", source)
            selected = source == self.value
        mesh.polygons.foreach_set("select", selected)
        mesh.update()
        return {"FINISHED"}


class MESHQUILT_OT_follow_base(bpy.types.Operator):
    """Place the quilted layer over its base as the base is now (posed, sculpted or moved; the same
    vertices and faces), without synthesizing again"""
    bl_idname = "meshquilt.follow_base"
    bl_label = "Follow the base"
    bl_options = {"REGISTER", "UNDO"}

    @classmethod
    def poll(cls, context):
        obj = context.active_object
        return obj is not None and "meshquilt_texture_file" in obj and obj.get("meshquilt_base") in bpy.data.objects

    def execute(self, context):
        obj = context.active_object
        module = module_or_report(self, context, "following the base")
        if module is None:
            return {"CANCELLED"}
        base = bpy.data.objects[obj["meshquilt_base"]]
        try:
            placed = module.embed(load_texture(obj),
                                  mesh_arrays(base, context.evaluated_depsgraph_get()))
        except module.Error as error:
            self.report({"ERROR"}, str(error))
            return {"CANCELLED"}
        if len(placed.vertices) != len(obj.data.vertices):
            self.report({"ERROR"}, "meshquilt: the result was edited; it can no longer follow its base")
            return {"CANCELLED"}
        world_to_local = np.array(obj.matrix_world.inverted())
        local = placed.vertices @ world_to_local[:3, :3].T + world_to_local[:3, 3]
        obj.data.vertices.foreach_set("co", local.ravel())
        obj.data.update()
        return {"FINISHED"}


def swatch_animation(context, module):
    """(rest, frames) of the swatch animation to play: the swatch object's shape keys (rest: its
    basis), or the built-in vine's sway cycle; None when the swatch has none."""
    s = settings_of(context)
    if s.swatch_object:
        keys = s.swatch_object.data.shape_keys
        if keys is None or len(keys.key_blocks) < 2:
            return None
        matrix = np.array(s.swatch_object.matrix_world)

        def world(block):
            co = np.empty(3 * len(block.data))
            block.data.foreach_get("co", co)
            return co.reshape(-1, 3) @ matrix[:3, :3].T + matrix[:3, 3]

        return world(keys.reference_key), [world(b) for b in keys.key_blocks if b != keys.reference_key]
    if s.swatch_kind != "vine":
        return None
    options = {"preset": "small"} if s.small else {}
    return (module.swatch("vine", **options).vertices, module.vine_frames(s.frames, **options))


class MESHQUILT_OT_animate(bpy.types.Operator):
    """Play the swatch's animation on the quilted object as shape keys, one a frame, keyed to play
    in turn: the swatch object's shape keys, or the built-in vine's sway. Elements that would meet
    in some frame are removed first"""
    bl_idname = "meshquilt.animate"
    bl_label = "Animate"
    bl_options = {"REGISTER", "UNDO"}

    @classmethod
    def poll(cls, context):
        obj = context.active_object
        return (obj is not None and obj.type == "MESH" and "origin" in obj.data.attributes
                and "element" in obj.data.attributes and obj.data.shape_keys is None)

    def execute(self, context):
        obj = context.active_object
        module = module_or_report(self, context, "animating")
        if module is None:
            return {"CANCELLED"}
        animation = swatch_animation(context, module)
        if animation is None:
            self.report({"ERROR"}, "meshquilt: the swatch has no animation (shape keys, or the built-in vine)")
            return {"CANCELLED"}
        mesh = obj.data
        vertices = np.empty(3 * len(mesh.vertices))
        mesh.vertices.foreach_get("co", vertices)
        faces = np.empty(3 * len(mesh.polygons), dtype=np.int32)
        mesh.polygons.foreach_get("vertices", faces)
        element = np.empty(len(mesh.polygons), dtype=np.int32)
        mesh.attributes["element"].data.foreach_get("value", element)
        origin = np.empty(len(mesh.vertices), dtype=np.int32)
        mesh.attributes["origin"].data.foreach_get("value", origin)
        result = module.Mesh(vertices.reshape(-1, 3), faces.reshape(-1, 3), element=element, origin=origin)
        try:
            frames, dropped = module.animate(result, *animation)
        except module.Error as error:
            self.report({"ERROR"}, str(error))
            return {"CANCELLED"}
        kept = np.ones(len(mesh.vertices), dtype=bool)
        if len(dropped):
            bm = bmesh.new()
            bm.from_mesh(mesh)
            layer = bm.faces.layers.int["element"]
            gone = [f for f in bm.faces if f[layer] in set(dropped.tolist())]
            used = np.zeros(len(mesh.vertices), dtype=bool)
            used[faces.reshape(-1, 3)[~np.isin(element, dropped)].ravel()] = True
            kept = used
            bmesh.ops.delete(bm, geom=gone, context="FACES_ONLY")
            bmesh.ops.delete(bm, geom=[v for v in bm.verts if not v.link_faces], context="VERTS")
            bm.to_mesh(mesh)
            bm.free()
        obj.shape_key_add(name="Basis", from_mix=False)
        for k, positions in enumerate(frames):
            key = obj.shape_key_add(name="frame_%d" % k, from_mix=False)
            key.data.foreach_set("co", np.asarray(positions)[kept].ravel())
            # Full at its own scene frame (from 1), off at its neighbours: the keys play in turn.
            for frame, value in ((k, 0.0), (k + 1, 1.0), (k + 2, 0.0)):
                key.value = value
                key.keyframe_insert("value", frame=frame)
        context.scene.frame_start, context.scene.frame_end = 1, len(frames)
        self.report({"INFO"}, "meshquilt: %d frames as shape keys; %d elements removed for meeting in some frame"
                    % (len(frames), len(dropped)))
        return {"FINISHED"}


SAMPLES = [("MAIL_SPHERE", "Chain mail sphere", "A UV sphere in the small chain mail"),
           ("WEAVE_TORUS", "Woven torus", "A torus in a plain weave along a guide circle round its hole"),
           ("VINE_PLANE", "Swaying vine", "A subdivided plane under the vine; Create, then Animate")]


def add_sample_scene(context, sample):
    """Adds the sample's base (and guide) at the 3D cursor's scene, sets the panel, and makes the
    base active: ready for Create."""
    s = settings_of(context)
    s.swatch_object, s.guide_object, s.small, s.seed = None, None, True, 1
    if sample == "MAIL_SPHERE":
        bpy.ops.mesh.primitive_uv_sphere_add(segments=48, ring_count=24, radius=1.0)
        s.swatch_kind, s.scale = "chainmail", 0.25
    elif sample == "WEAVE_TORUS":
        bpy.ops.mesh.primitive_torus_add(major_segments=64, minor_segments=24, major_radius=1.0, minor_radius=0.4)
        base = context.active_object
        bpy.ops.curve.primitive_bezier_circle_add(radius=1.4)
        s.guide_object = context.active_object
        s.guide_object.name = "meshquilt_guide"
        context.view_layer.objects.active = base
        base.select_set(True)
        s.swatch_kind, s.scale = "weave", 0.2
    else:
        bpy.ops.mesh.primitive_grid_add(x_subdivisions=16, y_subdivisions=16, size=2.0)
        s.swatch_kind, s.scale, s.frames = "vine", 0.35, 12
    return context.active_object


class MESHQUILT_OT_sample_scene(bpy.types.Operator):
    """Add a sample to start from: a base (and a guide) with the panel's settings for it"""
    bl_idname = "meshquilt.sample_scene"
    bl_label = "Sample scene"
    bl_options = {"REGISTER", "UNDO"}

    sample: bpy.props.EnumProperty(name="Sample", items=SAMPLES)

    def execute(self, context):
        base = add_sample_scene(context, self.sample)
        self.report({"INFO"}, "meshquilt: %s ready; press Create" % base.name)
        return {"FINISHED"}


class MESHQUILT_OT_preview_field(bpy.types.Operator):
    """Show the guidance field over the active mesh as short lines, one per face (the guide's
    strokes spread over the surface, or the default field): an object beside the base, replaced
    on each preview"""
    bl_idname = "meshquilt.preview_field"
    bl_label = "Preview field"
    bl_options = {"REGISTER", "UNDO"}

    @classmethod
    def poll(cls, context):
        return context.active_object is not None and context.active_object.type == "MESH"

    def execute(self, context):
        base = context.active_object
        module = module_or_report(self, context, "the field preview")
        if module is None:
            return {"CANCELLED"}
        s = settings_of(context)
        vertices, faces = mesh_arrays(base)
        try:
            field = guide_field(s.guide_object, base) if s.guide_object else None
            centres, directions = module.guidance((vertices, faces), field=field)
        except module.Error as error:
            self.report({"ERROR"}, str(error))
            return {"CANCELLED"}
        edges = np.linalg.norm(vertices[faces[:, 1]] - vertices[faces[:, 0]], axis=1)
        length = 0.5 * float(np.mean(edges)) if len(edges) else 1.0
        name = base.name + "_field"
        if name in bpy.data.objects:
            bpy.data.objects.remove(bpy.data.objects[name])
        mesh = bpy.data.meshes.new(name)
        ends = np.empty((2 * len(centres), 3))
        ends[0::2], ends[1::2] = centres, centres + length * directions
        mesh.from_pydata(ends.tolist(), [(2 * k, 2 * k + 1) for k in range(len(centres))], [])
        obj = bpy.data.objects.new(name, mesh)
        context.collection.objects.link(obj)
        self.report({"INFO"}, "meshquilt: %d field lines in %s" % (len(centres), name))
        return {"FINISHED"}


class MESHQUILT_OT_follow_frames(bpy.types.Operator):
    """Follow an animated base over the scene's frame range: the layer placed over the base as it
    is at each frame (its evaluated mesh: armature, shape keys, modifiers that keep its vertices),
    one shape key a frame, keyed to play in turn"""
    bl_idname = "meshquilt.follow_frames"
    bl_label = "Follow the base's animation"
    bl_options = {"REGISTER", "UNDO"}

    @classmethod
    def poll(cls, context):
        return MESHQUILT_OT_follow_base.poll(context) and context.active_object.data.shape_keys is None

    def execute(self, context):
        obj = context.active_object
        module = module_or_report(self, context, "following the base")
        if module is None:
            return {"CANCELLED"}
        base = bpy.data.objects[obj["meshquilt_base"]]
        texture = load_texture(obj)
        scene = context.scene
        current = scene.frame_current
        world_to_local = np.array(obj.matrix_world.inverted())
        frames = []
        try:
            for frame in range(scene.frame_start, scene.frame_end + 1):
                scene.frame_set(frame)
                placed = module.embed(texture, mesh_arrays(base, context.evaluated_depsgraph_get()))
                if len(placed.vertices) != len(obj.data.vertices):
                    raise module.Error("meshquilt: the result was edited; it can no longer follow its base")
                frames.append((frame, placed.vertices @ world_to_local[:3, :3].T + world_to_local[:3, 3]))
        except module.Error as error:
            self.report({"ERROR"}, str(error))
            return {"CANCELLED"}
        finally:
            scene.frame_set(current)
        obj.shape_key_add(name="Basis", from_mix=False)
        for frame, local in frames:
            key = obj.shape_key_add(name="frame_%d" % frame, from_mix=False)
            key.data.foreach_set("co", local.ravel())
            for at, value in ((frame - 1, 0.0), (frame, 1.0), (frame + 1, 0.0)):
                key.value = value
                key.keyframe_insert("value", frame=at)
        self.report({"INFO"}, "meshquilt: the layer follows the base over %d frames" % len(frames))
        return {"FINISHED"}


class VIEW3D_PT_meshquilt(bpy.types.Panel):
    bl_space_type = "VIEW_3D"
    bl_region_type = "UI"
    bl_category = "meshquilt"
    bl_label = "meshquilt"

    def draw(self, context):
        layout = self.layout
        layout.use_property_split = True
        layout.operator_menu_enum(MESHQUILT_OT_sample_scene.bl_idname, "sample", text="Sample scene")
        obj = context.active_object
        if is_result(obj):
            layout.label(text="Result of " + obj.get("meshquilt_base", "?"), icon="MOD_ARRAY")
            row = layout.row(align=True)
            row.operator(MESHQUILT_OT_recall.bl_idname, text="Recall")
            row.operator(MESHQUILT_OT_update.bl_idname)
            return
        s = settings_of(context)
        if s.job_running:
            row = layout.row()
            row.enabled = False
            row.prop(s, "job_progress", text="Quilting", slider=True)
            layout.label(text="Esc to cancel", icon="CANCEL")
            return
        layout.label(text="Base: " + (obj.name if obj else "none"), icon="MESH_DATA")
        made = estimate(context) if obj is not None and obj.type == "MESH" else None
        if made:
            faces, elements = made
            pace = _measures.get("faces_per_second")
            layout.label(text="About %s faces%s" % (format(faces, ","), ", %.0f s" % (faces / pace) if pace else ""))
            if elements:
                layout.label(text="About %s elements" % format(elements, ","))
        layout.operator(MESHQUILT_OT_create.bl_idname)


class MeshquiltSubPanel:
    bl_space_type = "VIEW_3D"
    bl_region_type = "UI"
    bl_category = "meshquilt"
    bl_parent_id = "VIEW3D_PT_meshquilt"


class VIEW3D_PT_meshquilt_swatch(MeshquiltSubPanel, bpy.types.Panel):
    bl_label = "Swatch"

    def draw(self, context):
        s, layout = settings_of(context), self.layout
        layout.use_property_split = True
        layout.prop(s, "swatch_object", text="Object")
        if not s.swatch_object:
            layout.prop(s, "swatch_kind")
            layout.prop(s, "small")


class VIEW3D_PT_meshquilt_placement(MeshquiltSubPanel, bpy.types.Panel):
    bl_label = "Placement"

    def draw(self, context):
        s, layout = settings_of(context), self.layout
        layout.use_property_split = True
        layout.prop(s, "scale")
        layout.prop(s, "seed")
        layout.prop(s, "shell_height", text="Height")
        layout.use_property_split = False
        layout.prop(s, "minimize_distortion")


class VIEW3D_PT_meshquilt_field(MeshquiltSubPanel, bpy.types.Panel):
    bl_label = "Field"
    bl_options = {"DEFAULT_CLOSED"}

    def draw(self, context):
        s, layout = settings_of(context), self.layout
        row = layout.row(align=True)
        row.prop(s, "guide_object")
        row.operator(MESHQUILT_OT_preview_field.bl_idname, text="", icon="ORIENTATION_NORMAL")


class VIEW3D_PT_meshquilt_result(MeshquiltSubPanel, bpy.types.Panel):
    bl_label = "Result"
    bl_options = {"DEFAULT_CLOSED"}

    def draw(self, context):
        s, layout = settings_of(context), self.layout
        layout.operator(MESHQUILT_OT_follow_base.bl_idname)
        layout.operator(MESHQUILT_OT_follow_frames.bl_idname)
        row = layout.row(align=True)
        row.operator(MESHQUILT_OT_animate.bl_idname)
        if not s.swatch_object and s.swatch_kind == "vine":
            row.prop(s, "frames")
        row = layout.row(align=True)
        row.prop(s, "select_share")
        row.operator(MESHQUILT_OT_select.bl_idname, text="Select").mode = "RANDOM"


class VIEW3D_PT_meshquilt_paint(MeshquiltSubPanel, bpy.types.Panel):
    bl_label = "Paint"
    bl_options = {"DEFAULT_CLOSED"}

    def draw(self, context):
        s, layout = settings_of(context), self.layout
        layout.template_ID(s, "paint_image", open="image.open")
        layout.use_property_split = True
        layout.prop(s, "paint_scale")
        layout.prop(s, "paint_pixels")
        layout.prop(s, "relief_height")
        layout.operator(MESHQUILT_OT_paint.bl_idname)


class VIEW3D_PT_meshquilt_loom(MeshquiltSubPanel, bpy.types.Panel):
    bl_label = "Loom"
    bl_options = {"DEFAULT_CLOSED"}

    def draw(self, context):
        s, layout = settings_of(context), self.layout
        layout.template_ID(s, "loom_design", open="image.open")
        layout.use_property_split = True
        layout.prop(s, "loom_exemplars")
        layout.prop(s, "loom_method")
        layout.prop(s, "loom_weaves")
        layout.prop(s, "loom_sides")
        layout.prop(s, "loom_stations")
        layout.operator(MESHQUILT_OT_loom.bl_idname)


classes = (MeshquiltPreferences, MeshquiltSettings, MESHQUILT_OT_create, MESHQUILT_OT_update, MESHQUILT_OT_recall,
           MESHQUILT_OT_select, MESHQUILT_OT_follow_base, MESHQUILT_OT_preview_field, MESHQUILT_OT_animate,
           MESHQUILT_OT_sample_scene, MESHQUILT_OT_follow_frames, MESHQUILT_OT_paint, VIEW3D_PT_meshquilt,
           VIEW3D_PT_meshquilt_swatch, VIEW3D_PT_meshquilt_placement, VIEW3D_PT_meshquilt_field,
           VIEW3D_PT_meshquilt_result, VIEW3D_PT_meshquilt_paint, MESHQUILT_OT_loom, VIEW3D_PT_meshquilt_loom)


def register():
    for cls in classes:
        bpy.utils.register_class(cls)
    bpy.types.Scene.meshquilt = bpy.props.PointerProperty(type=MeshquiltSettings)


def unregister():
    del bpy.types.Scene.meshquilt
    for cls in reversed(classes):
        bpy.utils.unregister_class(cls)
