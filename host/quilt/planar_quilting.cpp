#include "quilt/planar_quilting.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <random>
#include <utility>

#include "core/error.h"
#include "mesh/measures.h"
#include "mesh/topology.h"
#include "quilt/lattice_classes.h"
#include "quilt/lattice_copies.h"
#include "quilt/layer_index.h"
#include "quilt/merging/abutting_elements.h"
#include "quilt/quilt_driver.h"
#include "quilt/stage_timer.h"
#include "quilt/swatch_lattice.h"

namespace meshquilt {
namespace {

// Cells of the grid an output sub-patch spans: sub_patch_fraction of the swatch, at least one.
int sub_patch_cells(int swatch_cells, int grid_cells, double fraction) {
  return std::clamp(static_cast<int>(std::lround(swatch_cells * fraction)), 1, std::min(grid_cells, swatch_cells));
}

// Grid-unit translations for which the swatch covers the sub-patch (cells [px, px + sub_nx) x
// [py, py + sub_ny)) entirely.
std::vector<glm::dvec2> covering_translations(int px, int py, int sub_nx, int sub_ny, int swatch_nx, int swatch_ny,
                                              double cell) {
  std::vector<glm::dvec2> candidates;
  for (int ty = py + sub_ny - swatch_ny; ty <= py; ++ty)
    for (int tx = px + sub_nx - swatch_nx; tx <= px; ++tx) candidates.emplace_back(tx * cell, ty * cell);
  return candidates;
}

// How many elements of the swatch placed at `phase` and every period from it have their centre
// in `domain`: row by row along the second period, each row's count in closed form.
int64_t elements_inside(const QuiltSwatch& swatch, const SwatchLattice& lattice, const glm::dvec2& phase,
                        const Rect2& domain) {
  const std::array<glm::dvec2, 2>& b = lattice.basis;
  int64_t count = 0;
  for (const Rect2& bounds : swatch.element_bounds) {
    const glm::dvec2 c = 0.5 * (bounds.lo + bounds.hi) + phase;
    double k1_lo = std::numeric_limits<double>::max(), k1_hi = std::numeric_limits<double>::lowest();
    for (const glm::dvec2& corner : {domain.lo, domain.hi, glm::dvec2(domain.lo.x, domain.hi.y), glm::dvec2(domain.hi.x, domain.lo.y)}) {
      const double k1 = lattice_coordinates(corner - c, b).y;
      k1_lo = std::min(k1_lo, k1);
      k1_hi = std::max(k1_hi, k1);
    }
    for (double k1 = std::ceil(k1_lo); k1 <= k1_hi; ++k1) {
      // The row c + k1 b1 + s b0 inside the domain: s within the slab of x, then of y.
      const glm::dvec2 o = c + k1 * b[1];
      double lo = std::numeric_limits<double>::lowest(), hi = std::numeric_limits<double>::max();
      for (int axis = 0; axis < 2; ++axis) {
        if (b[0][axis] == 0.0) {
          if (o[axis] < domain.lo[axis] || o[axis] > domain.hi[axis]) lo = 1.0, hi = 0.0;
          continue;
        }
        const double s0 = (domain.lo[axis] - o[axis]) / b[0][axis], s1 = (domain.hi[axis] - o[axis]) / b[0][axis];
        lo = std::max(lo, std::min(s0, s1));
        hi = std::min(hi, std::max(s0, s1));
      }
      if (hi >= lo) count += static_cast<int64_t>(std::floor(hi) - std::ceil(lo) + 1.0);
    }
  }
  return count;
}

// The lattice's phase over the plane: of an 8 x 8 grid of phases within one period cell, the
// first that puts the most element centres in the domain (at the origin alone, a row of rings
// can fall just past each edge and leave a bare strip).
glm::dvec2 lattice_phase(const QuiltSwatch& swatch, const SwatchLattice& lattice, const Rect2& domain) {
  glm::dvec2 best(0.0);
  int64_t most = -1;
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 8; ++i) {
      // Half steps: a phase that puts a row of centres exactly on the plane's edge would leave
      // its elements to rounding.
      const glm::dvec2 phase = ((i + 0.5) / 8.0) * lattice.basis[0] + ((j + 0.5) / 8.0) * lattice.basis[1];
      const int64_t inside = elements_inside(swatch, lattice, phase, domain);
      if (inside > most) {
        most = inside;
        best = phase;
      }
    }
  return best;
}

// The elements of a pattern that all stand alone (lattice_classes.h), placed at every period
// from the phase where the centre of their bounds lies in the domain, as the step would place
// them; empty where some element does not stand alone.
std::vector<PlaneElement> filled_plane(const QuiltSwatch& swatch, const SwatchLattice& lattice,
                                       double partner_distance, const glm::dvec2& phase, const Rect2& domain, double tolerance,
                                       const CancelToken* cancel) {
  const std::vector<LatticeClass> classes = lattice_classes(swatch, lattice, partner_distance, tolerance);
  if (!std::all_of(classes.begin(), classes.end(), [](const LatticeClass& c) { return c.alone; })) return {};
  const std::array<glm::dvec2, 2>& b = lattice.basis;
  std::vector<PlaneElement> layer;
  for (const LatticeClass& cls : classes) {
    const Rect2& bounds = swatch.element_bounds[cls.element];
    const glm::dvec2 centre = 0.5 * (bounds.lo + bounds.hi) + phase;
    glm::dvec2 k_lo(std::numeric_limits<double>::max()), k_hi(std::numeric_limits<double>::lowest());
    for (const glm::dvec2& corner : {domain.lo, domain.hi, glm::dvec2(domain.lo.x, domain.hi.y), glm::dvec2(domain.hi.x, domain.lo.y)}) {
      const glm::dvec2 k = lattice_coordinates(corner - centre, b);
      k_lo = glm::min(k_lo, k);
      k_hi = glm::max(k_hi, k);
    }
    for (double k1 = std::ceil(k_lo.y); k1 <= k_hi.y; ++k1) {
      if (cancel) cancel->check();
      for (double k0 = std::ceil(k_lo.x); k0 <= k_hi.x; ++k0) {
        const glm::dvec2 t = phase + k0 * b[0] + k1 * b[1];
        if (!domain.contains(0.5 * (bounds.lo + bounds.hi) + t)) continue;
        PlaneElement e;
        e.mesh = swatch.elements[cls.element];
        for (Vec3& p : e.mesh.positions) p += Vec3(t, 0.0);
        e.bounds = {bounds.lo + t, bounds.hi + t};
        e.source = cls.element;
        layer.push_back(std::move(e));
      }
    }
  }
  return layer;
}

// Whether the clean-up would find nothing to do in a plane filled with one pattern: the pattern
// repeats, so a sample of it holding every element of each class within reach of its others (those
// whose centres lie within two of the widest elements and periods of the plane's middle) has what
// the whole has: no element open, folded or passing through another, none meeting another face to
// face.
bool filled_pattern_is_clean(const std::vector<PlaneElement>& layer, const QuiltSwatch& swatch,
                             const SwatchLattice& lattice, const Rect2& domain) {
  double reach = std::max(glm::length(lattice.basis[0]), glm::length(lattice.basis[1]));
  for (const Rect2& b : swatch.element_bounds) reach = std::max(reach, glm::length(b.hi - b.lo));
  const glm::dvec2 middle = 0.5 * (domain.lo + domain.hi);
  const Rect2 sample{middle - 2.0 * reach, middle + 2.0 * reach};
  std::vector<TriMesh> parts;
  for (const PlaneElement& e : layer)
    if (sample.contains(0.5 * (e.bounds.lo + e.bounds.hi))) parts.push_back(e.mesh);
  std::vector<const TriMesh*> meshes;
  for (const TriMesh& m : parts) meshes.push_back(&m);
  std::vector<uint8_t> alive(parts.size(), 1);
  const BrokenElements broken = remove_broken_elements(meshes, swatch.closed_elements, swatch.unfolded_elements, alive);
  if (broken.open + broken.folded + broken.intersecting > 0) return false;
  // Corners weld within the tolerance the whole plane's size gives.
  Box3 whole;
  for (const PlaneElement& e : layer)
    for (const Vec3& p : e.mesh.positions) {
      whole.lo = glm::min(whole.lo, p);
      whole.hi = glm::max(whole.hi, p);
    }
  TriMesh joined = join_elements(parts);
  const Box3 part = bounding_box(joined.positions);
  const double tolerance = kWeldTolerance * glm::length(whole.extent()) / glm::length(part.extent());
  return join_abutting_elements(joined, tolerance) == 0;
}

// Over a plane a repeating swatch is placed at a period from the phase, among those within the
// candidates' range: the best of them by matching, and as they are, since a refined placement
// would leave the lattice.
void place_on_lattice(const SwatchLattice& lattice, const glm::dvec2& phase, double cell, PatchRequest& request) {
  std::vector<glm::dvec2> placements = lattice_placements(request.candidates, -phase, lattice.basis, 1e-9 * cell);
  if (placements.empty()) return;
  request.candidates = std::move(placements);
  request.refine = false;
  request.reject_covered_inputs = false;
}

}  // namespace

TriMesh quilt_plane(const TriMesh& input_swatch, engine::Device& device, const PlanarQuiltOptions& options,
                    QuiltStats* stats_out) {
  if (!(options.width > 0.0) || !(options.height > 0.0)) throw OptionError("plane size must be positive");
  QuiltStats stats;
  auto& seconds = stats.stage_seconds;
  const QuiltSetup setup(input_swatch, device, options, stats);
  const QuiltSwatch& swatch = setup.swatch;
  const double cell = setup.cell;
  const Rect2 domain{glm::dvec2(0.0), glm::dvec2(options.width * swatch.extent.x, options.height * swatch.extent.y)};
  PlaneGrid grid;
  grid.cell = cell;
  // The cells whose centre lies in the plane: a last, partial row or column with its centre
  // outside could never be covered and would count as a hole.
  grid.nx = std::max(1, static_cast<int>(std::ceil(domain.hi.x / cell - 0.5 - 1e-9)));
  grid.ny = std::max(1, static_cast<int>(std::ceil(domain.hi.y / cell - 0.5 - 1e-9)));
  const int sub_nx = sub_patch_cells(setup.swatch_nx, grid.nx, options.sub_patch_fraction);
  const int sub_ny = sub_patch_cells(setup.swatch_ny, grid.ny, options.sub_patch_fraction);
  const int total_cells = grid.nx * grid.ny;
  stats.cells = total_cells;
  stats.cell_size = cell;
  stats.plane_extent = domain.hi;

  // A repeating swatch is placed at its periods only: its pattern then runs on unbroken, and a
  // patch's inputs are mostly copies of elements already there (quilt/lattice_copies.h).
  std::optional<SwatchLattice> lattice;
  {
    StageTimer timer(seconds, "swatch");
    if (options.lattice_placement) lattice = swatch_lattice(swatch, 1);
  }
  stats.on_lattice = lattice.has_value();
  std::unique_ptr<LatticeContacts> contacts;
  const glm::dvec2 phase = lattice ? lattice_phase(swatch, *lattice, domain) : glm::dvec2(0.0);
  if (lattice)
    contacts = std::make_unique<LatticeContacts>(swatch, lattice->basis, setup.step.partner_distance * swatch.mean_edge);

  LayerIndex index(std::max(swatch.extent.x, swatch.extent.y));
  SeedFinder seeds(grid.nx, grid.ny);
  HoleTracker holes(seeds, options.seed_attempts);
  std::mt19937_64 rng(options.seed);
  std::vector<PlaneElement> layer;
  if (lattice && options.fill_margin > 0.0) {
    StageTimer timer(seconds, "fill");
    layer = filled_plane(swatch, *lattice, setup.step.partner_distance * swatch.mean_edge, phase, domain, setup.step.copy_tolerance * swatch.mean_edge,
                         options.cancel);
    stats.filled_elements = static_cast<int>(layer.size());
    // The pattern covers the plane: no patch is left to place.
    if (!layer.empty()) {
      for (int c = 0; c < total_cells; ++c) seeds.mark_processed(c);
      const double area = total_cells * cell * cell;
      if (options.progress) options.progress(QuiltProgress{area, area, total_cells, total_cells, 0});
    }
  }
  PatchRequest request;
  request.grid = grid;
  // A patch seeded again on a cell it could not cover also places elements centred up to a
  // quarter of an element past the plane's edge: the rows of a sparse swatch drift from patch to
  // patch, and where a row's centres fall just past the edge the centre rule alone leaves a band
  // of the plane bare however often it is seeded.
  std::vector<double> element_sides;
  for (const Rect2& b : swatch.element_bounds) element_sides.push_back(std::min(b.hi.x - b.lo.x, b.hi.y - b.lo.y));
  std::nth_element(element_sides.begin(), element_sides.begin() + element_sides.size() / 2, element_sides.end());
  const double reach = element_sides.empty() ? 0.0 : 0.25 * element_sides[element_sides.size() / 2];
  const Rect2 retry_domain{domain.lo - glm::dvec2(reach), domain.hi + glm::dvec2(reach)};
  request.reachable = [&retry_domain](const glm::dvec2& p) { return retry_domain.contains(p); };

  SeedLoopDomain plane;
  plane.quilt_patch_at = [&](int seed_cell) {
    const int seed_x = seed_cell % grid.nx, seed_y = seed_cell / grid.nx;
    // Output-sub-patch: sub_nx x sub_ny cells around the seed, inside the domain.
    const int px = std::clamp(seed_x - sub_nx / 2, 0, grid.nx - sub_nx);
    const int py = std::clamp(seed_y - sub_ny / 2, 0, grid.ny - sub_ny);
    request.sub_patch = {glm::dvec2(px * cell, py * cell), glm::dvec2((px + sub_nx) * cell, (py + sub_ny) * cell)};
    request.candidates = covering_translations(px, py, sub_nx, sub_ny, setup.swatch_nx, setup.swatch_ny, cell);
    if (lattice) {
      place_on_lattice(*lattice, phase, cell, request);
      request.contacts = contacts.get();
    }
    const Rect2& placing = holes.tries(seed_cell) > 0 ? retry_domain : domain;
    request.inside_domain = [&placing](const glm::dvec2& p) { return placing.contains(p); };
    std::vector<int32_t> near;
    {
      StageTimer timer(seconds, "index");
      near = patch_neighbourhood(index, layer, request.candidates, swatch.extent, 2.0 * swatch.mean_edge);
    }
    request.near = &near;
    const size_t existing = layer.size();
    const PatchOutcome outcome =
        quilt_patch(layer, request, swatch, setup.matcher, setup.step, rng, stats.merges, seconds, options.cancel);
    request.near = nullptr;
    StageTimer timer(seconds, "seed");
    // The step changes only the elements it was given and those it appended.
    for (int32_t k : near)
      if (std::exchange(layer[k].changed, false)) index.update(layer, k);
    for (size_t k = existing; k < layer.size(); ++k) {
      layer[k].changed = false;
      index.update(layer, static_cast<int32_t>(k));
    }
    const CellWindow& w = outcome.window;
    for (int y = w.y0; y <= w.y1; ++y)
      for (int x = w.x0; x <= w.x1; ++x)
        if (outcome.covered[w.index(x, y)]) seeds.mark_processed(static_cast<int>(grid.index(x, y)));
  };
  plane.progress = [&] {
    const int processed = total_cells - seeds.unprocessed_count();
    return QuiltProgress{processed * cell * cell, total_cells * cell * cell, processed, total_cells, 0};
  };
  run_seed_loop(seeds, holes, options, stats, plane);

  const HoleSummary hole_summary = holes.summary(grid_neighbours(grid.nx, grid.ny));
  stats.holes = hole_summary.holes;
  stats.hole_cells = hole_summary.cells;
  stats.largest_hole_area = hole_summary.largest_cells * cell * cell;
  // A plane the pattern filled alone is clean when a sample of the pattern is: the clean-up's tests
  // over every face would only find again what the sample shows.
  QuiltOptions finishing = options;
  if (options.cleanup && stats.filled_elements > 0 && stats.filled_elements == static_cast<int>(layer.size())) {
    StageTimer timer(seconds, "cleanup");
    finishing.cleanup = !filled_pattern_is_clean(layer, swatch, *lattice, domain);
  }
  std::vector<TriMesh> elements;
  std::vector<uint8_t> alive;
  std::vector<int32_t> sources;
  for (PlaneElement& e : layer) {
    elements.push_back(std::move(e.mesh));
    alive.push_back(e.alive ? 1 : 0);
    sources.push_back(e.source);
  }
  TriMesh result = finish_quilt(elements, alive, sources, setup, finishing, stats);
  if (finishing.cleanup) {
    StageTimer timer(seconds, "cleanup");
    stats.joined_elements = join_abutting_elements(result, kWeldTolerance);
  }
  if (stats_out) *stats_out = stats;
  return result;
}

}  // namespace meshquilt
