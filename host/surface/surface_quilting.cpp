#include "surface/surface_quilting.h"

#include "inspect/copy_sizes.h"
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <random>
#include <unordered_map>

#include <glm/geometric.hpp>
#include <tbb/parallel_for.h>

#include "core/error.h"
#include "mesh/measures.h"
#include "mesh/topology.h"
#include "quilt/merging/abutting_elements.h"
#include "spatial/intersecting_pairs.h"
#include "quilt/quilt_driver.h"
#include "quilt/stage_timer.h"
#include "quilt/lattice_classes.h"
#include "quilt/lattice_copies.h"
#include "quilt/quilt_policies.h"
#include "quilt/swatch_lattice.h"
#include "quilt/swatch_symmetry.h"
#include "surface/direction_field.h"
#include "surface/element_placement.h"
#include "surface/lattice_fill.h"
#include "surface/base_layout.h"
#include "surface/surface_cells.h"

namespace meshquilt {
namespace {

// The filled median may be this far off the size asked before the layout is laid out again,
// and is then brought this near.
constexpr double kSizeTolerance = 0.02;
constexpr double kSizeAim = 0.01;
// Filled elements that tell their median (a tenth of it at least), and the share of the base
// they must cover for it to stand for all (near cones and borders the patch step places
// elements of other sizes).
constexpr size_t kSizeSample = 2000;
constexpr double kSizeCover = 0.8;
// Cells within this share of a window's radius of a seed whose window folds seed no window.
constexpr double kFailedReach = 0.25;
// Layouts again at most.
constexpr int kSizeRounds = 3;

struct SurfaceElement {
  std::vector<LocalVertex> vertices;
  std::vector<int32_t> origins;  // the swatch vertex of each vertex (TriMesh::origins), or empty
  std::vector<Tri> triangles;
  int32_t source = -1;
  Box3 bounds;  // of the base points under it, for culling
  // Its vertices in space (position_during_synthesis), filled when a patch first needs them as
  // an obstacle; a changed element is a new one, so they never go stale.
  std::vector<Vec3> in_space;
  // The whole element in space for collision tests, made when a patch first holds it whole.
  std::shared_ptr<const SpaceMesh> placed;
};

void update_bounds(SurfaceElement& e, const BaseSurface& base) {
  std::vector<Vec3> points;
  points.reserve(e.vertices.size());
  for (const LocalVertex& v : e.vertices) points.push_back(base.position(v.point));
  e.bounds = bounding_box(points);
}

// The part of an element inside a patch, and how its vertices map back.
struct ElementPart {
  int32_t element = -1;
  std::vector<int32_t> element_vertex;  // part vertex -> element vertex
  std::vector<uint8_t> face_in_part;    // #element faces
  std::vector<Vec3> plane_positions;    // part vertex -> where it was put in the plane
};

// Angle that turns the field direction at `seed` (mapped into the patch's plane) onto +x.
double field_angle(const BaseSurface& base, const SurfacePatch& patch, const SurfacePoint& seed, const Vec3& d) {
  const Tri& t = base.mesh.triangles[seed.face];
  const Vec3 e1 = base.mesh.positions[t[1]] - base.mesh.positions[t[0]];
  const Vec3 e2 = base.mesh.positions[t[2]] - base.mesh.positions[t[0]];
  // d = a e1 + b e2 in the face plane (least squares through the Gram matrix).
  const double g11 = glm::dot(e1, e1), g12 = glm::dot(e1, e2), g22 = glm::dot(e2, e2);
  const double r1 = glm::dot(d, e1), r2 = glm::dot(d, e2);
  const double det = g11 * g22 - g12 * g12;
  if (det <= 0.0) return 0.0;
  const double a = (r1 * g22 - r2 * g12) / det, b = (r2 * g11 - r1 * g12) / det;
  const glm::dvec2 origin = patch.to_plane({seed.face, glm::dvec2(0.0)});
  const glm::dvec2 u1 = patch.to_plane({seed.face, glm::dvec2(1.0, 0.0)}) - origin;
  const glm::dvec2 u2 = patch.to_plane({seed.face, glm::dvec2(0.0, 1.0)}) - origin;
  const glm::dvec2 planar = a * u1 + b * u2;
  return -std::atan2(planar.y, planar.x);
}

// The surface driver's domain: cells over the base's triangles, a conformal patch around each
// seed (oriented by the field) as the plane the patch step works in, and elements kept in local
// coordinates (base point, height) between patches.
class SurfaceDriver {
 public:
  SurfaceDriver(const TriMesh& input_swatch, const TriMesh& base_mesh, const GuidanceField& field,
                engine::Device& device, const SurfaceQuiltOptions& options, SurfaceQuiltStats& stats)
      : options_(options), stats_(stats), seconds_(stats.stage_seconds), field_(field),
        setup_(input_swatch, device, options, stats), swatch_(setup_.swatch), cell_(setup_.cell), base_(base_mesh),
        // Base units per swatch unit.
        unit_(options.scale * base_.diagonal / std::max(swatch_.extent.x, swatch_.extent.y)),
        cells_(make_cells()), seeds_(cells_.neighbours), holes_(seeds_, options.seed_attempts),
        own_chart_(cells_.centres.size(), 0), rng_(options.seed) {
    stats_.base_faces = static_cast<int>(base_mesh.num_faces());
    stats_.diagonal = base_.diagonal;
    double thickness = 0.0;
    for (const Vec3& p : swatch_.mesh.positions) thickness = std::max(thickness, p.z);
    shell_ = options.shell_height > 0.0 ? options.shell_height : thickness * unit_;
    // Heights of the swatch frame map onto [0, shell].
    height_unit_ = thickness > 0.0 ? shell_ / thickness : unit_;
    stats_.shell_height = shell_;
    {
      StageTimer timer(seconds_, "shell");
      embedding_ = options.embedding ? options.embedding(base_, shell_) : std::make_unique<NormalEmbedding>(base_);
    }
    sub_nx_ = std::clamp(static_cast<int>(std::lround(setup_.swatch_nx * options.sub_patch_fraction)), 1, setup_.swatch_nx);
    sub_ny_ = std::clamp(static_cast<int>(std::lround(setup_.swatch_ny * options.sub_patch_fraction)), 1, setup_.swatch_ny);
    stats_.cell_size = cell_ * unit_;
    stats_.cells = static_cast<int>(cells_.centres.size());
    for (double a : cells_.areas) total_area_ += a;
    // A patch must hold the footprint of any placement that covers the sub-patch: a disk of the
    // swatch's diagonal around the seed, plus a cell.
    full_radius_ = (glm::length(swatch_.extent) + cell_) * unit_;
    if (options.shared_layout) {
      layout_ = make_layout();
      fill_ = make_fill();
    } else {
      for (size_t f = 0; f < base_mesh.num_faces(); ++f)
        face_field_.push_back(field_.at(base_, {static_cast<int32_t>(f), glm::dvec2(1.0 / 3.0)}));
    }
  }

  // The smoothest n-direction field that holds the guidance field's given directions, and the
  // layout that follows it.
  std::unique_ptr<BaseLayout> make_layout() {
    StageTimer timer(seconds_, "layout");
    const int n = options_.symmetry > 0 ? options_.symmetry : rotational_symmetry(swatch_);
    if (n != 1 && n != 2 && n != 4) throw OptionError("{symmetry} must be 1, 2 or 4");
    // A field the user drew is followed everywhere; the default one only breaks the smoothest
    // field's rotational freedom.
    const FieldTargets targets = field_targets(base_, field_);
    lattice_ = swatch_lattice(swatch_, n);
    if (lattice_) {
      contacts_ = std::make_unique<LatticeContacts>(swatch_, lattice_->basis, setup_.step.partner_distance * swatch_.mean_edge);
      classes_ = lattice_classes(swatch_, *lattice_, setup_.step.partner_distance * swatch_.mean_edge,
                                 setup_.step.copy_tolerance * swatch_.mean_edge);
      stand_alone_ = std::any_of(classes_.begin(), classes_.end(), [](const LatticeClass& c) { return c.alone; });
    }
    std::optional<std::array<glm::dvec2, 2>> periods;
    if (lattice_) periods = std::array<glm::dvec2, 2>{unit_ * lattice_->basis[0], unit_ * lattice_->basis[1]};
    auto layout = std::make_unique<BaseLayout>(base_, n, targets.target, targets.weight, !field_.held_vertices.empty(),
                                               periods, options_.size_hold, options_.cone_spread, stand_alone_);
    stats_.on_lattice = layout->layout().on_lattice;
    stats_.field_symmetry = n;
    stats_.cones = layout->cones();
    stats_.cone_points.clear();
    for (const auto& [face, point] : layout->cone_points()) stats_.cone_points.push_back(point);
    stats_.cone_indices = layout->layout().cone_indices;
    stats_.layout_scale_spread = layout->scale_spread();
    return layout;
  }

  // Where the layout carries the swatch's pattern, the elements that stand alone in it, placed
  // where nothing breaks it (a cone, a border).
  std::unique_ptr<LatticeFill> make_fill() {
    if (!lattice_ || !layout_->layout().on_lattice || !(options_.fill_margin > 0.0)) return nullptr;
    StageTimer timer(seconds_, "fill");
    std::vector<LatticeClass> classes = classes_;
    // A cone's neighbourhood is left to the patch step: a period and the widest element around it.
    double widest = std::max(glm::length(lattice_->basis[0]), glm::length(lattice_->basis[1]));
    for (const LatticeClass& c : classes) {
      const Rect2& b = swatch_.element_bounds[c.element];
      widest = std::max(widest, glm::length(b.hi - b.lo));
    }
    const double margin = options_.fill_margin * widest * unit_;
    auto fill = std::make_unique<LatticeFill>(base_, swatch_, *lattice_, std::move(classes),
                                              distance_to_breaks(base_, layout_->cone_points()), margin, unit_, height_unit_);
    return fill->any() ? std::move(fill) : nullptr;
  }

  // What one fill window placed, and the cells under it with their plane points.
  struct FillRecord {
    FilledWindow filled;
    std::vector<std::pair<int32_t, glm::dvec2>> cells;
  };

  // Fills the pattern; where the filled elements cover most of the base and their median size is
  // off the size asked, lays the same field out again to undo that and fills again (the layout's
  // own median holds the median face, not the median element: bunny rings 7% small). Then marks
  // the cells they cover.
  void fill_lattice() {
    if (!fill_) return;
    std::vector<FillRecord> records = fill_windows();
    // Rounding seams to periods moves the median less than the layout's scale: the second
    // correction is a secant step in log size.
    double correction = 1.0, last_correction = 1.0, last_size = 0.0;
    for (int round = 0; round < (options_.median_from_fill ? kSizeRounds : 0); ++round) {
      const double size = filled_median_size();
      const double tolerance = round == 0 ? kSizeTolerance : kSizeAim;
      if (!(size > 0.0) || std::abs(size - 1.0) <= tolerance || covered_share(records) < kSizeCover) break;
      double gain = 1.0;
      if (round > 0 && std::abs(std::log(correction / last_correction)) > 1e-9)
        gain = std::clamp(std::log(size / last_size) / std::log(correction / last_correction), 0.3, 1.5);
      const double next = correction * std::exp(-std::log(size) / gain);
      {
        StageTimer timer(seconds_, "layout");
        try {
          layout_->resize(next);
        } catch (const SolverError&) {
          break;  // the layout and fill as they were
        }
        stats_.on_lattice = layout_->layout().on_lattice;
        stats_.size_correction = next;
      }
      last_correction = correction;
      last_size = size;
      correction = next;
      elements_.clear();
      alive_.clear();
      fill_ = make_fill();
      if (!fill_) return;
      records = fill_windows();
    }
    StageTimer timer(seconds_, "fill");
    keep_apart_in_space();
    for (const int32_t cell : covered_cells(records)) {
      seeds_.mark_processed(cell);
      processed_area_ += cells_.areas[cell];
    }
    stats_.filled_elements = static_cast<int>(std::count(alive_.begin(), alive_.end(), 1));
  }

  // Places the pattern window by window, from every cell no earlier window held near its middle.
  std::vector<FillRecord> fill_windows() {
    StageTimer timer(seconds_, "fill");
    const int total_cells = static_cast<int>(cells_.centres.size());
    std::vector<uint8_t> tried(total_cells, 0);
    std::vector<FillRecord> records;
    for (int c = 0; c < total_cells; ++c) {
      if (tried[c]) continue;
      if (options_.cancel) options_.cancel->check();
      tried[c] = 1;
      // A window seeded where the pattern breaks would place little.
      if (fill_->near_break(cells_.centres[c])) continue;
      std::optional<SurfacePatch> window = grow_layout_window(base_, cells_.centres[c], full_radius_, *layout_);
      if (!window) {
        // Windows from seeds this near would hold the fold this one does (the mannequin's
        // layout folds 1% of its faces, scattered: 90% of its windows failed, one by one).
        const Vec3 seed = base_.position(cells_.centres[c]);
        const double reach = kFailedReach * full_radius_;
        for (int32_t f : ball_faces(base_, cells_.centres[c], reach))
          for (int32_t cell = cells_.face_offsets[f]; cell < cells_.face_offsets[f + 1]; ++cell)
            if (glm::distance(base_.position(cells_.centres[cell]), seed) < reach) tried[cell] = 1;
        continue;
      }
      window->transform(0.0, 1.0 / unit_);
      window->index();
      FillRecord record{fill_->fill(*window, window->origin + lattice_->centre), {}};
      for (FilledElement& f : record.filled.added) {
        SurfaceElement added;
        added.source = f.source;
        added.vertices = std::move(f.vertices);
        added.origins = swatch_.elements[f.source].origins;
        added.triangles = swatch_.elements[f.source].triangles;
        update_bounds(added, base_);
        elements_.push_back(std::move(added));
        alive_.push_back(1);
      }
      record.filled.added.clear();
      const double inner = 0.75 * full_radius_ / unit_;
      for (int32_t f : window->faces)
        for (int32_t cell = cells_.face_offsets[f]; cell < cells_.face_offsets[f + 1]; ++cell) {
          const glm::dvec2 p = window->to_plane(cells_.centres[cell]);
          if (glm::length(p) < inner) tried[cell] = 1;
          record.cells.emplace_back(cell, p);
        }
      records.push_back(std::move(record));
    }
    return records;
  }

  // The unprocessed cells the kept filled elements cover, each once, in the order of the records.
  std::vector<int32_t> covered_cells(const std::vector<FillRecord>& records) const {
    std::vector<uint8_t> covered(cells_.centres.size(), 0);
    std::vector<int32_t> cells;
    for (const FillRecord& record : records)
      for (const auto& [cell, p] : record.cells) {
        if (covered[cell] || seeds_.processed(cell) || !record.filled.covers(p, cell_, alive_)) continue;
        covered[cell] = 1;
        cells.push_back(cell);
      }
    return cells;
  }

  // The share of the base's area those cells make.
  double covered_share(const std::vector<FillRecord>& records) const {
    double area = 0.0;
    for (const int32_t cell : covered_cells(records)) area += cells_.areas[cell];
    return total_area_ > 0.0 ? area / total_area_ : 0.0;
  }

  // The median filled element's size in space over the size asked, as the stats measure it,
  // from at most kSizeSample of them spread over the fill; 0 with too few to tell.
  double filled_median_size() {
    if (elements_.size() < kSizeSample / 10) return 0.0;
    const size_t stride = std::max<size_t>(1, elements_.size() / kSizeSample);
    std::vector<double> sizes(elements_.size() / stride, 0.0);
    tbb::parallel_for(size_t{0}, sizes.size(), [&](size_t k) {
      SurfaceElement& element = elements_[k * stride];
      fill_in_space(element);
      const double asked = unit_ * gyration(swatch_.elements[element.source].positions);
      if (asked > 0.0) sizes[k] = gyration(element.in_space) / asked;
    });
    const auto middle = sizes.begin() + static_cast<std::ptrdiff_t>(sizes.size() / 2);
    std::nth_element(sizes.begin(), middle, sizes.end());
    return *middle;
  }

  // Where the shell bends the pattern, or the base passes through itself, filled elements can
  // pass through themselves or each other in space, where the step would have refused them: the
  // fewest that leave the rest apart are left to it, as the clean-up would choose them.
  void keep_apart_in_space() {
    tbb::parallel_for(size_t{0}, elements_.size(), [&](size_t e) { fill_in_space(elements_[e]); });
    std::vector<TriMesh> placed(elements_.size());
    std::vector<const TriMesh*> meshes;
    for (size_t e = 0; e < elements_.size(); ++e) {
      placed[e].positions = elements_[e].in_space;
      placed[e].triangles = elements_[e].triangles;
      meshes.push_back(&placed[e]);
    }
    remove_broken_elements(meshes, false, swatch_.unfolded_elements, alive_);
  }

  SurfaceQuilt run() {
    fill_lattice();
    SeedLoopDomain surface;
    surface.quilt_patch_at = [this](int seed_cell) { patch_at(seed_cell); };
    surface.given_up = [this](int cell) { processed_area_ += cells_.areas[cell]; };
    surface.progress = [this] {
      const int total_cells = static_cast<int>(cells_.centres.size());
      return QuiltProgress{processed_area_, total_area_, total_cells - seeds_.unprocessed_count(), total_cells, 0};
    };
    // What the fill covered shows before the first patch.
    if (fill_ && options_.progress) options_.progress(surface.progress());
    run_seed_loop(seeds_, holes_, options_, stats_, surface);
    return finish();
  }

 private:
  SurfaceCells make_cells() {
    StageTimer timer(seconds_, "cells");
    return make_surface_cells(base_, cell_ * unit_);
  }

  void patch_at(int seed_cell) {
    const SurfacePoint seed = cells_.centres[seed_cell];
    double shrink = 1.0;
    const SurfacePatch patch = grow_patch(seed, seed_cell, shrink);
    std::vector<PlaneElement> layer;
    std::vector<ElementPart> parts;
    std::vector<TriMesh> obstacles;
    {
      StageTimer timer(seconds_, "layer");
      collect_layer(patch, layer, parts, obstacles);
    }
    PatchRequest request = make_request(patch, shrink, std::move(obstacles));
    place_on_lattice(patch, request);
    const size_t existing = layer.size();
    const PatchOutcome outcome =
        quilt_patch(layer, request, swatch_, setup_.matcher, setup_.step, rng_, stats_.merges, seconds_, options_.cancel);
    {
      StageTimer timer(seconds_, "layer");
      put_back(patch, layer, parts, existing);
    }
    StageTimer timer(seconds_, "seed");
    for (int32_t f : patch.faces)
      for (int32_t c = cells_.face_offsets[f]; c < cells_.face_offsets[f + 1]; ++c) {
        if (seeds_.processed(c)) continue;
        if (!outcome.covers(request.grid, patch.to_plane(cells_.centres[c]))) continue;
        seeds_.mark_processed(c);
        processed_area_ += cells_.areas[c];
      }
    if (patch.chart != PatchChart::layout_window || seeds_.processed(seed_cell)) return;
    // Seeded again, a layout window is the same window (its distortion is never what failed).
    // Where the pattern's elements stand alone the lattice closes round a cone, and rings placed
    // off it there would link to none: a window that leaves the seed's face out (folded round a
    // cone) is all that can be placed there, and a cell it left uncovered is a hole. Yarns have
    // nothing else to cover it (most of the bunny's ears, where cones crowd): the cell is
    // seeded again with a chart of the patch alone, off the lattice.
    if (!stand_alone_) {
      own_chart_[seed_cell] = 1;
      return;
    }
    if (patch.face_index(seed.face) < 0) {
      seeds_.mark_processed(seed_cell);
    } else {
      holes_.give_up(seed_cell);
    }
    processed_area_ += cells_.areas[seed_cell];
  }

  // On a layout whose seams continue by the swatch's periods, the pattern fits only where a
  // point it turns about lies on a period (the layout's origin is one): a patch chooses among
  // those placements within its candidates' range, as they are, and a patch with nothing around
  // it starts the pattern there.
  void place_on_lattice(const SurfacePatch& patch, PatchRequest& request) {
    if (!lattice_ || !layout_ || !layout_->layout().on_lattice || patch.chart != PatchChart::layout_window) return;
    const glm::dvec2 shift = patch.origin + lattice_->centre;  // t + shift must be a period
    std::vector<glm::dvec2> placements = lattice_placements(request.candidates, shift, lattice_->basis, 1e-9 * cell_);
    // A lattice finer than the candidates' spacing by far would list more placements than there
    // are inputs to place: the candidates stay as matching chose them.
    if (placements.empty()) return;
    request.candidates = std::move(placements);
    request.refine = false;
    request.reject_covered_inputs = false;
    request.contacts = contacts_.get();
  }

  // A cell that a patch seeded on it did not cover is seeded again with twice the distortion
  // allowed: the same patch would fail the same way, and a patch shrunk below an element's
  // length places nothing (long yarns over the bunny's ears and cone-like vertices).
  SurfacePatch grow_patch(const SurfacePoint& seed, int seed_cell, double& shrink) {
    StageTimer timer(seconds_, "patch");
    const double max_distortion = options_.max_area_distortion * std::ldexp(1.0, holes_.tries(seed_cell));
    SurfacePatch patch;
    for (int attempt = 0;; ++attempt) {
      patch = grow_conformal_patch(base_, seed, full_radius_ * shrink, layout_ ? nullptr : &face_field_, layout_.get(),
                                   !own_chart_[seed_cell]);
      const bool good = patch.flipped_faces == 0 && patch.area_distortion <= max_distortion;
      if (good || attempt >= options_.max_shrinks) break;
      shrink *= 0.75;
    }
    if (shrink < 1.0) ++stats_.shrunk_patches;
    if (patch.chart == PatchChart::layout_window) ++stats_.layout_windows;
    // A layout window or a field-aligned chart already runs along the field; a conformal one is
    // turned to it.
    const bool turned = patch.chart == PatchChart::conformal;
    patch.transform(turned ? field_angle(base_, patch, seed, field_.at(base_, seed)) : 0.0, 1.0 / unit_);
    patch.index();
    return patch;
  }

  // The layer: parts of the elements that reach into the patch, in its plane; the rest of each
  // stays where it is, an obstacle in space.
  void collect_layer(const SurfacePatch& patch, std::vector<PlaneElement>& layer, std::vector<ElementPart>& parts,
                     std::vector<TriMesh>& obstacles) {
    // Whatever can touch geometry placed over the patch: elements whose base points come within
    // two shell heights of the patch's faces (both may stand up to a shell height off the base).
    // The patch's faces reach a ring of faces past its radius, so its box, not the radius, decides.
    std::vector<Vec3> patch_points;
    for (int32_t v : patch.vertices) patch_points.push_back(base_.mesh.positions[v]);
    Box3 reach = bounding_box(patch_points);
    reach.lo -= Vec3(2.0 * shell_);
    reach.hi += Vec3(2.0 * shell_);
    std::vector<size_t> near;
    for (size_t e = 0; e < elements_.size(); ++e)
      if (alive_[e] && elements_[e].bounds.overlaps(reach)) near.push_back(e);
    // Each element's part is its own: gathered side by side, then kept in element order.
    std::vector<CollectedPart> collected(near.size());
    tbb::parallel_for(size_t{0}, near.size(), [&](size_t k) { collected[k] = collect_part(patch, near[k]); });
    for (CollectedPart& c : collected) {
      if (c.obstacle) obstacles.push_back(std::move(*c.obstacle));
      if (c.plane.mesh.triangles.empty()) continue;
      layer.push_back(std::move(c.plane));
      parts.push_back(std::move(c.part));
    }
  }

  // An element's part inside a patch, in its plane, and the rest of it in space.
  struct CollectedPart {
    PlaneElement plane;
    ElementPart part;
    std::optional<TriMesh> obstacle;
  };

  CollectedPart collect_part(const SurfacePatch& patch, size_t e) {
    SurfaceElement& element = elements_[e];
    CollectedPart out;
    std::vector<uint8_t> vertex_in(element.vertices.size());
    for (size_t v = 0; v < element.vertices.size(); ++v)
      vertex_in[v] = patch.face_index(element.vertices[v].point.face) >= 0;
    ElementPart& part = out.part;
    part.element = static_cast<int32_t>(e);
    part.face_in_part.assign(element.triangles.size(), 0);
    std::vector<int32_t> part_vertex(element.vertices.size(), -1);
    std::vector<uint8_t> used_outside(element.vertices.size(), 0);
    PlaneElement& plane = out.plane;
    for (size_t f = 0; f < element.triangles.size(); ++f) {
      const Tri& t = element.triangles[f];
      const bool inside = vertex_in[t[0]] && vertex_in[t[1]] && vertex_in[t[2]];
      if (!inside) {
        for (int32_t v : t) used_outside[v] = 1;
        continue;
      }
      part.face_in_part[f] = 1;
      Tri local;
      for (int k = 0; k < 3; ++k) {
        int32_t& index = part_vertex[t[k]];
        if (index < 0) {
          index = static_cast<int32_t>(plane.mesh.positions.size());
          const LocalVertex& lv = element.vertices[t[k]];
          plane.mesh.positions.push_back(Vec3(patch.to_plane(lv.point), lv.height / height_unit_));
          if (!element.origins.empty()) plane.mesh.origins.push_back(element.origins[t[k]]);
          part.element_vertex.push_back(t[k]);
        }
        local[k] = index;
      }
      plane.mesh.triangles.push_back(local);
    }
    if (std::find(part.face_in_part.begin(), part.face_in_part.end(), 0) != part.face_in_part.end())
      out.obstacle = rest_in_space(element, part);
    if (plane.mesh.triangles.empty()) return out;
    plane.pinned.assign(plane.mesh.positions.size(), 0);
    bool any_pinned = false;
    for (size_t k = 0; k < part.element_vertex.size(); ++k)
      if (used_outside[part.element_vertex[k]]) {
        plane.pinned[k] = 1;
        any_pinned = true;
      }
    if (!any_pinned) plane.pinned.clear();
    plane.bounds = xy_bounds(plane.mesh);
    plane.source = element.source;
    if (!any_pinned) plane.in_space = placed_in_space(element);
    part.plane_positions = plane.mesh.positions;
    return out;
  }

  // The whole element in space, placed once: each patch around it tests collisions against it.
  std::shared_ptr<const SpaceMesh> placed_in_space(SurfaceElement& element) const {
    if (!element.placed) {
      fill_in_space(element);
      auto placed = std::make_shared<SpaceMesh>();
      placed->mesh.positions = element.in_space;
      placed->mesh.triangles = element.triangles;
      placed->box = bounding_box(placed->mesh.positions);
      placed->runs = face_run_boxes(placed->mesh);
      element.placed = std::move(placed);
    }
    return element.placed;
  }

  void fill_in_space(SurfaceElement& element) const {
    if (element.in_space.empty())
      for (const LocalVertex& lv : element.vertices)
        element.in_space.push_back(embedding_->position_during_synthesis(lv.point, lv.height));
  }

  // The faces of an element outside its part, in space, less those at the seam: they touch the
  // part at its pinned vertices, and as an obstacle would refuse every change to it there.
  TriMesh rest_in_space(SurfaceElement& element, const ElementPart& part) const {
    fill_in_space(element);
    std::vector<uint8_t> on_part(element.vertices.size(), 0);
    for (size_t f = 0; f < element.triangles.size(); ++f)
      if (part.face_in_part[f])
        for (int32_t v : element.triangles[f]) on_part[v] = 1;
    TriMesh rest;
    for (size_t f = 0; f < element.triangles.size(); ++f) {
      if (part.face_in_part[f]) continue;
      const Tri& t = element.triangles[f];
      if (on_part[t[0]] || on_part[t[1]] || on_part[t[2]]) continue;
      const int32_t first = static_cast<int32_t>(rest.positions.size());
      for (int32_t v : element.triangles[f]) rest.positions.push_back(element.in_space[v]);
      rest.triangles.push_back({first, first + 1, first + 2});
    }
    return rest;
  }

  PatchRequest make_request(const SurfacePatch& patch, double shrink, std::vector<TriMesh> obstacles) const {
    PatchRequest request;
    const glm::dvec2 half = 0.5 * cell_ * glm::dvec2(sub_nx_, sub_ny_) * shrink;
    request.sub_patch = {-half, half};
    for (double ty = half.y - swatch_.extent.y; ty <= -half.y + 1e-9 * cell_; ty += cell_)
      for (double tx = half.x - swatch_.extent.x; tx <= -half.x + 1e-9 * cell_; tx += cell_)
        request.candidates.emplace_back(tx, ty);
    if (request.candidates.empty()) request.candidates.emplace_back(-0.5 * swatch_.extent);
    glm::dvec2 lo(std::numeric_limits<double>::max()), hi(std::numeric_limits<double>::lowest());
    for (const glm::dvec2& p : patch.uv) {
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
    request.grid.origin = lo;
    request.grid.cell = cell_;
    request.grid.nx = std::max(1, static_cast<int>(std::ceil((hi.x - lo.x) / cell_)));
    request.grid.ny = std::max(1, static_cast<int>(std::ceil((hi.y - lo.y) / cell_)));
    request.inside_domain = [&patch](const glm::dvec2& p) { return patch.locate(p).has_value(); };
    request.whole_inputs_only = true;
    request.account_per_input = false;
    request.obstacles = std::move(obstacles);
    request.to_space = [this, &patch](const TriMesh& plane_mesh) {
      TriMesh placed;
      placed.triangles = plane_mesh.triangles;
      placed.positions.reserve(plane_mesh.positions.size());
      for (const Vec3& p : plane_mesh.positions) {
        const std::optional<SurfacePoint> at = patch.locate(glm::dvec2(p));
        const SurfacePoint point = at ? *at : patch.nearest(glm::dvec2(p));
        placed.positions.push_back(embedding_->position_during_synthesis(point, p.z * height_unit_));
      }
      return placed;
    };
    return request;
  }

  // The layer back into local coordinates: new elements added, changed parts put back, elements
  // joined into others gone.
  void put_back(const SurfacePatch& patch, const std::vector<PlaneElement>& layer, const std::vector<ElementPart>& parts,
                size_t existing) {
    // Plane point -> local coordinates; a point outside every patch face goes to the nearest.
    const auto to_local = [&](const Vec3& p) {
      std::optional<SurfacePoint> at = patch.locate(glm::dvec2(p));
      if (!at) {
        ++stats_.outside_vertices;
        at = patch.nearest(glm::dvec2(p));
      }
      return LocalVertex{*at, p.z * height_unit_};
    };
    for (size_t l = 0; l < layer.size(); ++l) {
      const PlaneElement& plane = layer[l];
      if (!plane.changed) continue;
      if (l >= existing) {
        SurfaceElement added;
        added.source = plane.source;
        for (const Vec3& p : plane.mesh.positions) added.vertices.push_back(to_local(p));
        added.origins = plane.mesh.origins;
        added.triangles = plane.mesh.triangles;
        update_bounds(added, base_);
        elements_.push_back(std::move(added));
        alive_.push_back(1);
        continue;
      }
      // An element joined into another one (only whole elements are, never parts) is gone.
      if (!plane.alive) {
        alive_[parts[l].element] = 0;
        continue;
      }
      SurfaceElement& element = elements_[parts[l].element];
      element = rebuilt(element, parts[l], plane, to_local);
    }
  }

  // An element with its part replaced: faces outside the part stay; vertices that did not move
  // keep their local coordinates exactly (the pinned ones among them join the part to the rest).
  template <typename ToLocal>
  SurfaceElement rebuilt(const SurfaceElement& element, const ElementPart& part, const PlaneElement& plane,
                         const ToLocal& to_local) const {
    std::unordered_map<Vec3, int32_t, ExactPositionHash> unmoved;
    for (size_t k = 0; k < part.element_vertex.size(); ++k) unmoved.emplace(part.plane_positions[k], part.element_vertex[k]);
    SurfaceElement result;
    result.source = plane.source;
    const bool with_origins = !element.origins.empty() || !plane.mesh.origins.empty();
    std::vector<int32_t> kept_index(element.vertices.size(), -1);
    const auto keep = [&](int32_t v) {
      if (kept_index[v] < 0) {
        kept_index[v] = static_cast<int32_t>(result.vertices.size());
        result.vertices.push_back(element.vertices[v]);
        if (with_origins) result.origins.push_back(v < static_cast<int32_t>(element.origins.size()) ? element.origins[v] : -1);
      }
      return kept_index[v];
    };
    for (size_t f = 0; f < element.triangles.size(); ++f) {
      if (part.face_in_part[f]) continue;
      const Tri& t = element.triangles[f];
      result.triangles.push_back({keep(t[0]), keep(t[1]), keep(t[2])});
    }
    std::vector<int32_t> new_index(plane.mesh.positions.size());
    for (size_t k = 0; k < plane.mesh.positions.size(); ++k) {
      const auto it = unmoved.find(plane.mesh.positions[k]);
      if (it != unmoved.end()) {
        new_index[k] = keep(it->second);
      } else {
        new_index[k] = static_cast<int32_t>(result.vertices.size());
        result.vertices.push_back(to_local(plane.mesh.positions[k]));
        if (with_origins) result.origins.push_back(k < plane.mesh.origins.size() ? plane.mesh.origins[k] : -1);
      }
    }
    for (const Tri& t : plane.mesh.triangles) result.triangles.push_back({new_index[t[0]], new_index[t[1]], new_index[t[2]]});
    update_bounds(result, base_);
    return result;
  }

  // Face pairs named by element and face within it.
  struct ElementFacePairs {
    std::vector<std::array<int32_t, 4>> different, same;  // element, face, element, face
  };

  ElementFacePairs element_pairs(const FaceIntersections& found, const std::vector<size_t>& placed) const {
    std::vector<int32_t> element_of, local;
    for (size_t e : placed)
      for (size_t f = 0; f < elements_[e].triangles.size(); ++f) {
        element_of.push_back(static_cast<int32_t>(e));
        local.push_back(static_cast<int32_t>(f));
      }
    ElementFacePairs out;
    for (const auto& [a, b] : found.different_elements) out.different.push_back({element_of[a], local[a], element_of[b], local[b]});
    for (const auto& [a, b] : found.same_element) out.same.push_back({element_of[a], local[a], element_of[b], local[b]});
    return out;
  }

  // The pairs among the elements still placed, as faces of their placement.
  FaceIntersections remaining_pairs(const ElementFacePairs& pairs, const std::vector<size_t>& placed) const {
    std::vector<int32_t> first(elements_.size(), -1);
    int32_t next = 0;
    for (size_t e : placed) {
      first[e] = next;
      next += static_cast<int32_t>(elements_[e].triangles.size());
    }
    const auto carry = [&](const std::vector<std::array<int32_t, 4>>& from, std::vector<FacePair>& to) {
      for (const auto& [e, f, d, g] : from)
        if (first[e] >= 0 && first[d] >= 0) {
          const int32_t a = first[e] + f, b = first[d] + g;
          to.emplace_back(std::min(a, b), std::max(a, b));
        }
      std::sort(to.begin(), to.end());
    };
    FaceIntersections out;
    carry(pairs.different, out.different_elements);
    carry(pairs.same, out.same_element);
    return out;
  }

  // Every alive element placed in space by the final embedding, as one batch; `met`, the faces
  // that meet there, where the placement tested them last.
  std::vector<TriMesh> embed_elements(std::optional<FaceIntersections>* met = nullptr) {
    StageTimer timer(seconds_, "embed");
    std::vector<TriMesh> embedded(elements_.size());
    std::vector<LocalVertex> vertices;
    std::vector<Tri> triangles;
    std::vector<int32_t> face_element;
    std::vector<size_t> placed;  // element of each placed one
    for (size_t e = 0; e < elements_.size(); ++e) {
      if (!alive_[e]) continue;
      const auto first = static_cast<int32_t>(vertices.size());
      vertices.insert(vertices.end(), elements_[e].vertices.begin(), elements_[e].vertices.end());
      for (const Tri& t : elements_[e].triangles) {
        triangles.push_back({t[0] + first, t[1] + first, t[2] + first});
        face_element.push_back(static_cast<int32_t>(placed.size()));
      }
      placed.push_back(e);
    }
    // Placed again with fewer elements, those left meet through the final map as they did.
    std::optional<FaceIntersections> final_map;
    if (final_map_met_) final_map = remaining_pairs(*final_map_met_, placed);
    ElementPlacement placement =
        place_elements(*embedding_, vertices, triangles, face_element, 4, final_map ? &*final_map : nullptr);
    stats_.synthesis_map_elements = placement.moved_elements();
    if (met) *met = std::move(placement.intersections);
    if (placement.final_map_intersections) final_map_met_ = element_pairs(*placement.final_map_intersections, placed);
    size_t next = 0;
    for (const size_t e : placed) {
      TriMesh& mesh = embedded[e];
      const auto begin = placement.positions.begin() + static_cast<std::ptrdiff_t>(next);
      next += elements_[e].vertices.size();
      mesh.positions.assign(begin, placement.positions.begin() + static_cast<std::ptrdiff_t>(next));
      mesh.triangles = elements_[e].triangles;
      mesh.origins = elements_[e].origins;
    }
    return embedded;
  }

  SurfaceQuilt finish() {
    std::optional<FaceIntersections> met;
    std::vector<TriMesh> embedded = embed_elements(&met);
    std::vector<int32_t> sources;
    for (const SurfaceElement& e : elements_) sources.push_back(e.source);
    BrokenElements removed;
    SurfaceQuilt result;
    result.mesh = finish_quilt(embedded, alive_, sources, setup_, options_, stats_, &removed, met ? &*met : nullptr);
    if (stats_.dropped_elements > 0 && embedding_->has_synthesis_map() && stats_.synthesis_map_elements > 0) {
      // Which map an element goes through depends on the others present: place the kept ones
      // again, so that `embed` of the texture over this base gives this output back (with none
      // through the synthesis map, fewer elements change nothing).
      std::vector<TriMesh> kept = embed_elements();
      QuiltOptions joined_only = options_;
      joined_only.cleanup = false;
      result.mesh = finish_quilt(kept, alive_, sources, setup_, joined_only, stats_, nullptr);
    }
    stats_.intersecting_face_pairs = removed.intersecting_face_pairs;
    const HoleSummary hole_summary = holes_.summary(cells_.neighbours, cells_.areas);
    stats_.holes = hole_summary.holes;
    stats_.hole_cells = hole_summary.cells;
    stats_.hole_area = hole_summary.area;
    stats_.largest_hole_area = hole_summary.largest_area;
    stats_.covered_area = processed_area_ - stats_.hole_area;
    for (size_t e = 0; e < elements_.size(); ++e)
      if (alive_[e]) result.local.insert(result.local.end(), elements_[e].vertices.begin(), elements_[e].vertices.end());
    if (options_.cleanup) {
      // Windows on the swatch's periods place a yarn's copies end to end, cap on cap.
      StageTimer timer(seconds_, "cleanup");
      std::vector<int32_t> kept;
      stats_.joined_elements = join_abutting_elements(result.mesh, kWeldTolerance, &kept);
      if (stats_.joined_elements > 0) {
        std::vector<LocalVertex> local;
        local.reserve(kept.size());
        for (int32_t v : kept) local.push_back(result.local[v]);
        result.local = std::move(local);
        // A joined yarn is one element to the map that places it, as to `embed` after it.
        if (embedding_->has_synthesis_map())
          result.mesh.positions = place_elements(*embedding_, result.local, result.mesh.triangles, result.mesh.elements).positions;
      }
    }
    stats_.element_size = copy_sizes(result.mesh, swatch_.elements, unit_);
    return result;
  }

  const SurfaceQuiltOptions& options_;
  SurfaceQuiltStats& stats_;
  std::map<std::string, double>& seconds_;
  const GuidanceField& field_;
  const QuiltSetup setup_;
  const QuiltSwatch& swatch_;
  const double cell_;
  const BaseSurface base_;
  const double unit_;
  SurfaceCells cells_;
  SeedFinder seeds_;
  HoleTracker holes_;
  std::vector<uint8_t> own_chart_;  //!< per cell: a layout window left it uncovered
  std::mt19937_64 rng_;
  double shell_ = 0.0, height_unit_ = 0.0, full_radius_ = 0.0;
  int sub_nx_ = 1, sub_ny_ = 1;
  double total_area_ = 0.0, processed_area_ = 0.0;
  std::unique_ptr<SurfaceEmbedding> embedding_;
  std::unique_ptr<BaseLayout> layout_;
  std::unique_ptr<LatticeContacts> contacts_;  // its pattern's contacts, where it has periods
  std::unique_ptr<LatticeFill> fill_;  // where the layout carries a pattern with elements that stand alone
  std::optional<ElementFacePairs> final_map_met_;  // faces that met with every element through the final map
  std::optional<SwatchLattice> lattice_;  // the swatch's periods, where its pattern repeats
  std::vector<LatticeClass> classes_;     // its elements' classes in the lattice
  bool stand_alone_ = false;              // some of them stand alone (rings, not yarns)
  std::vector<Vec3> face_field_;  // per base face, for field-aligned charts of single patches
  std::vector<SurfaceElement> elements_;
  std::vector<uint8_t> alive_;
};

}  // namespace

SurfaceQuilt quilt_surface(const TriMesh& input_swatch, const TriMesh& base_mesh, const GuidanceField& field,
                           engine::Device& device, const SurfaceQuiltOptions& options, SurfaceQuiltStats* stats_out) {
  if (!(options.scale > 0.0) || !std::isfinite(options.scale)) throw OptionError("{scale} must be positive");
  if (options.shell_height < 0.0 || !std::isfinite(options.shell_height))
    throw OptionError("{shell_height} must not be negative");
  SurfaceQuiltStats stats;
  SurfaceQuilt result = SurfaceDriver(input_swatch, base_mesh, field, device, options, stats).run();
  if (stats_out) *stats_out = stats;
  return result;
}

}  // namespace meshquilt
