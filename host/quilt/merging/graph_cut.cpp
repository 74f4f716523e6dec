#include "quilt/merging/graph_cut.h"

#include <cmath>
#include <string>

// Boost.Graph's BK implementation trips GCC's maybe-uninitialized analysis on its iterators.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/boykov_kolmogorov_max_flow.hpp>
#pragma GCC diagnostic pop

#include "core/error.h"

namespace meshquilt {
namespace {

using Traits = boost::adjacency_list_traits<boost::vecS, boost::vecS, boost::directedS>;
using FlowGraph = boost::adjacency_list<
    boost::vecS, boost::vecS, boost::directedS,
    boost::property<boost::vertex_index_t, long,
                    boost::property<boost::vertex_color_t, boost::default_color_type,
                                    boost::property<boost::vertex_distance_t, long,
                                                    boost::property<boost::vertex_predecessor_t,
                                                                    Traits::edge_descriptor>>>>,
    boost::property<boost::edge_capacity_t, double,
                    boost::property<boost::edge_residual_capacity_t, double,
                                    boost::property<boost::edge_reverse_t, Traits::edge_descriptor>>>>;

void check_capacity(double c, const char* what, size_t index) {
  if (std::isnan(c) || c < 0.0)
    throw InputError("minimum_cut: " + std::string(what) + " " + std::to_string(index) +
                         " has a negative or NaN capacity",
                     ErrorKind::invalid_option);
}

}  // namespace

CutResult minimum_cut(const CutGraph& graph) {
  const int32_t n = graph.num_nodes;
  if (n < 0 || graph.weights.size() != graph.edges.size() ||
      graph.source_caps.size() != static_cast<size_t>(n) || graph.sink_caps.size() != static_cast<size_t>(n))
    throw InputError("minimum_cut: array sizes do not match num_nodes/edges", ErrorKind::invalid_option);

  // Every finite cut costs at most the sum of all finite capacities, so anything above it acts
  // as infinity without overflowing the solver's arithmetic.
  double finite_sum = 0.0;
  for (size_t e = 0; e < graph.edges.size(); ++e) {
    check_capacity(graph.weights[e], "edge", e);
    const auto [u, v] = graph.edges[e];
    if (u < 0 || v < 0 || u >= n || v >= n || u == v)
      throw InputError("minimum_cut: edge " + std::to_string(e) + " has an invalid end node",
                       ErrorKind::invalid_option);
    if (std::isfinite(graph.weights[e])) finite_sum += graph.weights[e];
  }
  for (int32_t i = 0; i < n; ++i) {
    check_capacity(graph.source_caps[i], "source link of node", i);
    check_capacity(graph.sink_caps[i], "sink link of node", i);
    if (std::isinf(graph.source_caps[i]) && std::isinf(graph.sink_caps[i]))
      throw InputError("minimum_cut: node " + std::to_string(i) + " is linked to both terminals with infinite capacity",
                       ErrorKind::invalid_option);
    if (std::isfinite(graph.source_caps[i])) finite_sum += graph.source_caps[i];
    if (std::isfinite(graph.sink_caps[i])) finite_sum += graph.sink_caps[i];
  }
  const double infinite = 2.0 * finite_sum + 1.0;
  auto finite = [&](double c) { return std::isinf(c) ? infinite : c; };

  FlowGraph g(static_cast<size_t>(n) + 2);
  const auto source = static_cast<Traits::vertex_descriptor>(n);
  const auto sink = static_cast<Traits::vertex_descriptor>(n + 1);
  auto capacity = get(boost::edge_capacity, g);
  auto reverse = get(boost::edge_reverse, g);
  // Each link is a pair of opposite arcs that are each other's reverse; an undirected edge gives
  // both arcs the capacity, a terminal link only the arc leaving SOURCE / entering SINK.
  auto add_pair = [&](Traits::vertex_descriptor a, Traits::vertex_descriptor b, double ab, double ba) {
    const auto e1 = add_edge(a, b, g).first;
    const auto e2 = add_edge(b, a, g).first;
    capacity[e1] = ab;
    capacity[e2] = ba;
    reverse[e1] = e2;
    reverse[e2] = e1;
  };
  for (size_t e = 0; e < graph.edges.size(); ++e) {
    if (graph.weights[e] <= 0.0) continue;
    const double w = finite(graph.weights[e]);
    add_pair(graph.edges[e][0], graph.edges[e][1], w, w);
  }
  for (int32_t i = 0; i < n; ++i) {
    if (graph.source_caps[i] > 0.0) add_pair(source, i, finite(graph.source_caps[i]), 0.0);
    if (graph.sink_caps[i] > 0.0) add_pair(i, sink, finite(graph.sink_caps[i]), 0.0);
  }

  CutResult result;
  result.value = boost::boykov_kolmogorov_max_flow(g, source, sink);
  auto color = get(boost::vertex_color, g);
  result.source_side.resize(n);
  // After the run the SOURCE search tree (black) is exactly the set reachable from SOURCE in
  // the residual graph: the source side of a minimum cut.
  for (int32_t i = 0; i < n; ++i) result.source_side[i] = get(color, i) == boost::black_color ? 1 : 0;
  return result;
}

}  // namespace meshquilt
