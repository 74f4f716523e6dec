#include "surface/base_layout.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <unordered_map>

#include "mesh/topology.h"
#include "surface/cone_metric_field.h"

namespace meshquilt {
namespace {

// Bases below this many faces are split until they reach it (at most three times).
constexpr size_t kLayoutFaces = 1000;
// Opposite cones added to the cone metric: at most this many pairs, each this many periods
// from every other cone; its spread within this factor of the smoothest field's counts as even.
constexpr int kMaxConePairs = 32;
constexpr double kConeSeparation = 4.0;
constexpr double kConeSpreadTie = 1.05;
// Where elements run on (yarns), each cone more than the smoothest field's must narrow the
// spread by this factor: over the bunny four more cones for 0.1% left its ears bare (0061).
constexpr double kYarnConeCost = 0.99;

}  // namespace

TriMesh split_faces(const TriMesh& mesh, int levels) {
  TriMesh result = mesh;
  for (int level = 0; level < levels; ++level) {
    TriMesh split;
    split.positions = result.positions;
    std::unordered_map<uint64_t, int32_t> midpoint;
    const auto middle = [&](int32_t a, int32_t b) {
      const auto [it, fresh] = midpoint.emplace(undirected_edge_key(a, b), static_cast<int32_t>(split.positions.size()));
      if (fresh) split.positions.push_back(0.5 * (result.positions[a] + result.positions[b]));
      return it->second;
    };
    split.triangles.reserve(4 * result.triangles.size());
    for (const Tri& t : result.triangles) {
      const int32_t ab = middle(t[0], t[1]), bc = middle(t[1], t[2]), ca = middle(t[2], t[0]);
      split.triangles.push_back({t[0], ab, ca});
      split.triangles.push_back({ab, t[1], bc});
      split.triangles.push_back({ca, bc, t[2]});
      split.triangles.push_back({ab, bc, ca});
    }
    result = std::move(split);
  }
  return result;
}

BaseLayout::BaseLayout(const BaseSurface& base, int symmetry, const std::vector<Vec3>& target,
                       const std::vector<double>& weight, bool drawn,
                       const std::optional<std::array<glm::dvec2, 2>>& lattice, double size_hold, double cone_spread,
                       bool stand_alone)
    : base_(base), lattice_(lattice), size_hold_(size_hold) {
  size_t faces = base.mesh.num_faces();
  while (faces > 0 && faces < kLayoutFaces && levels_ < 3) {
    faces *= 4;
    ++levels_;
  }
  fine_mesh_ = split_faces(base.mesh, levels_);
  fine_ = std::make_unique<BaseSurface>(fine_mesh_);
  const size_t parts = size_t{1} << (2 * levels_);
  std::vector<Vec3> fine_target(fine_mesh_.num_faces());
  std::vector<double> fine_weight(fine_mesh_.num_faces());
  for (size_t f = 0; f < fine_mesh_.num_faces(); ++f) {
    fine_target[f] = target[f / parts];
    fine_weight[f] = weight[f / parts];
  }
  field_ = smoothest_direction_field(*fine_, symmetry, fine_target, fine_weight);
  // Where no one drew a field, the cones that flatten the base more evenly, pairs of them kept
  // apart by a few periods so the pattern closes round each. Area spreads within a few percent
  // do not tell the sizes of placed rings apart, and apart cones close the pattern better: a tie
  // goes to the cone metric, unless it has fewer cones, whose sizes run further past p10 and p90.
  // A yarn ends at every cone: there each cone more must narrow the spread.
  if (!drawn) {
    ConeBound bound{cone_spread, 0.0, lattice_ ? kMaxConePairs : 0};
    if (lattice_)
      bound.separation = kConeSeparation * std::max(glm::length((*lattice_)[0]), glm::length((*lattice_)[1]));
    std::optional<DirectionField> placed = cone_metric_field(*fine_, symmetry, fine_target[0], bound);
    if (placed) {
      const std::vector<int> placed_index = field_indices(*fine_, *placed), smoothest_index = field_indices(*fine_, field_);
      const double placed_spread = *cone_scale_spread(*fine_, placed_index, symmetry);
      const double smoothest_spread = *cone_scale_spread(*fine_, smoothest_index, symmetry);
      const auto count = [](const std::vector<int>& index) {
        return std::count_if(index.begin(), index.end(), [](int k) { return k != 0; });
      };
      const auto more = count(placed_index) - count(smoothest_index);
      const double tie = more < 0                  ? 1.0
                         : stand_alone || more == 0 ? kConeSpreadTie
                                                    : std::pow(kYarnConeCost, static_cast<double>(more));
      if (placed_spread < tie * smoothest_spread) {
        field_ = std::move(*placed);
        scale_spread_ = placed_spread;
      } else {
        scale_spread_ = smoothest_spread;
      }
    }
  }
  layout_ = seamless_layout(*fine_, field_, lattice_, size_hold_);
}

void BaseLayout::resize(double element_scale) {
  layout_ = seamless_layout(*fine_, field_, lattice_, size_hold_, element_scale);
}

LayoutWindow BaseLayout::unfold(const std::vector<int32_t>& faces, int32_t start, const std::vector<int32_t>& corner_vertex,
                                int32_t vertices) const {
  if (levels_ == 0) return unfold_window(*fine_, layout_, faces, start, corner_vertex, vertices);
  const int32_t parts = 1 << (2 * levels_);
  // The base's own vertices keep their local indices; the midpoints get new ones after them.
  std::unordered_map<int32_t, int32_t> local;
  for (size_t k = 0; k < faces.size(); ++k)
    for (int c = 0; c < 3; ++c) local.emplace(base_.mesh.triangles[faces[k]][c], corner_vertex[3 * k + c]);
  int32_t next = vertices;
  std::vector<int32_t> fine_faces, fine_corners;
  fine_faces.reserve(faces.size() * parts);
  fine_corners.reserve(3 * faces.size() * parts);
  for (int32_t f : faces)
    for (int32_t p = 0; p < parts; ++p) {
      fine_faces.push_back(f * parts + p);
      for (int32_t v : fine_mesh_.triangles[f * parts + p]) {
        const auto [it, fresh] = local.emplace(v, next);
        if (fresh) ++next;
        fine_corners.push_back(it->second);
      }
    }
  LayoutWindow fine = unfold_window(*fine_, layout_, fine_faces, start * parts, fine_corners, next);
  LayoutWindow window;
  window.consistent = fine.consistent;
  window.corner_uv.resize(3 * faces.size());
  window.face_turn.resize(faces.size());
  // Corner c of a face lies in part c of it at every level, as that part's corner c.
  const int32_t corner_part = (parts - 1) / 3;
  for (size_t k = 0; k < faces.size(); ++k) {
    window.face_turn[k] = fine.face_turn[k * parts];
    for (int c = 0; c < 3; ++c) window.corner_uv[3 * k + c] = fine.corner_uv[3 * (k * parts + c * corner_part) + c];
  }
  return window;
}

std::vector<std::pair<int32_t, Vec3>> BaseLayout::cone_points() const {
  std::vector<std::pair<int32_t, Vec3>> points;
  for (int32_t v : layout_.cones) {
    const int32_t fine_face = fine_->vertex_faces[v].empty() ? -1 : fine_->vertex_faces[v].front();
    if (fine_face >= 0) points.emplace_back(fine_face >> (2 * levels_), fine_mesh_.positions[v]);
  }
  return points;
}

}  // namespace meshquilt
