#include "paint/surface_paint.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <unordered_map>
#include <utility>

#include <glm/geometric.hpp>

#include "core/error.h"
#include "mesh/measures.h"
#include "paint/sweep_order.h"
#include "surface/base_layout.h"
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
}

// Splits until the mean edge is at most one sample pixel.
int refinement_levels(const TriMesh& base, const PaintOptions& o) {
  const double pixels = mean_edge_length(base) * o.pixels_per_unit;
  const int levels = pixels > 1.0 ? static_cast<int>(std::ceil(std::log2(pixels))) : 0;
  const double vertices = static_cast<double>(base.num_faces()) * std::pow(4.0, levels) / 2.0;
  if (levels > 12 || vertices > static_cast<double>(o.max_vertices))
    throw InputError("{pixels_per_unit}: " + std::to_string(o.pixels_per_unit) + " sample pixels per base unit needs about " +
                         std::to_string(static_cast<long long>(vertices)) + " vertices (at most " +
                         std::to_string(o.max_vertices) + "): use fewer pixels per unit",
                     ErrorKind::invalid_option);
  return levels;
}

// The sample at half its size: each pixel the mean of a 2 x 2 block (even sizes only).
ColourImage halved(const ColourImage& image) {
  ColourImage out;
  out.width = image.width / 2;
  out.height = image.height / 2;
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x)
      out.rgb.push_back(0.25 * (image.at(2 * x, 2 * y) + image.at(2 * x + 1, 2 * y) + image.at(2 * x, 2 * y + 1) +
                                image.at(2 * x + 1, 2 * y + 1)));
  return out;
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
std::vector<Vec3> split_field(const TriMesh& mesh, const std::vector<Vec3>& directions, const BaseSurface& finer) {
  std::vector<Vec3> out(finer.mesh.num_vertices());
  std::copy(directions.begin(), directions.end(), out.begin());
  const std::vector<std::pair<int32_t, int32_t>> parents = midpoint_parents(mesh);
  for (size_t k = 0; k < parents.size(); ++k) {
    const Vec3 a = directions[parents[k].first], b = directions[parents[k].second];
    out[mesh.num_vertices() + k] = glm::length(a + b) > 1e-9 ? a + b : a;
  }
  for (size_t v = 0; v < out.size(); ++v) {
    const Vec3& n = finer.vertex_normals[v];
    const Vec3 t = out[v] - glm::dot(out[v], n) * n;
    if (glm::length(t) > 1e-9) out[v] = glm::normalize(t);
  }
  return out;
}

// A neighbour of the vertex being coloured: where it lies in the vertex's frame, in pixels.
struct Neighbour {
  int32_t vertex;
  glm::dvec2 offset;
  double weight;
};

class Painter {
 public:
  Painter(const BaseSurface& surface, const std::vector<Vec3>& directions, const ColourImage& sample,
          double pixels_per_unit, const PaintOptions& options, uint64_t seed)
      : surface_(surface),
        directions_(directions),
        sample_(sample),
        options_(options),
        pixels_per_unit_(pixels_per_unit),
        rng_(seed) {
    const size_t n = surface.mesh.num_vertices();
    colour_.assign(n, glm::dvec3(0.0));
    source_.assign(n, glm::dvec2(0.0));
    done_.assign(n, 0);
    seen_.assign(n, 0);
    radius_ = 0.5 * options.window / pixels_per_unit;
    sigma2_ = std::pow(0.25 * options.window, 2.0);
  }

  // One visit: the best candidate for v given the neighbours coloured so far (or all of them).
  double visit(int32_t v, bool whole) {
    gather(v, whole);
    std::vector<glm::dvec2> candidates;
    for (const Neighbour& u : neighbours_) candidates.push_back(source_[u.vertex] - u.offset);
    if (done_[v]) candidates.push_back(source_[v]);
    std::uniform_real_distribution<double> x(0.0, sample_.width), y(0.0, sample_.height);
    const int random = candidates.empty() ? 1 : options_.random_candidates;
    for (int k = 0; k < random; ++k) candidates.emplace_back(x(rng_), y(rng_));
    double best = std::numeric_limits<double>::infinity();
    glm::dvec2 chosen = candidates.front();
    for (const glm::dvec2& c : candidates) {
      double cost = 0.0;
      for (const Neighbour& u : neighbours_) {
        const glm::dvec3 d = colour_[u.vertex] - sample_.sample(c + u.offset);
        cost += u.weight * glm::dot(d, d);
        if (cost >= best) break;
      }
      if (cost < best) {
        best = cost;
        chosen = c;
      }
    }
    source_[v] = wrap(chosen);
    colour_[v] = sample_.sample(source_[v]);
    done_[v] = 1;
    double weights = 0.0;
    for (const Neighbour& u : neighbours_) weights += u.weight;
    return weights > 0.0 ? best / weights : 0.0;
  }

  // Every vertex starts from a sample position (a coarser level's, carried over): coloured there.
  void start_from(const std::vector<glm::dvec2>& sources) {
    for (size_t v = 0; v < sources.size(); ++v) {
      source_[v] = wrap(sources[v]);
      colour_[v] = sample_.sample(source_[v]);
      done_[v] = 1;
    }
  }

  const std::vector<glm::dvec3>& colours() const { return colour_; }
  const std::vector<glm::dvec2>& sources() const { return source_; }

 private:
  glm::dvec2 wrap(const glm::dvec2& p) const {
    return {p.x - sample_.width * std::floor(p.x / sample_.width), p.y - sample_.height * std::floor(p.y / sample_.height)};
  }

  // The vertices within the window's radius of v (through edges, by distance in space), coloured
  // ones only unless `whole`, in v's frame: x along the field, y along normal x field.
  void gather(int32_t v, bool whole) {
    neighbours_.clear();
    const Vec3& p = surface_.mesh.positions[v];
    const Vec3& d = directions_[v];
    const Vec3 b = glm::normalize(glm::cross(surface_.vertex_normals[v], d));
    ++stamp_;
    frontier_.assign(1, v);
    seen_[v] = stamp_;
    for (size_t k = 0; k < frontier_.size(); ++k) {
      for (const auto& [w, length] : surface_.edges[frontier_[k]]) {
        (void)length;
        if (seen_[w] == stamp_) continue;
        seen_[w] = stamp_;
        const Vec3 q = surface_.mesh.positions[w] - p;
        if (glm::length(q) > radius_) continue;
        frontier_.push_back(w);
        if (!whole && !done_[w]) continue;
        const glm::dvec2 offset = pixels_per_unit_ * glm::dvec2(glm::dot(q, d), glm::dot(q, b));
        neighbours_.push_back({w, offset, std::exp(-glm::dot(offset, offset) / (2.0 * sigma2_))});
      }
    }
  }

  const BaseSurface& surface_;
  const std::vector<Vec3>& directions_;
  const ColourImage& sample_;
  const PaintOptions& options_;
  double pixels_per_unit_;
  std::mt19937_64 rng_;
  std::vector<glm::dvec3> colour_;
  std::vector<glm::dvec2> source_;
  std::vector<uint8_t> done_;
  std::vector<uint32_t> seen_;
  uint32_t stamp_ = 0;
  std::vector<int32_t> frontier_;
  std::vector<Neighbour> neighbours_;
  double radius_ = 0.0, sigma2_ = 1.0;
};

}  // namespace

PaintResult paint_surface(const TriMesh& base, const ColourImage& sample,
                          const std::vector<FieldConstraint>& constraints, const PaintOptions& options) {
  check(base, sample, options);
  PaintResult result;
  result.levels = refinement_levels(base, options);
  // Coarse to fine: the sample halved while it still holds a window and a pixel, one split level
  // for each halving, so that every level has about a vertex per pixel of its sample.
  std::vector<ColourImage> pyramid{sample};
  while (static_cast<int>(pyramid.size()) <= result.levels && pyramid.back().width % 2 == 0 &&
         pyramid.back().height % 2 == 0 && pyramid.back().width / 2 > options.window &&
         pyramid.back().height / 2 > options.window)
    pyramid.push_back(halved(pyramid.back()));
  const int coarsest = static_cast<int>(pyramid.size()) - 1;
  // Synth's field: spread over the base, then carried to each split.
  TriMesh mesh = base;
  std::vector<Vec3> directions = interpolate_field(BaseSurface(base), constraints).directions;
  for (int k = 0; k < result.levels - coarsest; ++k) {
    TriMesh finer = split_faces(mesh, 1);
    directions = split_field(mesh, directions, BaseSurface(finer));
    mesh = std::move(finer);
  }
  std::vector<glm::dvec2> sources;
  double cost = 0.0;
  for (int step = coarsest; step >= 0; --step) {
    const double pixels_per_unit = std::ldexp(options.pixels_per_unit, -step);
    const BaseSurface surface(mesh);
    result.order = sweep_order(sweep_function(surface, directions));
    Painter painter(surface, directions, pyramid[step], pixels_per_unit, options, options.seed + step);
    // The coarsest level is swept; a finer one starts from the coarser positions carried over
    // and is corrected with whole neighbourhoods.
    const int passes = step == coarsest ? options.passes : std::max(1, options.passes - 1);
    if (step < coarsest) painter.start_from(sources);
    for (int pass = 0; pass < passes; ++pass) {
      cost = 0.0;
      for (int32_t v : result.order) cost += painter.visit(v, pass > 0 || step < coarsest);
    }
    sources = painter.sources();
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
    // To the next level: old vertices at twice their position; a new one (an edge's midpoint)
    // where its first parent's position and its offset in that parent's frame put it.
    const std::vector<std::pair<int32_t, int32_t>> parents = midpoint_parents(mesh);
    TriMesh finer = split_faces(mesh, 1);
    const double next = 2.0 * pixels_per_unit;
    std::vector<glm::dvec2> carried(finer.num_vertices());
    for (size_t v = 0; v < mesh.num_vertices(); ++v) carried[v] = 2.0 * sources[v];
    for (size_t k = 0; k < parents.size(); ++k) {
      const int32_t a = parents[k].first;
      const Vec3& d = directions[a];
      const Vec3 b = glm::normalize(glm::cross(surface.vertex_normals[a], d));
      const Vec3 q = finer.positions[mesh.num_vertices() + k] - mesh.positions[a];
      carried[mesh.num_vertices() + k] = 2.0 * sources[a] + next * glm::dvec2(glm::dot(q, d), glm::dot(q, b));
    }
    sources = std::move(carried);
    directions = split_field(mesh, directions, BaseSurface(finer));
    mesh = std::move(finer);
  }
  result.mean_cost = cost / static_cast<double>(std::max<size_t>(1, result.order.size()));
  return result;
}

}  // namespace meshquilt
