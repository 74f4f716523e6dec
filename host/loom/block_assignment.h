#pragma once
//! Structure-aware assignment of exemplar blocks to a design's crossings (paper 004, Sections
//! 5.3-5.4): the correct yarn on top first, then consistency (the four neighbours agree), then
//! continuity (neighbouring crossings copy neighbouring blocks), by dynamic programming along
//! each warp, randomized by the exemplars' translational symmetries in small blocks.

#include <cstdint>
#include <vector>

#include "swatch/weave_pattern.h"

namespace meshquilt {

//! A binary weave design: crossing (r, c) is row r from the top and column c from the left; 1
//! where the warp (column c) lies over the weft (row r).
struct LoomDesign {
  int rows = 0, columns = 0;
  std::vector<uint8_t> warp_over;  //!< rows x columns, row-major
  bool at(int r, int c) const { return warp_over[static_cast<size_t>(r) * columns + c] != 0; }
};

//! Exemplar u's crossing of warp x and weft y. Design row r + 1 is exemplar weft y - 1 (rows run
//! down the design, wefts up the exemplar, so blocks are copied unmirrored) and column c + 1 is
//! warp x + 1.
struct LoomBlock {
  int32_t exemplar = 0, x = 0, y = 0;
  bool operator==(const LoomBlock&) const = default;
};

enum class AssignmentMethod {
  naive,       //!< any block with the correct yarn on top (Figure 4, top)
  greedy,      //!< the most consistent block, ties at random (Figure 4, middle)
  structured,  //!< the most consistent, then the most continuous along warps, then shifted
};

struct AssignmentOptions {
  AssignmentMethod method = AssignmentMethod::structured;
  uint64_t seed = 1;
  int shift_block = 3;  //!< side of the design blocks shifted together (the paper's m-hat)
  bool periodic = false;  //!< the design repeats: its edges' neighbours wrap around
};

struct LoomAssignment {
  int rows = 0, columns = 0;
  std::vector<LoomBlock> blocks;  //!< rows x columns, row-major
  const LoomBlock& at(int r, int c) const { return blocks[static_cast<size_t>(r) * columns + c]; }
};

//! Assigns a block of `exemplars` to every crossing of `design`. Blocks are taken from each
//! exemplar's interior (all four neighbours inside it).
//! \throw InputError(invalid_option) when the exemplars have no interior block with the warp
//!        (or the weft) on top and the design asks for one.
LoomAssignment assign_blocks(const LoomDesign& design, const std::vector<WeavePattern>& exemplars,
                             const AssignmentOptions& options = {});

//! How well an assignment follows its design, judged from the assignment alone.
struct AssignmentScores {
  double correct = 0.0;     //!< share of crossings with the design's yarn on top
  double consistent = 0.0;  //!< share whose four (present) neighbours all agree
  double continuous = 0.0;  //!< share of neighbouring crossing pairs copying neighbouring blocks
  double continuous_along_warps = 0.0;  //!< the same over pairs along a warp (r, r + 1)
};

//! With `periodic`, the design's edges have their wrapped neighbours.
AssignmentScores score_assignment(const LoomDesign& design, const std::vector<WeavePattern>& exemplars,
                                  const LoomAssignment& assignment, bool periodic = false);

}  // namespace meshquilt
