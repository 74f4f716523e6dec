#pragma once
//! Minimum s-t cut of a small undirected graph with terminal links (Boykov-Kolmogorov max-flow,
//! Boost.Graph): the optimizer behind the graph cuts of element merging (Section 2.7 of the mesh
//! quilting paper).

#include <array>
#include <cstdint>
#include <limits>
#include <vector>

namespace meshquilt {

//! Capacity meaning "never cut this link" (the paper's infinite weight).
inline constexpr double kInfiniteCapacity = std::numeric_limits<double>::infinity();

//! An undirected graph with links to SOURCE and SINK.
//! edges        #E node pairs (u, v), u != v, both in [0, num_nodes)
//! weights      #E capacities >= 0 (the same in both directions)
//! source_caps  #num_nodes capacity of the SOURCE-node link (0: none; kInfiniteCapacity allowed)
//! sink_caps    #num_nodes capacity of the node-SINK link (0: none; kInfiniteCapacity allowed)
struct CutGraph {
  int32_t num_nodes = 0;
  std::vector<std::array<int32_t, 2>> edges;
  std::vector<double> weights;
  std::vector<double> source_caps;
  std::vector<double> sink_caps;
};

struct CutResult {
  std::vector<uint8_t> source_side;  //!< #num_nodes: 1 on the SOURCE side of the minimum cut
  double value = 0.0;                //!< total capacity of the cut (finite links only)
};

//! Minimum cut separating SOURCE from SINK. Infinite capacities are replaced by a value above the
//! sum of all finite ones, so they are never cut while a finite cut exists. Nodes that reach
//! neither terminal fall on the SINK side.
//! \throw InputError (invalid_option) for mismatched array sizes, an edge out of range, a negative
//!        or NaN capacity, or a node linked to both terminals with infinite capacity.
CutResult minimum_cut(const CutGraph& graph);

}  // namespace meshquilt
