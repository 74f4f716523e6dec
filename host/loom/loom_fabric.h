#pragma once
//! A design woven at yarn level (paper 004, Sections 5.3-5.5 on meshes): every crossing copies
//! its assigned exemplar block's two yarn pieces, seams between blocks are closed by moving the
//! pieces' centrelines and cross-sections linearly over each block (the one-dimensional Poisson
//! solve with the seam's mean as boundary value), and each warp and weft is swept as one closed
//! tube from one edge of the design to the other.

#include <array>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <vector>

#include <glm/vec2.hpp>

#include "loom/block_assignment.h"
#include "loom/yarn_profile.h"
#include "core/error.h"
#include "mesh/tri_mesh.h"

namespace meshquilt {

//! Where the crossings lie: crossing (r, c) at origin + r row_step + c column_step; z is up.
struct LoomGrid {
  glm::dvec2 origin{0.0}, row_step{0.0}, column_step{0.0};
  int rows = 0, columns = 0;
};

struct LoomFabric {
  TriMesh mesh;   //!< warp c is element c, weft r element columns + r; closed, outward
  LoomGrid grid;  //!< the fabric spans [0, columns pitch.x] x [0, rows pitch.y]
};

//! A colour per yarn (warps by column, then wefts by row), or none.
using YarnColours = std::vector<std::array<uint8_t, 3>>;

//! Weaves `design` as `assignment` says from `exemplars` (profiled with equal sides), at the first
//! exemplar's pitch; other exemplars are scaled to it. With `colours`, each yarn's vertices take
//! its colour. With `periodic`, the design is one repeat: each yarn ends as it starts, so copies
//! of the fabric side by side continue each other (a swatch for synth).
LoomFabric weave_fabric(const LoomDesign& design, const LoomAssignment& assignment,
                        const std::vector<ExemplarProfiles>& exemplars, const YarnColours& colours = {},
                        bool periodic = false);

//! Where a point of the flat fabric goes (x, y in the fabric's plane; z above its underside), or
//! nothing where it falls off the surface it is draped over.
using FabricPlacement = std::function<std::optional<Vec3>(const Vec3&)>;

//! weave_fabric draped by `place`: each yarn keeps the runs of stations whose rings all land,
//! each run a closed tube of its own (elements numbered in yarn order).
LoomFabric drape_fabric(const LoomDesign& design, const LoomAssignment& assignment,
                        const std::vector<ExemplarProfiles>& exemplars, const FabricPlacement& place,
                        const YarnColours& colours = {}, bool periodic = false);

//! What a streamed fabric holds.
struct LoomFabricFile {
  LoomGrid grid;
  size_t vertices = 0, faces = 0;
};

//! weave_fabric written straight to `file` as binary PLY (the `element` face property), yarn by
//! yarn, without holding the mesh: for fabrics too large to hold twice. The file is replaced
//! atomically. \throw IoError(write_failed); Cancelled through `cancel`.
LoomFabricFile write_fabric_ply(const LoomDesign& design, const LoomAssignment& assignment,
                                const std::vector<ExemplarProfiles>& exemplars, const std::filesystem::path& file,
                                const YarnColours& colours = {}, bool periodic = false,
                                const CancelToken* cancel = nullptr);

}  // namespace meshquilt
