#pragma once
//! A loom job as every front end runs it: a binary design image and woven exemplars in, the
//! assignment of exemplar blocks to its crossings and the fabric woven from them out, with the
//! stats JSON of `loom --stats` (paper 004).

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <array>
#include <cstdint>

#include "loom/block_assignment.h"
#include "loom/loom_fabric.h"
#include "mesh/tri_mesh.h"
#include "paint/colour_image.h"
#include "render/rgb_image.h"

namespace meshquilt {

//! A design colour and the elementary weave it stands for (the paper's Section 5.2).
struct ColourWeave {
  std::array<uint8_t, 3> colour{};
  WeavePattern pattern;
};

//! "RRGGBB=plain,RRGGBB=twill:2/2,RRGGBB=satin:4/1,RRGGBB=FILE.pbm" (weaves as `swatch weave
//! --pattern` reads them). \throw InputError(invalid_option) "{weaves}: ..." for a bad entry.
std::vector<ColourWeave> parse_colour_weaves(const std::string& text);

struct LoomRequest {
  ColourImage design;                      //!< one pixel a crossing; dark: the warp over the weft
  std::vector<ColourWeave> weaves;         //!< when given, design colours name weaves instead
  ColourImage warp_types, weft_types;      //!< yarn colours: warp c pixel (c, 0), weft r pixel (0, r)
  std::string design_name = "design";      //!< in messages and stats
  std::vector<TriMesh> exemplars;          //!< woven swatch meshes, as read
  std::vector<std::string> exemplar_names;  //!< in messages and stats
  AssignmentMethod method = AssignmentMethod::structured;
  uint64_t seed = 1;
  int stations = 8;  //!< samples along a yarn per pitch
  int sides = 8;     //!< vertices around a yarn
  bool assignment_only = false;  //!< assign blocks, weave nothing
  bool periodic = false;         //!< the design is one repeat: its copies continue each other
  std::optional<TriMesh> base;   //!< a disc to drape the fabric over, as read
  std::string base_name = "base";
  double scale = 0.8;            //!< the fabric's longer side over the base's bounding-box diagonal
  //! When set, the fabric is written there as binary PLY yarn by yarn (write_fabric_ply) instead
  //! of returned: for fabrics too large to hold.
  std::filesystem::path ply_output;
};

//! "naive", "greedy" or "structured". \throw InputError(invalid_option) "{method}: ..." otherwise.
AssignmentMethod parse_assignment_method(const std::string& text);

//! \throw InputError(invalid_option) naming {name}: no exemplar, a scale outside (0, 10], a base
//!        with ply_output or assignment_only, stations outside 2..64 (even),
//!        sides outside 3..64; too_large when the job's estimated memory passes the budget (the
//!        yarns' stations, and unless streamed the mesh: 4 x stations x sides faces a crossing).
void check_loom_request(const LoomRequest& request);

//! The design read from its image: dark (grey < 0.5) where the warp lies over the weft; or, with
//! `weaves`, crossing (r, c) of a pixel of colour X as X's weave reads at warp c, weft -r.
//! \throw InputError(invalid_option) naming `name` and the pixel for a colour `weaves` lacks.
LoomDesign design_of(const ColourImage& image, const std::vector<ColourWeave>& weaves = {},
                     const std::string& name = "design");

struct LoomOutcome {
  LoomDesign design;
  LoomAssignment assignment;
  LoomFabric fabric;    //!< empty mesh with assignment_only or ply_output
  nlohmann::json stats;  //!< `loom --stats` less file names and seconds: `loom`, and with geometry
                         //!< `faces`, `vertices`, `elements` as synth's
};

//! Registers the exemplars, assigns blocks and (unless assignment_only) weaves the fabric.
//! `progress(share)` is called between stages. \throw what register_exemplar and assign_blocks
//! throw, naming the exemplar's file.
LoomOutcome run_loom(const LoomRequest& request, const std::function<void(double)>& progress = {});

//! A false-colour picture of the assignment, as the paper's Figure 4 right column: a hue per
//! exemplar, lighter where the block continues the one above it; `pixels` square a crossing.
RgbImage assignment_picture(const LoomAssignment& assignment, int exemplars, int pixels = 1);

}  // namespace meshquilt
