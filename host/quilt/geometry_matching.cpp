#include "quilt/geometry_matching.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/mat2x2.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "device.h"
#include "matching_cost.h"
#include "mesh/measures.h"
#include "spatial/face_bvh.h"

namespace meshquilt {
namespace {

// rng() % n rather than std::uniform_int_distribution: the latter differs between standard
// libraries, and the same seed must give the same output everywhere.
size_t draw_index(std::mt19937_64& rng, size_t n) { return static_cast<size_t>(rng() % n); }

// The nearest-face grid's shape, in the swatch's mean edge lengths (docs/decisions/0008, 0009):
// small swatches (interlocking rings crowding hundreds of faces into a voxel's reach) get finer
// voxels and longer lists than large ones, whose lists are short and whose grids are large.
constexpr size_t kSmallSwatchFaces = 8192;
constexpr double kSmallVoxel = 0.75, kLargeVoxel = 1.0;
constexpr int kSmallMaxList = 1024, kLargeMaxList = 128;
constexpr double kListReach = 1.5;  // faces listed within this far past the voxel's diagonal
constexpr double kFar = 3.0;        // a point this far costs at least 1 + 3 lambda: lists nothing
constexpr int64_t kMaxVoxels = int64_t{1} << 18;
// Normal bins per octahedron side past kSmallSwatchFaces (docs/decisions/0007): short lists gain
// little from finer bins and pay for them in small groups.
constexpr int kLargeSwatchBinsPerSide = 3;
// Exact evaluations are summed in this many blocks between early-stop tests (docs/decisions/0011).
constexpr size_t kAbandonBlocks = 32;

}  // namespace

GeometryMatcher::GeometryMatcher(engine::Device& device, const TriMesh& swatch, double cell_size,
                                 const MatchingOptions& options)
    : swatch_(swatch), options_(options), cell_size_(cell_size),
      mean_edge_(std::max(mean_edge_length(swatch), 1e-12)), face_spheres_(face_spheres(swatch)),
      face_planes_(face_planes(swatch)) {
  double largest = 0.0;
  for (const Vec3& p : swatch.positions) largest = std::max({largest, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  rounding_ = 1e-12 * largest;
  // With the drivers' lambda = 1 / mean edge, the cap 1 + lambda * reach exceeds what most points
  // cost even where the normals disagree: the bound equals Eq. 2 for most pairs and the host
  // rarely needs the BVH. The grid's shape changes how fast answers come, never the answers
  // (exact costs and their faces, ties to the lower index).
  const double mean_edge = mean_edge_;
  const bool small = swatch.num_faces() <= kSmallSwatchFaces;
  const double voxel = (small ? kSmallVoxel : kLargeVoxel) * mean_edge;
  const int max_list = small ? kSmallMaxList : kLargeMaxList;
  // Each voxel's list grouped by the faces' normal directions (an octahedral grid): most points
  // face away from most groups, which a scan then passes over whole.
  std::vector<Vec3> normals;
  normals.reserve(face_planes_.size());
  for (const FacePlane& plane : face_planes_) normals.push_back(plane.normal);
  normal_bins_ = bin_normals(normals, small ? kMaxBinsPerSide : kLargeSwatchBinsPerSide);
  const NearFaceGridRequest request{voxel,    mean_edge,          kListReach * mean_edge, kFar * mean_edge,
                                    max_list, kMaxVoxels, normal_bins_.bin_of};
  grid_ = cached_near_face_grid(options.grid_folder, swatch, request, &grid_source_);
  std::vector<std::vector<int32_t>> bin_faces(normal_bins_.size());
  for (size_t f = 0; f < normal_bins_.bin_of.size(); ++f) bin_faces[normal_bins_.bin_of[f]].push_back(static_cast<int32_t>(f));
  for (std::vector<int32_t>& faces : bin_faces) bin_bvhs_.push_back(std::make_unique<FaceBvh>(swatch_, std::move(faces)));

  MatchingSwatch device_swatch;
  device_swatch.positions.reserve(swatch.num_vertices());
  for (const Vec3& p : swatch.positions) device_swatch.positions.emplace_back(p);
  device_swatch.triangles.reserve(swatch.num_faces());
  for (const Tri& t : swatch.triangles)
    device_swatch.triangles.push_back({static_cast<uint32_t>(t[0]), static_cast<uint32_t>(t[1]),
                                       static_cast<uint32_t>(t[2])});
  for (const FacePlane& plane : face_planes_) device_swatch.normals.emplace_back(plane.normal);
  device_swatch.lambda = static_cast<float>(options.lambda);
  device_swatch.normal_bins = normal_bins_.size();
  kernel_ = std::make_unique<MatchingCost>(device, device_swatch, grid_);
}

GeometryMatcher::~GeometryMatcher() = default;

double GeometryMatcher::point_cost(const Vec3& q, const Vec3& normal, const double* factors, int32_t& face) const {
  const double lambda = options_.lambda;
  const auto face_cost = [&](int32_t f, double distance) {
    return (1.0 + lambda * distance) * (1.0 + glm::length(normal - face_planes_[f].normal));
  };
  const auto distance_to = [&](int32_t f) {
    const Tri& t = swatch_.triangles[f];
    return closest_point_on_triangle(q, swatch_.positions[t[0]], swatch_.positions[t[1]], swatch_.positions[t[2]]).distance;
  };
  // The distance is at least that to the face's bounding sphere and (for a face with a
  // well-defined plane) to its plane, less what rounding can take from either: a bound above
  // the distance as computed, even by one unit in the last place, can pass over the nearest face.
  const double rounding = rounding_ + 1e-12 * std::max({std::abs(q.x), std::abs(q.y), std::abs(q.z)});
  const auto gap_to = [&](int32_t f) {
    double gap = glm::length(q - face_spheres_[f].centre) - face_spheres_[f].radius;
    if (face_planes_[f].planar) {
      const Vec3& a = swatch_.positions[swatch_.triangles[f][0]];
      gap = std::max(gap, std::abs(glm::dot(q - a, face_planes_[f].normal)) * (1.0 - 1e-12));
    }
    return std::max(gap - rounding, 0.0);
  };
  const auto face_bound = [&](int32_t f) {
    return (1.0 + lambda * gap_to(f)) * (1.0 + glm::length(normal - face_planes_[f].normal));
  };
  // The hinted face (nearest at a translation close to this one) costs what it costs: starting
  // from it the searches below stop sooner, and their minimum is the same.
  double best = face >= 0 ? face_cost(face, distance_to(face)) : std::numeric_limits<double>::infinity();
  const int64_t voxel = grid_.voxel_of(q);
  if (voxel >= 0) {
    // A group's faces all cost at least (1 + lambda * near) x its normal bound, and entries come
    // nearest first: once one cannot beat or tie the best, none after it in the group can. Ties
    // go to the lower face index, as in the BVH's search, so that the face found (a hint, and
    // the refinement's correspondence) does not depend on the order of the scan or the hint.
    const auto scan = [&](const FaceGroup& g) {
      const double factor = factors[g.label];
      for (uint32_t k = g.first; k < g.end; ++k) {
        const double nearest = 1.0 + lambda * grid_.near[k];
        if (nearest * factor > best) break;
        const auto f = static_cast<int32_t>(grid_.faces[k]);
        const double turn = 1.0 + glm::length(normal - face_planes_[f].normal);
        if (nearest * turn > best) continue;  // nor can this face, facing away
        if ((1.0 + lambda * gap_to(f)) * turn > best) continue;  // or far off
        const double c = (1.0 + lambda * distance_to(f)) * turn;
        if (c < best || (c == best && f < face)) {
          best = c;
          face = f;
        }
      }
    };
    // Each group's bound once; the lists of the groups that may be scanned are fetched before
    // the first scan, which would otherwise wait on each in turn.
    const FaceGroup* groups = grid_.groups.data() + grid_.group_start[voxel];
    const uint32_t count = grid_.group_start[voxel + 1] - grid_.group_start[voxel];
    double bounds[kMaxBins];
    // The most promising group first, so that the others are mostly passed over whole.
    uint32_t lowest = 0;
    for (uint32_t g = 0; g < count; ++g) {
      bounds[g] = (1.0 + lambda * groups[g].near) * factors[groups[g].label];
      if (bounds[g] <= best) {
        __builtin_prefetch(&grid_.near[groups[g].first]);
        __builtin_prefetch(&grid_.faces[groups[g].first]);
      }
      if (bounds[g] < bounds[lowest]) lowest = g;
    }
    if (count > 0) scan(groups[lowest]);
    for (uint32_t g = 0; g < count; ++g)
      if (g != lowest && bounds[g] <= best) scan(groups[g]);
    // Every unlisted face costs at least 1 + lambda * reach (D >= 1 + lambda * Dist).
    if (best < 1.0 + lambda * grid_.reach[voxel]) return best;
    // A far voxel's nearest face is often cheaper than the hint (found at another translation):
    // the search below then starts from the lower cost and meets fewer faces.
    if (const int32_t f = grid_.nearest_face[voxel]; f >= 0 && f != face) {
      const double c = face_cost(f, distance_to(f));
      if (c < best || (c == best && f < face)) {
        best = c;
        face = f;
      }
    }
  }
  // A face of a bin costs at least (1 + lambda * Dist) x the bin's factor, so no face of it
  // farther than (D_best / factor - 1) / lambda can win, and a bin whose factor exceeds the best
  // holds none that can win or tie. Bins are searched in increasing factor (the best falls
  // fastest), each from the best so far; within a search, a face's normal term and bounding
  // sphere rule most out without a closest point. The answer is that of one search over every
  // face: the least cost, ties to the lower index (a later bin's face wins a tie only when lower).
  // See docs/decisions/0019.
  const size_t bins = bin_bvhs_.size();
  uint32_t order[kMaxBins];
  for (uint32_t b = 0; b < bins; ++b) order[b] = b;
  std::sort(order, order + bins, [&](uint32_t a, uint32_t b) { return factors[a] < factors[b] || (factors[a] == factors[b] && a < b); });
  double factor = 1.0;  // of the bin searched
  const std::function<double(const ClosestPoint&)> cost = [&](const ClosestPoint& cp) { return face_cost(cp.face, cp.distance); };
  const std::function<double(double)> radius = [&](double d) { return std::max((d / factor - 1.0) / lambda, 0.0); };
  const std::function<double(int32_t)> bound = face_bound;
  for (size_t k = 0; k < bins; ++k) {
    factor = factors[order[k]];
    if (factor > best) break;
    const ClosestPoint found = bin_bvhs_[order[k]]->min_cost_face(q, cost, radius, &best, best, bound, face);
    if (found.face >= 0) face = found.face;
  }
  return best;
}

std::vector<double> GeometryMatcher::normal_factors(const std::vector<Vec3>& normals) const {
  std::vector<double> factors(normals.size() * normal_bins_.size());
  for (size_t i = 0; i < normals.size(); ++i) normal_bins_.factor_bounds(normals[i], &factors[i * normal_bins_.size()]);
  return factors;
}

double GeometryMatcher::exact_cost(const std::vector<Vec3>& points, const std::vector<Vec3>& normals,
                                   const glm::dvec2& translation) const {
  std::vector<int32_t> faces(points.size(), -1);
  return exact_cost(points, normals, translation, faces);
}

double GeometryMatcher::exact_cost(const std::vector<Vec3>& points, const std::vector<Vec3>& normals,
                                   const glm::dvec2& translation, std::vector<int32_t>& faces) const {
  return exact_cost(points, normals, normal_factors(normals), translation, faces);
}

double GeometryMatcher::exact_cost(const std::vector<Vec3>& points, const std::vector<Vec3>& normals,
                                   const std::vector<double>& factors, const glm::dvec2& translation,
                                   std::vector<int32_t>& faces) const {
  return exact_cost_up_to(points, normals, factors, translation, faces, nullptr,
                          std::numeric_limits<double>::infinity());
}

double GeometryMatcher::exact_cost_up_to(const std::vector<Vec3>& points, const std::vector<Vec3>& normals,
                                         const std::vector<double>& factors, const glm::dvec2& translation,
                                         std::vector<int32_t>& faces, const double* lower, double ceiling) const {
  const size_t bins = normal_bins_.size(), n = points.size();
  const Vec3 shift(translation.x, translation.y, 0.0);
  // Blocks of a kAbandonBlocks-th of the points (small sets in one block, and without bounds all
  // of them): a candidate whose cost exceeds the ceiling by a fraction of the gap between its
  // bound and its cost is known after a few blocks, the excess over the bounds being spread over
  // the points.
  const size_t block = lower ? std::max<size_t>({1, static_cast<size_t>(options_.abandon_block),
                                                 (n + kAbandonBlocks - 1) / kAbandonBlocks})
                             : std::max<size_t>(n, 1);
  std::vector<double> left((n + block - 1) / block + 1, 0.0);  // bounds of the points from each block on
  for (size_t b = left.size() - 1; lower && b-- > 0;) {
    left[b] = left[b + 1];
    for (size_t i = b * block; i < std::min(n, (b + 1) * block); ++i) left[b] += lower[i];
  }
  // Per-point minima in parallel, summed in point order so the total is the same on every run.
  std::vector<double> costs(n);
  double total = 0.0;
  for (size_t b = 0; b * block < n; ++b) {
    const size_t first = b * block, end = std::min(n, first + block);
    tbb::parallel_for(tbb::blocked_range<size_t>(first, end, 64), [&](const tbb::blocked_range<size_t>& range) {
      for (size_t i = range.begin(); i != range.end(); ++i) costs[i] = point_cost(points[i] - shift, normals[i], &factors[i * bins], faces[i]);
    });
    for (size_t i = first; i < end; ++i) total += costs[i];
    // Sums of positive terms, each rounded by at most 2^-53 relative: 1e-9 covers any set of
    // points held in memory, so the whole sum exceeds the ceiling too.
    if (end < n && (total + left[b + 1]) * (1.0 - 1e-9) > ceiling) return std::numeric_limits<double>::infinity();
  }
  return total;
}

std::pair<glm::dvec2, double> GeometryMatcher::refine(const std::vector<Vec3>& points,
                                                      const std::vector<Vec3>& normals,
                                                      const std::vector<double>& factors,
                                                      const glm::dvec2& start, double cost,
                                                      std::vector<int32_t> faces) const {
  // With each point's minimizing face held, Eq. 3 becomes S(t) = sum of (1 + lambda * Dist(q_i
  // - t, f_i)) x turn_i: at least E(t), equal to it where the faces were found, convex in t and
  // cheap (one closest point per point, no search). S is lowered by reweighted Gauss-Newton
  // steps (each distance weighted by turn_i / d_i, the least-squares form of a sum of
  // distances, and modelled by its plane, edge line or corner, so a point on its face may slide
  // along it) with step halving; then one exact evaluation confirms the move and finds the
  // faces anew. A periodic swatch lines up exactly with the output it was copied into; the
  // result stays within one cell of the grid candidate.
  const size_t n = points.size();
  std::vector<double> turns(n);
  std::vector<ClosestPoint> nearest(n), trial(n);
  const auto held = [&](const glm::dvec2& u, std::vector<ClosestPoint>& out) {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 256), [&](const tbb::blocked_range<size_t>& range) {
      for (size_t i = range.begin(); i != range.end(); ++i) {
        const Tri& tri = swatch_.triangles[faces[i]];
        out[i] = closest_point_on_triangle(points[i] - Vec3(u, 0.0), swatch_.positions[tri[0]],
                                           swatch_.positions[tri[1]], swatch_.positions[tri[2]]);
      }
    });
    double total = 0.0;
    for (size_t i = 0; i < n; ++i) total += turns[i] * out[i].distance;
    return total;
  };
  const double floor = 1e-6 * mean_edge_;  // of the distances that weigh a point
  glm::dvec2 t = start;
  for (int outer = 0; outer < options_.refine_iterations; ++outer) {
    for (size_t i = 0; i < n; ++i) turns[i] = 1.0 + glm::length(normals[i] - face_planes_[faces[i]].normal);
    glm::dvec2 u = t;
    double s = held(u, nearest);
    for (int inner = 0; inner < 16; ++inner) {
      glm::dmat2 a(0.0);
      glm::dvec2 b(0.0);
      for (size_t i = 0; i < n; ++i) {
        const ClosestPoint& cp = nearest[i];
        const double alpha = turns[i] / std::max(cp.distance, floor);
        const Vec3 r = points[i] - Vec3(u, 0.0) - cp.point;  // across the face, edge or corner
        const Tri& tri = swatch_.triangles[faces[i]];
        const int zeros = (cp.barycentric.x == 0.0) + (cp.barycentric.y == 0.0) + (cp.barycentric.z == 0.0);
        glm::dmat3 model(1.0);  // a corner: every direction moves the distance
        if (zeros == 0 && face_planes_[faces[i]].planar) {
          const Vec3& m = face_planes_[faces[i]].normal;
          model = glm::outerProduct(m, m);
        } else if (zeros == 1) {
          const int off = cp.barycentric.x == 0.0 ? 0 : cp.barycentric.y == 0.0 ? 1 : 2;
          const Vec3 e = swatch_.positions[tri[(off + 2) % 3]] - swatch_.positions[tri[(off + 1) % 3]];
          if (const double len = glm::length(e); len > 0.0) model -= glm::outerProduct(e / len, e / len);
        }
        a += alpha * glm::dmat2(model[0][0], model[0][1], model[1][0], model[1][1]);
        b += alpha * glm::dvec2(r);
      }
      const double ridge = 1e-12 * (a[0][0] + a[1][1]);  // directions no point constrains stay put
      a[0][0] += ridge;
      a[1][1] += ridge;
      glm::dvec2 step = glm::inverse(a) * b;
      bool lowered = false;
      glm::dvec2 moved = u;
      for (int halving = 0; halving < 8 && !lowered; ++halving, step *= 0.5) {
        moved = glm::clamp(u + step, start - cell_size_, start + cell_size_);
        const double trial_s = held(moved, trial);
        if (trial_s < s) {
          lowered = true;
          s = trial_s;
          nearest.swap(trial);
        }
      }
      if (!lowered) break;
      const bool settled = glm::length(moved - u) <= 1e-9 * cell_size_;
      u = moved;
      if (settled) break;
    }
    if (u == t) break;
    const double c = exact_cost(points, normals, factors, u, faces);
    if (!(c < cost * (1.0 - 1e-12))) break;
    cost = c;
    t = u;
  }
  return {t, cost};
}

MatchResult GeometryMatcher::match(const std::vector<Vec3>& points, const std::vector<Vec3>& normals,
                                   const std::vector<glm::dvec2>& candidates,
                                   std::mt19937_64& rng, bool refine) const {
  MatchResult result;
  if (points.empty()) {
    result.translation = candidates[draw_index(rng, candidates.size())];
    return result;
  }

  std::vector<glm::vec3> fpoints(points.begin(), points.end());
  std::vector<glm::vec3> fnormals(normals.begin(), normals.end());
  std::vector<glm::vec2> ftranslations(candidates.begin(), candidates.end());
  const std::vector<double> factors = normal_factors(normals);
  const std::vector<double> lower = kernel_->pair_bounds(fpoints, fnormals, ftranslations, factors);
  const size_t n = points.size();
  std::vector<double> bounds(candidates.size(), 0.0);  // summed as MatchingCost::score sums
  for (size_t c = 0; c < candidates.size(); ++c)
    for (size_t i = 0; i < n; ++i) bounds[c] += lower[c * n + i];
  result.scored = static_cast<int>(candidates.size());

  // Exact costs in the order of the bounds, until no candidate left can be within the margin
  // of the best: its bound, and so its cost, exceeds the threshold, which only falls as better
  // candidates are found. For the same reason an evaluation stops once the exact costs so far
  // and the bounds of the points left exceed the threshold: the candidate is out of the near set
  // and cannot lower the best. Without pruning every candidate is evaluated in full.
  std::vector<size_t> order(candidates.size());
  for (size_t c = 0; c < order.size(); ++c) order[c] = c;
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return bounds[a] < bounds[b]; });
  const auto threshold = [&](double best) { return best * (1.0 + options_.rescore_margin) + 1e-9; };
  std::vector<std::pair<size_t, double>> evaluated;
  double best = std::numeric_limits<double>::infinity();
  std::vector<int32_t> faces(points.size(), -1);  // warm starts
  // The minimizing faces of candidates that may yet be in the near set: a refinement starts
  // from them (exact costs find the same faces whatever the warm start).
  std::map<size_t, std::vector<int32_t>> faces_of;
  for (size_t c : order) {
    if (options_.prune && bounds[c] > threshold(best)) break;
    ++result.rescored;
    if (!options_.prune) {
      evaluated.emplace_back(c, exact_cost(points, normals, factors, candidates[c], faces));
    } else if (const double cost = exact_cost_up_to(points, normals, factors, candidates[c], faces, &lower[c * n], threshold(best));
               cost < std::numeric_limits<double>::infinity()) {
      evaluated.emplace_back(c, cost);
    } else {
      ++result.abandoned;
      continue;
    }
    best = std::min(best, evaluated.back().second);
    if (evaluated.back().second <= threshold(best)) faces_of[c] = faces;
  }
  std::sort(evaluated.begin(), evaluated.end());
  std::vector<std::pair<size_t, double>> exact;  // the near set, in candidate order
  for (const auto& [c, cost] : evaluated)
    if (cost <= threshold(best)) exact.emplace_back(c, cost);
  result.near = static_cast<int>(exact.size());

  // Grid-unit translations sample a periodic swatch's equally good placements unevenly: one
  // falls near a lattice position, the next one mid-cell. So every local minimum (over the
  // 8-neighbourhood of the candidate grid) is refined before the choice, not just the best.
  std::vector<std::pair<double, size_t>> minima;  // (exact cost, candidate)
  for (const auto& [c, cost] : exact) {
    bool lowest = true;
    for (const auto& [o, other] : exact) {
      const glm::dvec2 d = glm::abs(candidates[o] - candidates[c]);
      if (o != c && d.x < 1.5 * cell_size_ && d.y < 1.5 * cell_size_ && (other < cost || (other == cost && o < c)))
        lowest = false;
    }
    if (lowest) minima.emplace_back(cost, c);
  }
  std::sort(minima.begin(), minima.end());
  if (minima.size() > static_cast<size_t>(options_.max_refined)) minima.resize(options_.max_refined);

  // The minima refine independently, so they run side by side (each also spreads its points).
  std::vector<std::pair<glm::dvec2, double>> refined(minima.size());
  tbb::parallel_for(size_t{0}, minima.size(), [&](size_t k) {
    refined[k] = refine ? this->refine(points, normals, factors, candidates[minima[k].second], minima[k].first,
                                       faces_of.at(minima[k].second))
                        : std::pair{candidates[minima[k].second], minima[k].first};
  });

  // The host decides: a seeded random pick among the near-best, as image quilting does.
  double best_refined = std::numeric_limits<double>::infinity();
  for (const auto& r : refined) best_refined = std::min(best_refined, r.second);
  std::vector<size_t> near_best;
  for (size_t k = 0; k < refined.size(); ++k)
    if (refined[k].second <= best_refined * (1.0 + options_.choose_tolerance)) near_best.push_back(k);
  const auto& [t, cost] = refined[near_best[draw_index(rng, near_best.size())]];
  result.translation = t;
  result.cost = cost;
  return result;
}

}  // namespace meshquilt
