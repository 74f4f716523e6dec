#include "paint/surface_paint.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <utility>

#include <glm/geometric.hpp>

#include "core/error.h"
#include "mesh/measures.h"
#include "paint/field_frame.h"
#include "paint/rigid_sources.h"
#include "paint/sweep_batches.h"
#include "paint/sweep_order.h"
#include "neighbourhood_cost.h"
#include "surface/base_layout.h"
#include "surface/direction_field.h"
#include "surface/surface_types.h"

namespace meshquilt {
namespace {

void check(const TriMesh& base, const ColourImage& sample, const PaintOptions& o) {
  if (base.num_faces() == 0) throw InputError("paint: the base has no faces", ErrorKind::invalid_mesh);
  if (sample.width < 1 || sample.height < 1 || sample.rgb.size() != static_cast<size_t>(sample.width) * sample.height)
    throw InputError("paint: the sample image is empty", ErrorKind::invalid_option);
  if (!(o.pixels_per_unit > 0.0) || !std::isfinite(o.pixels_per_unit))
    throw InputError("{pixels_per_unit}: expected a positive number", ErrorKind::invalid_option);
  if (o.window < 3 || o.window > 21 || o.window % 2 == 0)
    throw InputError("{window}: expected an odd number of pixels in 3..21, got " + std::to_string(o.window),
                     ErrorKind::invalid_option);
  if (o.random_candidates < 0 || o.random_candidates > 64)
    throw InputError("{random_candidates}: expected 0..64", ErrorKind::invalid_option);
  if (o.passes < 1 || o.passes > 8) throw InputError("{passes}: expected 1..8", ErrorKind::invalid_option);
  if (!(o.coherence >= 0.0 && o.coherence <= 100.0))
    throw InputError("{coherence}: expected a number in 0..100", ErrorKind::invalid_option);
  if (o.max_batch < 1) throw InputError("{max_batch}: expected at least 1", ErrorKind::invalid_option);
}

// Splits until the mean edge is at most one sample pixel.
int refinement_levels(const TriMesh& base, const PaintOptions& o) {
  const double pixels = mean_edge_length(base) * o.pixels_per_unit;
  const int levels = pixels > 1.0 ? static_cast<int>(std::ceil(std::log2(pixels))) : 0;
  const double vertices = static_cast<double>(base.num_faces()) * std::pow(4.0, levels) / 2.0;
  if (levels > 12 || vertices > static_cast<double>(o.max_vertices)) {
    char figures[96];
    std::snprintf(figures, sizeof figures, "%.6g sample pixels per base unit needs about %.3g vertices", o.pixels_per_unit,
                  vertices);
    throw InputError("{pixels_per_unit}: " + std::string(figures) + " (at most " + std::to_string(o.max_vertices) +
                         "): use fewer pixels per unit (a smaller {scale} or {sample_width})",
                     ErrorKind::invalid_option);
  }
  return levels;
}

// The edge (a, b) of each vertex split_faces(mesh, 1) adds, in the order it adds them.
std::vector<std::pair<int32_t, int32_t>> midpoint_parents(const TriMesh& mesh) {
  std::vector<std::pair<int32_t, int32_t>> parents;
  std::unordered_map<uint64_t, int32_t> seen;
  for (const Tri& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const int32_t a = t[k], b = t[(k + 1) % 3];
      const uint64_t key = (static_cast<uint64_t>(std::min(a, b)) << 32) | static_cast<uint32_t>(std::max(a, b));
      if (seen.emplace(key, static_cast<int32_t>(parents.size())).second) parents.emplace_back(a, b);
    }
  return parents;
}

// The field on split_faces(mesh, 1): old vertices keep theirs, a midpoint takes its edge's mean,
// each in its own tangent plane. Spread over the split mesh instead, the given directions would
// reach as many edges as over the base, so a fraction of the distance: not synth's field.
std::vector<Vec3> split_field(const TriMesh& mesh, const std::vector<Vec3>& directions, const TriMesh& finer,
                              const std::vector<std::pair<int32_t, int32_t>>& parents) {
  std::vector<Vec3> out(finer.num_vertices());
  std::copy(directions.begin(), directions.end(), out.begin());
  for (size_t k = 0; k < parents.size(); ++k) {
    const Vec3 a = directions[parents[k].first], b = directions[parents[k].second];
    out[mesh.num_vertices() + k] = glm::length(a + b) > 1e-9 ? a + b : a;
  }
  const std::vector<Vec3> normals = vertex_normals(finer);
  for (size_t v = 0; v < out.size(); ++v) {
    const Vec3& n = normals[v];
    const Vec3 t = out[v] - glm::dot(out[v], n) * n;
    if (glm::length(t) > 1e-9) out[v] = glm::normalize(t);
  }
  return out;
}

// Synth's field as a vector field per base vertex: the smoothest 1-direction field holding the
// guidance field's directions as synth's layout holds them (a sample has no symmetry to spare),
// each vertex the mean of its faces' directions in its tangent plane. Where that mean vanishes
// (at a singularity) the guidance field's own direction stands.
std::vector<Vec3> base_field(const BaseSurface& base, const std::vector<FieldConstraint>& constraints) {
  const GuidanceField guidance = interpolate_field(base, constraints);
  const FieldTargets targets = field_targets(base, guidance);
  const DirectionField smoothest = smoothest_direction_field(base, 1, targets.target, targets.weight);
  std::vector<Vec3> out(base.mesh.num_vertices());
  for (size_t v = 0; v < out.size(); ++v) {
    Vec3 sum(0.0);
    for (int32_t f : base.vertex_faces[v]) sum += base.face_areas[f] * smoothest.directions[f];
    const Vec3& n = base.vertex_normals[v];
    const Vec3 t = sum - glm::dot(sum, n) * n;
    out[v] = glm::length(t) > 1e-9 * (1.0 + glm::length(sum)) ? glm::normalize(t) : guidance.directions[v];
  }
  return out;
}

// A neighbour of the vertex being coloured: where it lies in the vertex's frame, in pixels.
struct Neighbour {
  int32_t vertex;
  glm::dvec2 offset;
  double weight;
};

// The k-th uniform number in [0, 1) of a vertex's visit: drawn from the vertex, the level and
// the pass alone (splitmix64), so that batches running side by side draw what the sweep draws.
double uniform(uint64_t seed, uint64_t vertex, uint64_t pass, uint64_t k) {
  uint64_t z = seed * 0x9e3779b97f4a7c15ULL ^ (vertex << 20 ^ pass << 8 ^ k) * 0xd1b54a32d192ed03ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) * 0x1p-53;
}

// Neighbours' sample positions that disagree by more than this many pixels of a level's sample
// are a seam between patches; below it, the sub-pixel slack of the choices at coarser levels.
constexpr double kRigidCut = 0.5;

// The cell, in pixels of a level's sample, a neighbourhood keeps one vertex of.
constexpr double kCell = 0.5;

class Painter {
 public:
  Painter(const BaseSurface& surface, const std::vector<Vec3>& directions, const std::vector<int32_t>& order,
          const ColourImage& sample, engine::Device& device, double pixels_per_unit, const PaintOptions& options,
          uint64_t seed)
      : surface_(surface),
        directions_(directions),
        sample_(sample),
        cost_(device, sample.width, sample.height, float_pixels(sample)),
        options_(options),
        pixels_per_unit_(pixels_per_unit),
        seed_(seed) {
    const size_t n = surface.mesh.num_vertices();
    colour_.assign(n, glm::dvec3(0.0));
    source_.assign(n, glm::dvec2(0.0));
    done_.assign(n, 0);
    windows_ = window_neighbours(surface, 0.5 * options.window / pixels_per_unit);
    schedule_ = sweep_batches(order, windows_, options.max_batch);
    sigma2_ = std::pow(0.25 * options.window, 2.0);
    // An odd number of cells, the middle one centred on the vertex, covering the window's reach.
    cells_ = 2 * static_cast<int>(std::ceil(0.5 * options.window / kCell)) + 1;
    cell_.assign(static_cast<size_t>(cells_) * cells_, -1);
  }

  // One pass over the sweep, in batches of vertices whose windows do not reach each other: each
  // vertex takes the candidate whose neighbourhood best matches its coloured neighbours' (or all
  // of them, when `whole`). Returns the summed mean mismatch per neighbour.
  double pass(bool whole, uint64_t pass_index) {
    double cost = 0.0;
    for (const std::vector<int32_t>& batch : schedule_) {
      work_.clear();
      visits_.clear();
      neighbours_.clear();
      candidates_.clear();
      for (int32_t v : batch) prepare(v, whole, pass_index);
      const std::vector<float> costs = cost_.score(work_);
      for (Visit& visit : visits_) cost += choose(visit, costs);
      for (const Visit& visit : visits_) {
        source_[visit.vertex] = wrap(visit.chosen);
        colour_[visit.vertex] = sample_.sample(source_[visit.vertex]);
        done_[visit.vertex] = 1;
      }
      ++batches_;
      visits_made_ += batch.size();
      if (options_.progress) options_.progress(visits_before_ + visits_made_, total_visits_);
      if (options_.cancel) options_.cancel->check();
    }
    return cost;
  }

  // Each coherent patch of sample positions made rigid (rigid_sources.h), then coloured anew.
  void make_rigid() {
    source_ = rigid_sources(surface_, directions_, pixels_per_unit_, {sample_.width, sample_.height}, source_,
                            kRigidCut);
    for (size_t v = 0; v < source_.size(); ++v) colour_[v] = sample_.sample(source_[v]);
  }

  // Every vertex starts from a sample position (a coarser level's, carried over): coloured there.
  void start_from(const std::vector<glm::dvec2>& sources) {
    for (size_t v = 0; v < sources.size(); ++v) {
      source_[v] = wrap(sources[v]);
      colour_[v] = sample_.sample(source_[v]);
      done_[v] = 1;
    }
  }

  // What progress reports: visits of the levels before this one, and of the whole job.
  void count_from(size_t visits_before, size_t total_visits) {
    visits_before_ = visits_before;
    total_visits_ = total_visits;
  }

  const std::vector<glm::dvec3>& colours() const { return colour_; }
  size_t batches() const { return batches_; }
  size_t visits() const { return visits_made_; }
  size_t neighbours_read() const { return neighbours_read_; }
  const std::vector<glm::dvec2>& sources() const { return source_; }

 private:
  // A vertex of the batch: its neighbours_ and candidates_ ranges, the candidates' in the
  // kernel's list, and what it chose.
  struct Visit {
    int32_t vertex;
    size_t neighbours, neighbours_end, candidates, candidates_end;
    glm::dvec2 chosen;
  };

  static std::vector<glm::vec4> float_pixels(const ColourImage& sample) {
    std::vector<glm::vec4> pixels;
    pixels.reserve(sample.rgb.size());
    for (const glm::dvec3& c : sample.rgb) pixels.emplace_back(glm::vec3(c), 0.0f);
    return pixels;
  }

  glm::dvec2 wrap(const glm::dvec2& p) const {
    return {p.x - sample_.width * std::floor(p.x / sample_.width), p.y - sample_.height * std::floor(p.y / sample_.height)};
  }

  // The visit's neighbours and candidates, in double for the choice and in float for the kernel.
  void prepare(int32_t v, bool whole, uint64_t pass_index) {
    Visit visit{v, neighbours_.size(), 0, candidates_.size(), 0, {}};
    gather(v, whole);
    visit.neighbours_end = neighbours_.size();
    neighbours_read_ += visit.neighbours_end - visit.neighbours;
    const auto first = static_cast<uint32_t>(work_.neighbours.size());
    for (size_t k = visit.neighbours; k < visit.neighbours_end; ++k) {
      const Neighbour& u = neighbours_[k];
      const glm::dvec3& c = colour_[u.vertex];
      work_.neighbours.push_back({glm::vec4(u.offset.x, u.offset.y, u.weight, 0.0), glm::vec4(glm::vec3(c), 0.0f)});
    }
    const auto index = static_cast<uint32_t>(work_.visits.size());
    work_.visits.push_back({first, static_cast<uint32_t>(work_.neighbours.size() - first), 0, 0});
    for (size_t k = visit.neighbours; k < visit.neighbours_end; ++k)
      candidates_.push_back(source_[neighbours_[k].vertex] - neighbours_[k].offset);
    if (done_[v]) candidates_.push_back(source_[v]);
    const int random = candidates_.size() == visit.candidates ? 1 : options_.random_candidates;
    for (int k = 0; k < random; ++k)
      candidates_.emplace_back(sample_.width * uniform(seed_, v, pass_index, 2 * k),
                               sample_.height * uniform(seed_, v, pass_index, 2 * k + 1));
    // Neighbours of one coherent patch propose nearly the same position: one in each quarter
    // pixel is scored, which leaves the choice to where the sample differs.
    seen_.clear();
    size_t kept = visit.candidates;
    for (size_t k = visit.candidates; k < candidates_.size(); ++k) {
      const glm::dvec2 p = wrap(candidates_[k]);
      const auto key = [](double x) { return static_cast<uint64_t>(std::floor(x * 4.0)); };
      if (seen_.insert(key(p.x) << 32 ^ key(p.y)).second) candidates_[kept++] = candidates_[k];
    }
    candidates_.resize(kept);
    visit.candidates_end = candidates_.size();
    for (size_t k = visit.candidates; k < visit.candidates_end; ++k) {
      const glm::dvec2 p = wrap(candidates_[k]);
      glm::ivec2 pixel(static_cast<int>(std::floor(p.x)), static_cast<int>(std::floor(p.y)));
      glm::vec2 fraction(p - glm::dvec2(pixel));
      // Rounding may put a position on the far border or a fraction at 1: both are the next pixel.
      for (int axis = 0; axis < 2; ++axis) {
        const int size = axis == 0 ? sample_.width : sample_.height;
        if (fraction[axis] >= 1.0f) {
          fraction[axis] = 0.0f;
          ++pixel[axis];
        }
        if (pixel[axis] >= size) pixel[axis] -= size;
      }
      work_.candidates.push_back({pixel, fraction, index, 0});
    }
    visits_.push_back(visit);
  }

  // The candidate of least mismatch in double among those the kernel's float costs leave in
  // reach of its best (a margin well above float rounding): what a search in double would choose.
  // Each mismatch is weighed by the candidate's support (coherence_factor), computed on the host
  // alike for both back ends.
  double choose(Visit& visit, const std::vector<float>& costs) {
    double weights = 0.0;
    for (size_t k = visit.neighbours; k < visit.neighbours_end; ++k) weights += neighbours_[k].weight;
    const size_t first = visit.candidates, count = visit.candidates_end - visit.candidates;
    factors_.assign(count, 0.0);
    const auto factor = [&](size_t k) {
      double& f = factors_[k - first];
      if (f == 0.0) f = coherence_factor(visit, k, weights);
      return f;
    };
    const auto margin = [&](double least) { return 1e-4 * (1.0 + options_.coherence) * (least + weights); };
    // The least weighed cost: a factor is at least 1, so once the plain costs, in rising order,
    // pass the least found and its margin, no candidate after can come within reach.
    order_.resize(count);
    for (size_t k = 0; k < count; ++k) order_[k] = first + k;
    std::sort(order_.begin(), order_.end(),
              [&](size_t a, size_t b) { return costs[a] < costs[b] || (costs[a] == costs[b] && a < b); });
    double least = std::numeric_limits<double>::infinity();
    for (size_t k : order_) {
      if (static_cast<double>(costs[k]) > least + margin(least)) break;
      least = std::min(least, factor(k) * static_cast<double>(costs[k]));
    }
    const double reach = least + margin(least);
    double best = std::numeric_limits<double>::infinity(), mismatch = 0.0;
    visit.chosen = candidates_[first];
    for (size_t k = first; k < visit.candidates_end; ++k) {
      if (static_cast<double>(costs[k]) > reach || factor(k) * static_cast<double>(costs[k]) > reach) continue;
      double cost = 0.0;
      for (size_t i = visit.neighbours; i < visit.neighbours_end; ++i) {
        const Neighbour& u = neighbours_[i];
        const glm::dvec3 d = colour_[u.vertex] - sample_.sample(candidates_[k] + u.offset);
        cost += u.weight * glm::dot(d, d);
      }
      if (factor(k) * cost < best) {
        best = factor(k) * cost;
        mismatch = cost;
        visit.chosen = candidates_[k];
      }
    }
    return weights > 0.0 ? mismatch / weights : 0.0;
  }

  // Candidate k's mismatch is multiplied by 1 + coherence x (the weight of the neighbours that
  // do not propose it, to within half a pixel, over all): a position few neighbours agree on
  // starts a new patch, and wins only where it fits that much better (Hertzmann et al. 2001's
  // coherence term, weighed by agreement instead of all or nothing).
  double coherence_factor(const Visit& visit, size_t k, double weights) const {
    if (options_.coherence <= 0.0 || weights <= 0.0) return 1.0;
    const glm::dvec2 period(sample_.width, sample_.height);
    double support = 0.0;
    for (size_t i = visit.neighbours; i < visit.neighbours_end; ++i) {
      glm::dvec2 d = source_[neighbours_[i].vertex] - neighbours_[i].offset - candidates_[k];
      d -= period * glm::round(d / period);
      if (glm::dot(d, d) <= 0.25) support += neighbours_[i].weight;
    }
    return 1.0 + options_.coherence * (1.0 - support / weights);
  }

  // The window neighbours of v, coloured ones only unless `whole`, in v's frame: x along the
  // field, y along normal x field.
  void gather(int32_t v, bool whole) {
    const Vec3& p = surface_.mesh.positions[v];
    const FieldFrame frame = field_frame(surface_.vertex_normals[v], directions_[v]);
    const size_t first = neighbours_.size();
    for (int64_t k = windows_.first[v]; k < windows_.first[v + 1]; ++k) {
      const int32_t w = windows_.vertices[k];
      if (!whole && !done_[w]) continue;
      const glm::dvec2 offset = frame_offset(frame, surface_.mesh.positions[w] - p, pixels_per_unit_);
      neighbours_.push_back({w, offset, std::exp(-glm::dot(offset, offset) / (2.0 * sigma2_))});
    }
    if (neighbours_.size() - first > cell_.size()) thin(first);
  }

  // A window holding more vertices than it has cells of kCell pixels (a base far denser than
  // the sample, or a coarse level of one) keeps only the one nearest each cell's centre, so its
  // cost stays that of a base a cell apart. Windows at the sample's density keep every vertex.
  void thin(size_t first) {
    std::fill(cell_.begin(), cell_.end(), -1);
    distance_.clear();
    size_t kept = first;
    for (size_t k = first; k < neighbours_.size(); ++k) {
      const glm::dvec2 at = neighbours_[k].offset / kCell + 0.5 * static_cast<double>(cells_);
      const glm::ivec2 c = glm::clamp(glm::ivec2(glm::floor(at)), glm::ivec2(0), glm::ivec2(cells_ - 1));
      const glm::dvec2 from_centre = at - glm::dvec2(c) - 0.5;
      const double d = glm::dot(from_centre, from_centre);
      int64_t& slot = cell_[static_cast<size_t>(c.y) * cells_ + c.x];
      if (slot < 0) {
        slot = static_cast<int64_t>(kept);
        neighbours_[kept++] = neighbours_[k];
        distance_.push_back(d);
      } else if (d < distance_[static_cast<size_t>(slot) - first]) {
        neighbours_[static_cast<size_t>(slot)] = neighbours_[k];
        distance_[static_cast<size_t>(slot) - first] = d;
      }
    }
    neighbours_.resize(kept);
  }

  const BaseSurface& surface_;
  const std::vector<Vec3>& directions_;
  const ColourImage& sample_;
  NeighbourhoodCost cost_;
  const PaintOptions& options_;
  double pixels_per_unit_;
  uint64_t seed_;
  WindowNeighbours windows_;
  std::vector<glm::dvec3> colour_;
  std::vector<glm::dvec2> source_;
  std::vector<uint8_t> done_;
  NeighbourhoodBatch work_;
  std::vector<Visit> visits_;
  std::vector<Neighbour> neighbours_;
  std::vector<glm::dvec2> candidates_;
  std::unordered_set<uint64_t> seen_;
  std::vector<double> factors_;
  std::vector<size_t> order_;
  std::vector<int64_t> cell_;
  std::vector<double> distance_;
  int cells_ = 0;
  double sigma2_ = 1.0;
  std::vector<std::vector<int32_t>> schedule_;
  size_t batches_ = 0, visits_made_ = 0, visits_before_ = 0, total_visits_ = 0, neighbours_read_ = 0;
};

// Visits of the whole job: each level's passes over its vertices, a split adding one per edge.
size_t total_visits(const TriMesh& base, int levels, int coarsest, const PaintOptions& options) {
  size_t vertices = base.num_vertices(), edges = midpoint_parents(base).size(), faces = base.num_faces(), total = 0;
  for (int k = 0; k <= levels; ++k) {
    const int step = levels - k;
    if (step <= coarsest)
      total += vertices * static_cast<size_t>((step == coarsest ? options.passes : std::max(1, options.passes - 1)) +
                                              (step > 0 ? 1 : 0));
    vertices += edges;
    edges = 2 * edges + 3 * faces;
    faces *= 4;
  }
  return total;
}

}  // namespace

PaintResult paint_surface(const TriMesh& base, const ColourImage& sample,
                          const std::vector<FieldConstraint>& constraints, const PaintOptions& options,
                          engine::Device& device) {
  check(base, sample, options);
  PaintResult result;
  result.levels = refinement_levels(base, options);
  // Coarse to fine: the sample halved while it still holds a window and a pixel, one split level
  // for each halving, so that every level has about a vertex per pixel of its sample.
  std::vector<ColourImage> pyramid{sample};
  while (static_cast<int>(pyramid.size()) <= result.levels && pyramid.back().width / 2 > options.window &&
         pyramid.back().height / 2 > options.window)
    pyramid.push_back(halved(pyramid.back()));
  const int coarsest = static_cast<int>(pyramid.size()) - 1;
  result.sample_levels = static_cast<int>(pyramid.size());
  // Each level's pixels per unit, and how a position grows to the next finer level: twice for an
  // even side, a little more for an odd one (63 pixels over 31), each axis on its own.
  std::vector<double> level_pixels_per_unit(pyramid.size(), options.pixels_per_unit);
  std::vector<glm::dvec2> growth(pyramid.size(), glm::dvec2(1.0));
  for (size_t k = 1; k < pyramid.size(); ++k) {
    growth[k] = glm::dvec2(static_cast<double>(pyramid[k - 1].width) / pyramid[k].width,
                           static_cast<double>(pyramid[k - 1].height) / pyramid[k].height);
    level_pixels_per_unit[k] = level_pixels_per_unit[k - 1] / std::sqrt(growth[k].x * growth[k].y);
  }
  // Synth's field on the base, then carried to each split.
  TriMesh mesh = base;
  std::vector<Vec3> directions = base_field(BaseSurface(base), constraints);
  for (int k = 0; k < result.levels - coarsest; ++k) {
    TriMesh finer = split_faces(mesh, 1);
    directions = split_field(mesh, directions, finer, midpoint_parents(mesh));
    mesh = std::move(finer);
  }
  std::vector<glm::dvec2> sources;
  double cost = 0.0;
  const size_t total = total_visits(base, result.levels, coarsest, options);
  for (int step = coarsest; step >= 0; --step) {
    const double pixels_per_unit = level_pixels_per_unit[step];
    const BaseSurface surface(mesh);
    result.order = sweep_order(sweep_function(surface, directions));
    Painter painter(surface, directions, result.order, pyramid[step], device, pixels_per_unit, options, options.seed + step);
    painter.count_from(result.visits, total);
    // The coarsest level is swept; a finer one starts from the coarser positions carried over,
    // their patches made rigid, and is corrected with whole neighbourhoods. Not made rigid after
    // the finest correction: the seams it blended in a smooth sample would come back hard.
    const int passes = step == coarsest ? options.passes : std::max(1, options.passes - 1);
    if (step < coarsest) {
      painter.start_from(sources);
      painter.make_rigid();
    }
    for (int pass = 0; pass < passes; ++pass) cost = painter.pass(pass > 0 || step < coarsest, pass);
    // A coarse level, a quarter of the next or less, is made rigid and corrected once more: it
    // settles the low frequencies every finer level inherits.
    if (step > 0) {
      painter.make_rigid();
      painter.pass(true, passes);
    }
    sources = painter.sources();
    result.batches += painter.batches();
    result.visits += painter.visits();
    result.neighbours += painter.neighbours_read();
    if (step == 0) {
      result.mesh = std::move(mesh);
      result.source = sources;
      result.directions = directions;
      const std::vector<glm::dvec3>& colours = painter.colours();
      result.mesh.colors.resize(result.mesh.num_vertices());
      for (size_t v = 0; v < result.mesh.num_vertices(); ++v) {
        const glm::dvec3 c = glm::clamp(colours[v], 0.0, 1.0);
        result.mesh.colors[v] = {static_cast<uint8_t>(std::lround(255.0 * c.x)),
                                 static_cast<uint8_t>(std::lround(255.0 * c.y)),
                                 static_cast<uint8_t>(std::lround(255.0 * c.z))};
      }
      break;
    }
    // To the next level: old vertices at their position grown (twice, for even sides); a new one
    // (an edge's midpoint) where its first parent's position and its offset in that parent's
    // frame put it.
    const std::vector<std::pair<int32_t, int32_t>> parents = midpoint_parents(mesh);
    TriMesh finer = split_faces(mesh, 1);
    const double next = level_pixels_per_unit[step - 1];
    const glm::dvec2 grow = growth[step];
    std::vector<glm::dvec2> carried(finer.num_vertices());
    for (size_t v = 0; v < mesh.num_vertices(); ++v) carried[v] = grow * sources[v];
    for (size_t k = 0; k < parents.size(); ++k) {
      const int32_t a = parents[k].first;
      const Vec3 q = finer.positions[mesh.num_vertices() + k] - mesh.positions[a];
      carried[mesh.num_vertices() + k] =
          grow * sources[a] + frame_offset(field_frame(surface.vertex_normals[a], directions[a]), q, next);
    }
    sources = std::move(carried);
    directions = split_field(mesh, directions, finer, parents);
    mesh = std::move(finer);
  }
  result.mean_cost = cost / static_cast<double>(std::max<size_t>(1, result.order.size()));
  return result;
}

}  // namespace meshquilt
