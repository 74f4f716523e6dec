"""Jobs off Blender's main thread: a worker thread, a cancel token and the progress the modal
operator shows. Quilting uses the Python module `meshquilt` where it can be imported, else runs
the `meshquilt` executable and reads its PLY back; painting needs the module."""
import json
import os
import subprocess
import sys
import tempfile
import threading
import time

import numpy as np


# Where scripts/blender_addon.sh puts the module inside the add-on.
BUNDLED = os.path.join(os.path.dirname(os.path.abspath(__file__)), "module")


def module_folder(path):
    """`path` as a folder: Blender's "//" relative to the .blend, others relative to the current
    folder; "" stays "" (the preference unset)."""
    if not path:
        return ""
    try:
        import bpy
        path = bpy.path.abspath(path)
    except ImportError:
        pass
    return os.path.abspath(os.path.expanduser(path))


def import_module(path=""):
    """The module `meshquilt`: bundled in the add-on, from `path` (a folder holding the package),
    or from the usual places; None when it is nowhere."""
    for folder in (BUNDLED, module_folder(path)):
        if folder and os.path.isdir(os.path.join(folder, "meshquilt")) and folder not in sys.path:
            sys.path.insert(0, folder)
    try:
        import meshquilt  # noqa: F401
        return meshquilt
    except ImportError:
        return None


def read_binary_ply(path):
    """Vertices, faces, the per-face `element` and `source` and the per-vertex `origin` of a PLY
    that meshquilt wrote."""
    data = open(path, "rb").read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode().split("\n")
    vertex_props, face_props, current, nv, nf = [], [], None, 0, 0
    for line in header:
        words = line.split()
        if words[:1] == ["element"]:
            current = words[1]
            if current == "vertex":
                nv = int(words[2])
            else:
                nf = int(words[2])
        elif words[:1] == ["property"]:
            (vertex_props if current == "vertex" else face_props).append(words[-1])
    types = {"double": "<f8", "int": "<i4", "uchar": "u1"}
    vdtype = np.dtype([(p, "<f8" if p in "xyz" else "<i4") for p in vertex_props])
    vertices = np.frombuffer(data, dtype=vdtype, count=nv, offset=end)
    fields = [("n", "u1"), ("v", "<i4", 3)] + [(p, types["int"]) for p in face_props if p != "vertex_indices"]
    faces = np.frombuffer(data, dtype=np.dtype(fields), count=nf, offset=end + vdtype.itemsize * nv)
    out = {"vertices": np.stack([vertices["x"], vertices["y"], vertices["z"]], axis=1).astype(np.float64),
           "faces": np.ascontiguousarray(faces["v"], dtype=np.int32)}
    for name in ("element", "source"):
        if name in faces.dtype.names:
            out[name] = np.ascontiguousarray(faces[name], dtype=np.int32)
    if "origin" in vertices.dtype.names:
        out["origin"] = np.ascontiguousarray(vertices["origin"], dtype=np.int32)
    return out


class BackgroundJob:
    """Runs `_work` on a worker thread. `share` and `seconds_left` follow its progress; `result`
    holds what it returned when `done` and no `error`, `seconds` how long that took; cancel()
    stops it and leaves `cancelled` set."""

    def __init__(self, module):
        self.module = module
        self.share, self.seconds_left = 0.0, -1.0
        self.seconds = 0.0  # how long _work took
        self.result, self.error, self.cancelled = None, None, False
        self.done = threading.Event()
        self._token = self.module.CancelToken() if self.module else None
        self._process = None
        self._thread = threading.Thread(target=self._run, daemon=True)

    def start(self):
        self._thread.start()
        return self

    def wait(self, timeout=None):
        self.done.wait(timeout)
        return self.done.is_set()

    def cancel(self):
        self.cancelled = True
        if self._token is not None:
            self._token.cancel()
        if self._process is not None and self._process.poll() is None:
            self._process.terminate()

    def _progress(self, share, seconds_left):
        self.share, self.seconds_left = share, seconds_left

    def _run(self):
        begun = time.monotonic()
        try:
            self.result = self._work()
            self.seconds = time.monotonic() - begun
        except Exception as error:  # reported to the operator, which leaves the scene as it was
            if not self.cancelled:
                self.error = str(error)
        finally:
            if self.cancelled:
                self.result = None
            self.done.set()

    def _work(self):
        raise NotImplementedError


class QuiltJob(BackgroundJob):
    """One synthesis: `result` holds vertices, faces, element, source, origin and texture."""

    def __init__(self, base, swatch=None, swatch_kind="chainmail", swatch_options=None, scale=0.15, seed=1,
                 minimize_distortion=True, shell_height=0.0, module_path="", executable="meshquilt", field=None):
        super().__init__(import_module(module_path))
        self.module_path = module_path
        self.base = base  # (vertices, faces) as numpy arrays
        self.field = field  # (points, directions) drawn over the base, or None for the default field
        self.swatch = swatch  # (vertices, faces), or None for a built-in kind
        self.swatch_kind = swatch_kind
        self.swatch_options = dict(swatch_options or {})
        self.scale, self.seed = scale, seed
        self.minimize_distortion, self.shell_height = minimize_distortion, shell_height
        self.executable = executable

    def _work(self):
        if self.module is not None:
            return self._run_module()
        try:
            return self._run_executable()
        except FileNotFoundError:
            raise RuntimeError(
                "neither the Python module (Preferences > Add-ons > meshquilt > Module folder: %s) nor the "
                "executable '%s' was found; install the zip of scripts/blender_addon.sh, or set either "
                "preference" % ("'%s' holds no package meshquilt" % self.module_path if self.module_path else "unset",
                                self.executable)) from None

    def _run_module(self):
        m = self.module
        swatch = self.swatch
        if swatch is None:
            swatch = m.swatch(self.swatch_kind, **self.swatch_options)
        r = m.synth(swatch, base=self.base, scale=self.scale, seed=self.seed,
                    minimize_distortion=self.minimize_distortion, shell_height=self.shell_height,
                    keep_texture=True, progress=self._progress, cancel=self._token, field=self.field)
        return {"vertices": r.vertices, "faces": r.faces, "element": r.element, "source": r.source,
                "origin": r.origin, "texture": r.texture}

    def _run_executable(self):
        with tempfile.TemporaryDirectory() as folder:
            base = os.path.join(folder, "base.off")
            self._write_off(base, *self.base)
            swatch = os.path.join(folder, "swatch.off")
            if self.swatch is not None:
                self._write_off(swatch, *self.swatch)
            else:
                args = [self.executable, "swatch", self.swatch_kind, "-o", os.path.join(folder, "swatch.ply")]
                for key, value in self.swatch_options.items():
                    args += ["--" + key.replace("_", "-"), str(value)]
                subprocess.run(args, check=True, capture_output=True)
                swatch = os.path.join(folder, "swatch.ply")
            out = os.path.join(folder, "out.ply")
            texture = os.path.join(folder, "out.mqt")
            args = [self.executable, "synth", "--swatch", swatch, "--base", base, "--scale", str(self.scale),
                    "--seed", str(self.seed), "--progress", "json", "--write-texture", texture, "--provenance",
                    "-o", out]
            if self.shell_height > 0.0:
                args += ["--shell-height", str(self.shell_height)]
            if not self.minimize_distortion:
                args.append("--no-distortion-min")
            if self.field is not None:
                # The same directions as a field file's `point` entries.
                field = os.path.join(folder, "field.json")
                with open(field, "w") as out:
                    json.dump({"directions": [{"point": [float(x) for x in p], "direction": [float(x) for x in d]}
                                              for p, d in zip(*self.field)]}, out)
                args += ["--field", field]
            # --progress json: one JSON line per patch on stdout (done, total, eta_s).
            self._process = subprocess.Popen(args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
            for line in self._process.stdout:
                try:
                    record = json.loads(line)
                except ValueError:
                    continue
                if record.get("event") == "progress" and record.get("total", 0) > 0:
                    self._progress(min(1.0, record["done"] / record["total"]), record.get("eta_s", -1.0))
            if self._process.wait() != 0:
                message = self._process.stderr.read().strip().splitlines()
                raise RuntimeError(message[-1] if message else "meshquilt synth failed")
            result = read_binary_ply(out)
            result["texture"] = open(texture, "rb").read()
            return result

    @staticmethod
    def _write_off(path, vertices, faces):
        with open(path, "w") as f:
            f.write("OFF\n%d %d 0\n" % (len(vertices), len(faces)))
            for p in vertices:
                f.write("%.17g %.17g %.17g\n" % tuple(p))
            for t in faces:
                f.write("3 %d %d %d\n" % tuple(t))


class PaintJob(BackgroundJob):
    """The module's paint (or, with a relief height, its relief) of `base` from `image`:
    `result` is its Result."""

    def __init__(self, module, base, image, scale, seed, field=None, relief_height=0.0, sample_width=0):
        super().__init__(module)
        self.base, self.image, self.field = base, image, field
        self.scale, self.seed, self.relief_height, self.sample_width = scale, seed, relief_height, sample_width

    def _work(self):
        common = dict(scale=self.scale, seed=self.seed, field=self.field, progress=self._progress, cancel=self._token,
                      sample_width=self.sample_width)
        if self.relief_height > 0.0:
            return self.module.relief(self.base, self.image, height=self.relief_height, **common)
        return self.module.paint(self.base, self.image, **common)
