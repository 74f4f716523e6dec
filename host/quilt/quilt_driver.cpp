#include "quilt/quilt_driver.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "mesh/topology.h"
#include "quilt/stage_timer.h"

namespace meshquilt {
namespace {

double scheduling_cell(const QuiltSwatch& swatch, const QuiltOptions& options) {
  return std::min(swatch.extent.x, swatch.extent.y) / std::max(4, options.cells_across_swatch);
}

// Whole cells along a swatch side (the epsilon keeps an exact multiple whole).
int cells_along(double length, double cell) { return std::max(1, static_cast<int>(std::floor(length / cell + 1e-9))); }

PatchStepOptions step_options(const QuiltOptions& options, const QuiltSwatch& swatch) {
  PatchStepOptions step = options.step;
  step.correspondence.lambda = options.lambda / swatch.mean_edge;
  return step;
}

MatchingOptions matching_options(const QuiltOptions& options, const QuiltSwatch& swatch) {
  MatchingOptions matching = options.matching;
  matching.lambda = options.lambda / swatch.mean_edge;
  return matching;
}

}  // namespace

QuiltSetup::QuiltSetup(const TriMesh& input_swatch, engine::Device& device, const QuiltOptions& options,
                       QuiltStats& stats)
    : swatch(timed(stats.stage_seconds, "swatch", [&] { return prepare_swatch(input_swatch); })),
      cell(scheduling_cell(swatch, options)),
      swatch_nx(cells_along(swatch.extent.x, cell)),
      swatch_ny(cells_along(swatch.extent.y, cell)),
      step(step_options(options, swatch)),
      matcher(timed(stats.stage_seconds, "index", [&] {
        return GeometryMatcher(device, swatch.mesh, cell, matching_options(options, swatch));
      })) {
  stats.grid_source = matcher.grid_source();
  stats.cut_swatch_elements = swatch.cut_elements;
}

void run_seed_loop(SeedFinder& seeds, HoleTracker& holes, const QuiltOptions& options, QuiltStats& stats,
                   const SeedLoopDomain& domain) {
  while (true) {
    if (options.cancel) options.cancel->check();
    std::optional<int> seed_cell;
    {
      StageTimer timer(stats.stage_seconds, "seed");
      seed_cell = seeds.next_seed();
    }
    if (!seed_cell || (options.max_patches > 0 && stats.patches >= options.max_patches)) break;
    domain.quilt_patch_at(*seed_cell);
    {
      StageTimer timer(stats.stage_seconds, "seed");
      const bool was_processed = seeds.processed(*seed_cell);
      holes.attempted(*seed_cell);
      if (!was_processed && seeds.processed(*seed_cell) && domain.given_up) domain.given_up(*seed_cell);
    }
    ++stats.patches;
    if (options.progress) {
      QuiltProgress progress = domain.progress();
      progress.patches = stats.patches;
      options.progress(progress);
    }
  }
}

TriMesh finish_quilt(std::vector<TriMesh>& elements, std::vector<uint8_t>& alive, const std::vector<int32_t>& sources,
                     const QuiltSetup& setup, const QuiltOptions& options, QuiltStats& stats,
                     BrokenElements* removed_out, const FaceIntersections* known) {
  if (options.cleanup) {
    StageTimer timer(stats.stage_seconds, "cleanup");
    std::vector<const TriMesh*> meshes;
    for (const TriMesh& m : elements) meshes.push_back(&m);
    const BrokenElements removed = remove_broken_elements(meshes, setup.swatch.closed_elements, setup.swatch.unfolded_elements, alive, known);
    stats.dropped_open = removed.open;
    stats.dropped_folded = removed.folded;
    stats.dropped_intersecting = removed.intersecting;
    if (removed_out) *removed_out = removed;
  }
  stats.dropped_elements = stats.dropped_open + stats.dropped_folded + stats.dropped_intersecting;
  std::vector<TriMesh> kept;
  std::vector<int32_t> kept_sources;
  for (size_t i = 0; i < elements.size(); ++i)
    if (alive[i]) {
      kept.push_back(std::move(elements[i]));
      kept_sources.push_back(sources[i]);
    }
  TriMesh result = join_elements(kept);
  result.sources.resize(result.num_faces());
  for (size_t f = 0; f < result.num_faces(); ++f) result.sources[f] = kept_sources[result.elements[f]];
  return result;
}

}  // namespace meshquilt
