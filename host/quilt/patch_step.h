#pragma once
//! One patch of mesh quilting in a 2D parameter plane (Sections 2.4-2.7 of the mesh quilting
//! paper): geometry matching over the output sub-patch, element correspondences, Laplacian
//! deformation and graph-cut merging, applied to the output elements as seen in that plane.
//!
//! The plane is whatever the driver makes of it: the output plane itself (planar_quilting) or a
//! surface patch's conformal parameter plane (surface_quilting). Positions are (x, y) in the plane
//! and z the height above it, in the swatch frame's units.
//!
//! Elements larger than a patch take part through their part inside the plane: the driver passes
//! the faces that lie in the plane and marks as `pinned` the vertices those faces share with the
//! rest of the element. Pinned vertices never move and are never cut away: a deformation restores
//! them exactly, and a merge or replacement whose result no longer holds every pinned vertex at
//! its exact position is refused. The driver then puts the part back by those vertices.

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "core/error.h"
#include "mesh/tri_mesh.h"
#include "mesh/convex_outline.h"
#include "mesh/measures.h"
#include "quilt/correspondence.h"
#include "quilt/element_deformation.h"
#include "quilt/merging/element_merging.h"
#include "quilt/geometry_matching.h"
#include "quilt/plane_rect.h"
#include "quilt/quilt_swatch.h"

namespace meshquilt {

class LatticeContacts;

//! A mesh placed in space with what collision tests measure of it: its box and its face runs'.
struct SpaceMesh {
  TriMesh mesh;
  Box3 box;
  std::vector<Box3> runs;  //!< face_run_boxes(mesh)
};

//! An output element (or its part inside the plane), in plane coordinates.
struct PlaneElement {
  TriMesh mesh;                  //!< no `elements` ids
  Rect2 bounds;                  //!< x-y bounds of mesh
  std::vector<uint8_t> pinned;   //!< #V, 1 where the part joins the rest of its element; empty: none
  int32_t source = -1;           //!< index of the swatch element it was copied from (first copy)
  bool alive = true;             //!< false once removed
  bool changed = false;          //!< set by the step when its mesh changed
  //! Where the whole element lies in space, when the driver knows it from before the patch (over
  //! a curved base): collision tests take it while the element is unchanged, rather than placing
  //! it again. Null: PatchRequest::to_space places it.
  std::shared_ptr<const SpaceMesh> in_space;
};

//! A regular grid over the plane: cells of `cell` size from `origin`, nx x ny of them.
struct PlaneGrid {
  glm::dvec2 origin{0.0};
  double cell = 1.0;
  int nx = 1, ny = 1;
  int column(double x) const;
  int row(double y) const;
  size_t index(int x, int y) const { return static_cast<size_t>(y) * nx + x; }
};

//! A rectangle of a PlaneGrid's cells, [x0, x1] x [y0, y1], with masks of its own: a patch only
//! reads and writes cells near its footprint, and whole-grid masks made large planes quadratic.
struct CellWindow {
  int x0 = 0, y0 = 0, x1 = -1, y1 = -1;
  int width() const { return x1 - x0 + 1; }
  size_t size() const { return x1 < x0 || y1 < y0 ? 0 : static_cast<size_t>(width()) * (y1 - y0 + 1); }
  bool contains(int x, int y) const { return x >= x0 && x <= x1 && y >= y0 && y <= y1; }
  size_t index(int x, int y) const { return static_cast<size_t>(y - y0) * width() + (x - x0); }
};

//! Options of the step (shared by every driver).
struct PatchStepOptions {
  double partner_distance = 0.5;  //!< merge partners' mean pair distance, in mean edge lengths, at most
  //! Inputs that are an output element already there (quilt/lattice_copies.h) skip the step;
  //! false sends them through it, which gives the same elements more slowly.
  bool skip_lattice_copies = true;
  //! How close, in the swatch's mean edge lengths, an input must lie to an output element to be it.
  double copy_tolerance = 1e-6;
  CorrespondenceOptions correspondence;
  DeformationOptions deformation;
  MergeOptions merging;
};

//! One patch: where it may go and where it must agree with the output.
struct PatchRequest {
  Rect2 sub_patch;                           //!< the output sub-patch around the seed
  std::vector<glm::dvec2> candidates;        //!< translations of the swatch to choose among
  //! Refine the chosen candidate continuously; false where the candidates are the only
  //! placements that fit (the swatch's periods in a shared surface layout).
  bool refine = true;
  //! Leave out an unpartnered input lying wholly over cells the output occupies. False where
  //! the placement is exact (a shared layout's periods): there such an input fills a gap
  //! between neighbours that occupy its cells, and the collision test keeps out duplicates.
  bool reject_covered_inputs = true;
  //! The layer elements the step may touch, ascending: those whose bounds meet the region any
  //! candidate placement covers, and those whose bounds meet theirs (a driver's index over a
  //! large layer). Elements the step appends join them. Null: every element of the layer.
  const std::vector<int32_t>* near = nullptr;
  //! Where the candidates are the swatch's lattice placements, its pattern's contacts: output
  //! elements that are unchanged copies on that lattice and come near no input leave the step
  //! (quilt/lattice_copies.h). Null: every output element under the footprint takes part.
  LatticeContacts* contacts = nullptr;
  PlaneGrid grid;                            //!< cells for the overlap's occupancy
  //! Whether a point of the plane lies in the output domain: inputs whose centre lies outside
  //! are not placed, and cells whose centre lies outside need no cover.
  std::function<bool(const glm::dvec2&)> inside_domain;
  //! Place only inputs whose every vertex lies inside the domain (a surface patch is a window on
  //! the surface: geometry past its edge has no place to go). Planar quilting lets elements whose
  //! centre is inside hang over the rectangle's edge.
  bool whole_inputs_only = false;
  //! Planar: where an element's centre may lie for a patch seeded again to place it (the plane
  //! grown by a quarter element). A left-out element centred there leaves at most a quarter of
  //! its width bare before its cells are seeded again; one centred beyond, half (see
  //! PatchOutcome::covered). Empty: half for every left-out element.
  std::function<bool(const glm::dvec2&)> reachable;
  //! A cell is covered only where each input over it is accounted for by what stands for it in
  //! the layer (see PatchOutcome::covered); false: where any kept geometry lies within a cell.
  //! On a surface, neighbouring patches register their elements less well than on a plane, and
  //! the strict rule would seed most cells again and again (four times the patches on the
  //! bunny) to count them as holes in the end.
  bool account_per_input = true;
  //! Where plane geometry ends up (a surface patch: embedded over the base); the collision
  //! policy tests there, since bending a layer over a curved base can make elements that are
  //! apart in the plane meet. Empty: the plane is the space.
  std::function<TriMesh(const TriMesh&)> to_space;
  //! Geometry already in that space that the step cannot change (the parts of output elements
  //! outside a surface patch); new and merged elements must not pass through it either.
  std::vector<TriMesh> obstacles;
};

//! Counters of what the merging did, summed over patches.
struct MergeCounts {
  int stitched = 0;              //!< related pairs cut and stitched into one element
  int bridged = 0;               //!< stitched inputs joined to a second output element they met end to end
  int replaced = 0;              //!< output elements replaced by an input element (kept_in)
  int kept = 0;                  //!< input elements that yielded to an output element (kept_out)
  int rejected_inputs = 0;       //!< unrelated input elements that would have collided
  int refused_merges = 0;        //!< merges whose result would have passed through a neighbour
  int undone_deformations = 0;   //!< output deformations undone because they hit a neighbour
  int refused_pinned = 0;        //!< changes refused because they would move a pinned vertex
  int lattice_copies = 0;        //!< inputs that were an output element already there (skipped the step)
};

//! What one step did.
struct PatchOutcome {
  MatchResult placement;                  //!< where the swatch went
  Rect2 footprint;                        //!< the placed swatch's x-y bounds
  std::vector<int32_t> added;             //!< indices of elements appended to the layer
  int inputs = 0;                         //!< swatch elements placed inside the domain
  //! #grid cells: 1 where the patch covered the cell, that is, the cell lies inside the footprint
  //! shrunk by one cell and every placed input over it is accounted for: what stands for it in
  //! the layer (the element it was added as, merged into or yielded to; with
  //! account_per_input false, any kept geometry) lies within a cell of it; under a swatch element
  //! left out at the domain's or the patch's edge, kept geometry within half its width. Cells
  //! inside the swatch's outline where it has no geometry are covered (a sparse swatch is mostly
  //! empty by design); cells outside it (the corners of a turned swatch) are not. A refused
  //! merge, a rejected input or an input that yielded to an element ending short of it leaves
  //! its cells uncovered, so the driver seeds there again.
  //! Over `window` (the footprint's cells); cells outside it are not covered.
  std::vector<uint8_t> covered;
  CellWindow window;
  //! Whether the point lies in a covered cell.
  bool covers(const PlaneGrid& grid, const glm::dvec2& p) const;
  //! Whether grid cell (x, y) is covered.
  bool covers_cell(int x, int y) const { return window.contains(x, y) && covered[window.index(x, y)] != 0; }
};

//! Runs one patch on `layer` (modified in place: elements deformed, merged, replaced; inputs
//! appended). Stage seconds accumulate in `seconds` under match, correspondence, deform, merge.
//! \pre `swatch` comes from prepare_swatch.
//! \throw SolverError, DeviceError from the stages; Cancelled when `cancel` is set.
PatchOutcome quilt_patch(std::vector<PlaneElement>& layer, const PatchRequest& request,
                         const QuiltSwatch& swatch, const GeometryMatcher& matcher,
                         const PatchStepOptions& options, std::mt19937_64& rng,
                         MergeCounts& counts, std::map<std::string, double>& seconds,
                         const CancelToken* cancel = nullptr);

}  // namespace meshquilt
