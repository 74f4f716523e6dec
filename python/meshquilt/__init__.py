"""meshquilt: grows 3D geometric textures (chain mail, weaves, fruit, vines) over planes and
triangle meshes by mesh quilting (Zhou et al. 2006), from Python, with numpy in and out.

    import meshquilt
    mail = meshquilt.swatch("chainmail", preset="small")
    result = meshquilt.synth(mail, plane=(2, 2), seed=1)
    result.vertices, result.faces, result.element, result.source, result.stats

Errors raise meshquilt.Error with the command line's one-line message; a CancelToken passed as
`cancel` stops a job between stages (meshquilt.Cancelled), and nothing half-made is returned.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Callable, Dict, List, Optional, Sequence, Tuple, Union

import numpy as np

from . import _meshquilt
from ._meshquilt import CancelToken, Cancelled, Error

__all__ = ["Mesh", "Result", "Animation", "CancelToken", "Cancelled", "Error", "swatch", "swatch_kinds", "synth", "guidance", "paint", "relief",
           "vine_frames", "loom",
           "animate",
           "inspect", "render", "edit", "read", "write", "embed"]


@dataclass
class Mesh:
    """A triangle mesh: vertices (N, 3) float64, faces (M, 3) int32, and per face the element id
    and (for quilted results) the swatch element it was copied from."""

    vertices: np.ndarray
    faces: np.ndarray
    element: Optional[np.ndarray] = None
    source: Optional[np.ndarray] = None
    origin: Optional[np.ndarray] = None
    colors: Optional[np.ndarray] = None  # per vertex, (N, 3) uint8 sRGB, for painted bases


@dataclass
class Result(Mesh):
    """A synthesized texture: the mesh and what the engine reports about it (`stats`)."""

    stats: Dict[str, Any] = field(default_factory=dict)
    texture: Optional[bytes] = None  # with keep_texture over a base: the layer in texture space (.mqt bytes)
    heights: Optional[np.ndarray] = None  # relief: (N,) each vertex's displacement along the base's smooth normal
    assignment: Optional[np.ndarray] = None  # loom: (H, W, 3) exemplar, warp, weft of each crossing's block


MeshLike = Union[Mesh, Tuple[Any, Any]]
#: Directions drawn over a base: (points, directions), two (K, 3) arrays.
Field = Tuple[Any, Any]


def _arrays(mesh: MeshLike, what: str) -> Tuple[np.ndarray, np.ndarray]:
    if isinstance(mesh, Mesh):
        vertices, faces = mesh.vertices, mesh.faces
    else:
        try:
            vertices, faces = mesh
        except (TypeError, ValueError):
            raise TypeError(f"{what}: expected a Mesh or a (vertices, faces) pair") from None
    vertices = np.ascontiguousarray(vertices, dtype=np.float64)
    faces = np.ascontiguousarray(faces, dtype=np.int32)
    return vertices, faces


def _field_arrays(field: Optional[Field]) -> Tuple[Optional[np.ndarray], Optional[np.ndarray]]:
    if field is None:
        return None, None
    points, directions = field
    return (np.ascontiguousarray(points, dtype=np.float64).reshape(-1, 3),
            np.ascontiguousarray(directions, dtype=np.float64).reshape(-1, 3))


def _colors(mesh: MeshLike) -> Optional[np.ndarray]:
    colors = getattr(mesh, "colors", None)
    return None if colors is None else np.ascontiguousarray(colors, np.uint8)


def _mesh(d: dict, cls=Mesh, **extra) -> Mesh:
    return cls(vertices=d["vertices"], faces=d["faces"], element=d.get("element"), source=d.get("source"),
               origin=d.get("origin"), colors=d.get("colors"), **extra)


def swatch(kind: str, preset: str = "default", seed: int = 1, **options: Any) -> Mesh:
    """A built-in swatch: "chainmail", "weave" (pattern="plain" | "twill:M/N" | "satin:M/N"), "wire",
    "fruit", "vine", "nuts" or "heightfield", with the options of `meshquilt swatch KIND`
    (underscores for dashes; see swatch_kinds()). preset="small" gives test-sized swatches."""
    return _mesh(_meshquilt.swatch(kind, preset, seed, **options))


def swatch_kinds() -> list:
    """The built-in swatch kinds, as `swatch` and `meshquilt swatch KIND` take them: per kind its
    name, help, whether the seed changes it, its options (name, type, help, choices) and their
    values under the default and the small preset."""
    return _meshquilt.swatch_kinds()


def synth(swatch: Optional[MeshLike] = None, *, plane: Optional[Tuple[float, float]] = None,
          base: Optional[MeshLike] = None, scale: float = 0.1, seed: int = 1, backend: str = "auto",
          cells: int = 16, cleanup: bool = True, fill_margin: float = 0.5, symmetry: int = 0,
          shell_height: float = 0.0, embed: str = "shell", per_patch_charts: bool = False,
          minimize_distortion: bool = True, keep_texture: bool = False,
          progress: Optional[Callable[[float, float], None]] = None, cancel: Optional[CancelToken] = None,
          field: Optional[Field] = None, size_hold: float = 0.1,
          cone_spread: float = 1.5625) -> Result:
    """Grows the swatch (default: the built-in chain mail) over a plane of `plane` = (width, height)
    swatch extents, or over `base` at `scale` (the swatch's longer side over the base's bounding-box
    diagonal), as `meshquilt synth` does with the same options: the same seed gives the same
    vertices and faces. minimize_distortion=False is synth's --no-distortion-min. keep_texture
    (over a base) also returns the layer in texture space, the bytes of `--write-texture`'s file,
    for `embed` over the base posed or edited. `field` = (points, directions), two (K, 3) arrays:
    directions drawn over the base, each held at the base vertex nearest its point (synth's
    --field file with `point` entries); see `guidance`. fill_margin is synth's --fill-margin (0:
    every element through the patch step), size_hold synth's --size-hold, cone_spread its --cone-spread. `progress(share, seconds_left)` is called once a
    repeating pattern is filled and after each patch (seconds_left is -1 until something is
    covered); raising in it cancels the job. The engine runs without the GIL. Swatch and base are
    repaired as the command line repairs files (winding, duplicates, T-junctions...);
    stats["repairs"] counts what was done."""
    if (plane is None) == (base is None):
        raise TypeError("synth: give plane=(width, height) or base=(vertices, faces)")
    sv = sf = bv = bf = None
    if swatch is not None:
        sv, sf = _arrays(swatch, "swatch")
    if base is not None:
        bv, bf = _arrays(base, "base")
    fp, fd = _field_arrays(field)
    d = _meshquilt.synth(sv, sf, None if plane is None else (float(plane[0]), float(plane[1])), bv, bf, scale, seed,
                         backend, cells, cleanup, fill_margin, symmetry, shell_height, embed, per_patch_charts,
                         minimize_distortion, keep_texture, progress, cancel, fp, fd, size_hold=float(size_hold),
                         cone_spread=float(cone_spread))
    return _mesh(d, Result, stats=d["stats"], texture=d.get("texture"))


def guidance(base: MeshLike, field: Optional[Field] = None) -> Tuple[np.ndarray, np.ndarray]:
    """The guidance field synth spreads over `base` from `field` (or its default without one):
    (centres, directions), per face of the welded base its centroid and the field there, unit and
    tangent, for drawing it as short lines before quilting."""
    bv, bf = _arrays(base, "base")
    fp, fd = _field_arrays(field)
    return _meshquilt.guidance(bv, bf, fp, fd)


def paint(base: MeshLike, image: Any, *, scale: float = 0.25, pixels_per_unit: float = 0.0, window: int = 7,
          passes: int = 2, coherence: float = 2.0, seed: int = 1, backend: str = "auto",
          progress: Optional[Callable[[float, float], None]] = None, cancel: Optional[CancelToken] = None,
          field: Optional[Field] = None, sample_width: int = 0) -> Result:
    """Colours `base` from an image sample as `meshquilt paint` does (Turk 2001, swept along synth's
    field): `image` an (H, W, 3) array of colours in [0, 1], row 0 at the top; `scale` the sample's
    width over the base's bounding-box diagonal, or `pixels_per_unit` given; `coherence` the weight
    against a sample position few neighbours propose (as `--coherence`); `sample_width` > 0 shrinks
    the image to that many pixels across first (as `--sample-width`). Returns the base
    refined until a vertex falls every sample pixel, its `colors` (N, 3) uint8 and `stats`; the
    same seed gives the same colours as the command line on either back end. `progress(share,
    seconds_left)` and `cancel` work as synth's."""
    bv, bf = _arrays(base, "base")
    fp, fd = _field_arrays(field)
    d = _meshquilt.paint(bv, bf, np.ascontiguousarray(image, dtype=np.float64), scale, pixels_per_unit, window, passes,
                         coherence, seed, backend, progress, cancel, fp, fd, sample_width)
    return _mesh(d, Result, stats=d["stats"])


def relief(base: MeshLike, heights: Any = None, *, height: float = 0.0, model: Optional[MeshLike] = None,
           region: Optional[Sequence[float]] = None, smoothing: float = 0.0, pixels: int = 32, scale: float = 0.25,
           pixels_per_unit: float = 0.0, window: int = 7, passes: int = 2, coherence: float = 2.0, seed: int = 1,
           backend: str = "auto", clearance: float = 0.4, progress: Optional[Callable[[float, float], None]] = None,
           cancel: Optional[CancelToken] = None, field: Optional[Field] = None, sample_width: int = 0) -> Result:
    """Raises a relief over `base` as `meshquilt relief` does: from `heights`, an (H, W) array (or
    (H, W, 3), read by its luma) in [0, 1] with white high, raised by `height` base units; or from
    `model`'s detail (it minus its copy smoothed over `smoothing` model units), over `region`
    (x, y, z, radius in model units, or round its richest detail) flattened into `pixels` a side,
    at its own height scaled as its width is unless `height` is given; `sample_width` shrinks
    `heights` as paint's does. Returns the base refined
    and raised, `heights` (N,) each vertex's displacement along the base's smooth normal, and
    `stats`; the same seed gives the command line's vertices on either back end. `progress` and
    `cancel` work as synth's."""
    bv, bf = _arrays(base, "base")
    fp, fd = _field_arrays(field)
    mv = mf = None
    if model is not None:
        mv, mf = _arrays(model, "model")
    image = None if heights is None else np.ascontiguousarray(heights, dtype=np.float64)
    d = _meshquilt.relief(bv, bf, image, height, mv, mf, None if region is None else [float(x) for x in region],
                          smoothing, pixels, scale, pixels_per_unit, window, passes, coherence, seed, backend,
                          clearance, progress, cancel, fp, fd, sample_width)
    return _mesh(d, Result, stats=d["stats"], heights=d["heights"])


def vine_frames(count: int, preset: str = "default", seed: int = 1, **options: Any) -> List[np.ndarray]:
    """`count` frames of one sway cycle of `swatch("vine", preset, seed, **options)`: its vertex
    positions per frame, (S, 3) arrays, as `meshquilt swatch vine --frames` writes them."""
    return list(_meshquilt.vine_frames(count, preset, seed, **options))


@dataclass
class Animation:
    """A swatch animation played on a result: positions per frame, (V, 3) arrays; the element ids
    left out for meeting another or themselves in some frame; and the figures `meshquilt animate
    --stats` writes. Unpacks as (frames, dropped)."""

    frames: List[np.ndarray]
    dropped: np.ndarray
    stats: Dict[str, Any] = field(default_factory=dict)

    def __iter__(self):
        return iter((self.frames, self.dropped))


def animate(result: Mesh, swatch_rest: Any, swatch_frames: Sequence[Any],
            keep_all: bool = False) -> Animation:
    """Plays a swatch animation on a result, as `meshquilt animate` does: each vertex moves by its
    swatch vertex's displacement (from `swatch_rest`, the swatch as synth used it, to each frame)
    turned into its own local frame. `result` needs `element` and `origin` (every synth result
    has them). Returns an Animation: positions per frame, the element ids that meet another or
    themselves in some frame (left out by the command; none with keep_all), and its stats."""
    if result.element is None or result.origin is None:
        raise TypeError("animate: the result needs per-face element ids and per-vertex origins")
    vertices, faces = _arrays(result, "animate")
    rest = np.ascontiguousarray(swatch_rest, dtype=np.float64).reshape(-1, 3)
    frames = [np.ascontiguousarray(f, dtype=np.float64).reshape(-1, 3) for f in swatch_frames]
    d = _meshquilt.animate(vertices, faces, np.ascontiguousarray(result.element, np.int32),
                           np.ascontiguousarray(result.origin, np.int32), rest, frames, keep_all)
    return Animation(list(d["frames"]), np.asarray(d["dropped"], dtype=np.int32), d["stats"])


def loom(design: Any, exemplars: Sequence[MeshLike], *, method: str = "structured", seed: int = 1,
         stations: int = 8, sides: int = 8, weaves: str = "", warp_colors: Any = None, weft_colors: Any = None,
         assignment_only: bool = False) -> Result:
    """Weaves a design from woven exemplar meshes as `meshquilt loom` does (Zhao et al. 2012).
    `design`: an (H, W) bool array (True where the warp, column c, lies over the weft, row r), or
    an image as paint takes one ((H, W) grey or (H, W, 3) colours in [0, 1]; dark where the warp
    lies over), row 0 at the top; with `weaves` ("RRGGBB=plain,RRGGBB=twill:2/2,...") its
    colours name weaves. `warp_colors` / `weft_colors`: (1, N, 3) / (M, 1, 3) images colouring
    the yarns. Returns the fabric (warp c is element c, weft r element W + r; `colors` with
    yarn colours) with `stats` (`loom --stats`'s keys) and `assignment`, an (H, W, 3) int array
    of each crossing's block: exemplar, warp, weft. With assignment_only the mesh is empty."""
    image = np.asarray(design)
    if image.dtype == np.bool_:
        image = np.where(image, 0.0, 1.0)
    meshes = []
    for k, mesh in enumerate(exemplars):
        vertices, faces = _arrays(mesh, "exemplar %d" % k)
        element = getattr(mesh, "element", None)
        meshes.append((vertices, faces, None if element is None else np.ascontiguousarray(element, np.int32)))
    colours = [None if c is None else np.ascontiguousarray(c, dtype=np.float64) for c in (warp_colors, weft_colors)]
    d = _meshquilt.loom(np.ascontiguousarray(image, dtype=np.float64), meshes, method, seed, stations, sides, weaves,
                        colours[0], colours[1], assignment_only)
    if assignment_only:
        empty = Result(vertices=np.zeros((0, 3)), faces=np.zeros((0, 3), np.int32), stats=d["stats"])
        empty.assignment = d["assignment"]
        return empty
    result = _mesh(d, Result, stats=d["stats"])
    result.assignment = d["assignment"]
    return result


def inspect(mesh: MeshLike) -> Dict[str, Any]:
    """What `meshquilt inspect --json` reports: elements, closed ones, defects, intersecting pairs."""
    vertices, faces = _arrays(mesh, "inspect")
    element = getattr(mesh, "element", None)
    return _meshquilt.inspect(vertices, faces, None if element is None else np.ascontiguousarray(element, np.int32))


def render(mesh: MeshLike, path: str, width: int = 1024, height: int = 768, mode: str = "shaded",
           view: str = "oblique", up: str = "z", around: Optional[Sequence[float]] = None,
           radius: float = 0.0) -> None:
    """Writes a PNG preview as `meshquilt render` does: mode "shaded", "elements" or "colors" (the
    mesh's per-vertex `colors`, as paint returns them), view "oblique", "top", "front" or "side",
    `up` the mesh's axis shown upward ("y" for y-up scans). With `around` (x, y, z), a close-up of
    the elements within `radius` of that point (0: a tenth of the mesh's diagonal), as
    `render --around --radius` draws it."""
    vertices, faces = _arrays(mesh, "render")
    element = getattr(mesh, "element", None)
    _meshquilt.render(vertices, faces, None if element is None else np.ascontiguousarray(element, np.int32), path,
                      width, height, mode, _colors(mesh), view, up,
                      None if around is None else [float(v) for v in around], float(radius))


def edit(mesh: Mesh, *, remove_elements: Sequence[int] = (), remove_sources: Sequence[int] = (),
         keep_sources: Sequence[int] = (), remove_box: Optional[Sequence[float]] = None,
         remove_sphere: Optional[Sequence[float]] = None, age: float = 0.0, seed: int = 1,
         color_by: str = "", palette: str = "") -> Result:
    """Removes elements as `meshquilt edit` does (by id, by source, keeping some sources, inside a
    box (x0, y0, z0, x1, y1, z1) or a sphere (x, y, z, r), or a share at random with `age`); every
    other element stays exactly as it was. `color_by` ("element" or "source") and `palette`
    ("RRGGBB,...") recolour what is kept. The result's `stats` are `edit --stats`'s."""
    if mesh.element is None:
        raise TypeError("edit: the mesh needs per-face element ids")
    vertices, faces = _arrays(mesh, "edit")
    source = None if mesh.source is None else np.ascontiguousarray(mesh.source, np.int32)
    d = _meshquilt.edit(vertices, faces, np.ascontiguousarray(mesh.element, np.int32), source, list(remove_elements),
                        list(remove_sources), list(keep_sources),
                        None if remove_box is None else [float(v) for v in remove_box],
                        None if remove_sphere is None else [float(v) for v in remove_sphere], age, seed, color_by,
                        palette)
    return _mesh(d, Result, stats=d["stats"])


def read(path: str) -> Mesh:
    """Reads a mesh as `meshquilt` does (.obj .ply .off .stl): per-face element ids from the PLY
    `element` property or OBJ groups, else the connected components; sources and per-vertex
    colours where the file has them."""
    return _mesh(_meshquilt.read(path))


def write(mesh: MeshLike, path: str) -> None:
    """Writes a mesh as `meshquilt synth` does, atomically (.ply .obj .off .stl, or .glb for
    Blender and game engines), with its element ids and sources, and its per-vertex `colors`
    where it has them (as `meshquilt paint` writes them)."""
    vertices, faces = _arrays(mesh, "write")
    element = getattr(mesh, "element", None)
    source = getattr(mesh, "source", None)
    _meshquilt.write(vertices, faces, None if element is None else np.ascontiguousarray(element, np.int32),
                     None if source is None else np.ascontiguousarray(source, np.int32), path, _colors(mesh))


def embed(texture: bytes, base: MeshLike, mode: str = "auto") -> Result:
    """Places a layer kept by `synth(..., keep_texture=True)` (or read from a `.mqt` file) over a
    base with the same vertices and faces, moved (a pose, a sculpt), as `meshquilt embed` does:
    over the base it was made on it gives synth's result back exactly. The result's `stats` are
    `embed --stats`'s."""
    vertices, faces = _arrays(base, "base")
    d = _meshquilt.embed(bytes(texture), vertices, faces, mode)
    return _mesh(d, Result, stats=d["stats"])
