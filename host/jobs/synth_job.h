#pragma once
//! A synth job as every front end runs it (the CLI, batch, the Python module and through it the
//! Blender add-on): the request with its defaults and checks, its inputs read as synth reads
//! them, the run, and the stats JSON of `synth --stats`. Front ends parse, call and print.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "device.h"
#include "mesh/mesh_repair.h"
#include "mesh/tri_mesh.h"
#include "quilt/quilt_options.h"
#include "shell/shell_embedding.h"
#include "surface/guidance_field.h"
#include "surface/surface_quilting.h"
#include "surface/surface_types.h"

namespace meshquilt {

//! What to grow, where, and how; the defaults are synth's.
struct SynthRequest {
  std::optional<TriMesh> swatch;       //!< as read; none: the built-in chain mail
  std::string swatch_name;             //!< in messages and stats; "" names the built-in one
  std::optional<glm::dvec2> plane;     //!< width and height in swatch extents, or
  std::optional<TriMesh> base;         //!< a base mesh, as read
  std::string base_name = "base";      //!< in messages and stats
  double scale = 0.1;                  //!< the swatch's longer side over the base's diagonal
  uint64_t seed = 1;                   //!< seed of every random choice
  int cells = 16;                      //!< grid cells along the swatch's shorter side
  int max_patches = 0;                 //!< stop after this many patches (0: until covered)
  bool cleanup = true;                 //!< remove elements that could not be made whole
  double fill_margin = 0.5;            //!< QuiltOptions::fill_margin
  int symmetry = 0;                    //!< n of the layout's field; 0: the swatch's own
  double size_hold = 0.1;              //!< SurfaceQuiltOptions::size_hold
  double cone_spread = 1.5625;         //!< SurfaceQuiltOptions::cone_spread
  double shell_height = 0.0;           //!< layer height in base units; 0: the swatch's at scale
  std::string embed = "shell";         //!< shell or normal
  bool shared_layout = true;           //!< patches are windows of one layout of the base
  bool distortion_min = true;          //!< minimize the shell map's stretch
  std::vector<FieldConstraint> field;  //!< directions held at base vertices (prepared base's)
  std::string field_name;              //!< the field's source in stats; "" for the default field
  bool keep_texture = false;           //!< keep the shell map's texture for texture files
  std::filesystem::path grid_folder;   //!< cache of nearest-face grids; empty: none
};

//! The swatch's name in messages and stats: its file, or "built-in chain mail".
std::string synth_swatch_name(const SynthRequest& request);

//! Checks every value of `request` before any work.
//! \throw InputError(invalid_option) naming the option as {name}: neither or both of plane and
//!        base, plane sizes outside (0, 1000], scale outside (0, 10], symmetry not 0, 1, 2 or 4,
//!        a negative or infinite shell height, embed not shell or normal, cells outside 4..256,
//!        a field over a plane.
void check_synth_request(const SynthRequest& request);

//! The request's meshes as synth uses them: the swatch repaired and in its frame, the base
//! repaired and prepared, what was repaired counted.
struct SynthInputs {
  TriMesh swatch, base;
  MeshRepairs swatch_repairs, base_repairs;
};

//! Reads the request's meshes (see SynthInputs) and, over a plane, checks the output against the
//! memory budget. \throw InputError for meshes that cannot be repaired; too_large for a plane
//! beyond the budget.
SynthInputs prepare_synth_inputs(const SynthRequest& request);

//! Bytes a planar job of `width` x `height` swatch extents is expected to need at its peak: the
//! output grows as the swatch's faces times the plane's area. Calibrated on the default job
//! (73,036 faces, 32 MiB peak) and the 304,162-face fruit job (71 MiB): about 170 B a face beyond
//! a fixed part; budgeted at 400 B a face plus 64 MiB for the output, Embree and slack.
double estimate_synth_bytes(const TriMesh& swatch, double width, double height);

//! What a run reports along the way, and may be stopped by.
struct SynthHooks {
  std::function<void(const QuiltProgress&)> progress;
  CancelToken* cancel = nullptr;
  //! Over a base: the base surface and the field the layout follows, once both are known.
  std::function<void(const BaseSurface&, const GuidanceField&)> field_ready;
};

struct SynthOutcome {
  TriMesh mesh;
  std::vector<LocalVertex> local;  //!< texture-space coordinates (over a base)
  ShellTexture shell_texture;      //!< the shell map's texture (with keep_texture)
  //! Every field of `synth --stats` but `output` and the `write` stage; `seconds` is the run's.
  nlohmann::json stats;
};

//! Runs the job on `device`. \throw InputError(invalid_option) when nothing was quilted (every
//! element dropped, or none fitting the base at the scale); Cancelled through hooks.cancel.
SynthOutcome run_synth(const SynthRequest& request, const SynthInputs& inputs, engine::Device& device,
                       const SynthHooks& hooks = {});

}  // namespace meshquilt
