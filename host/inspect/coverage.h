#pragma once
//! How much of the domain a synthesized mesh covers, measured at the scale of its elements, and
//! how far its vertices sit from a base surface.

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>

#include "mesh/tri_mesh.h"

namespace meshquilt {

struct PlaneCoverageOptions {
  double margin = 0.02;            //!< fraction of the bbox width/height removed on each side
  //! Measure this x-y rectangle (lo, hi) instead of the shrunk bounding box, for example the plane
  //! a synthesis was asked to cover (synth's `plane_rect`): parts hanging past it do not count.
  std::optional<std::pair<glm::dvec2, glm::dvec2>> region;
  int64_t max_cells = 1 << 24;     //!< the cell size grows when the grid would have more cells
};

struct PlaneCoverage {
  double coverage = 0.0;     //!< covered cells / all cells of the footprint grid, in [0, 1]
  double largest_gap = 0.0;  //!< largest 4-connected set of uncovered cells / all cells
  double cell_size = 0.0;    //!< the cell size used (x and y; cells are square up to rounding)
  int32_t cells_x = 0, cells_y = 0;
};

//! Coverage of the x-y footprint of the mesh's bounding box (shrunk by options.margin of its
//! width and height on each side), or of options.region, on a grid of about `cell_size` square
//! cells (the count along each axis is rounded so the cells tile the footprint exactly): a cell is covered when the x-y
//! projection of some triangle overlaps it (closed sets, separating-axis test). With cell_size
//! half the median element's x-y extent, the hole inside a ring is no gap but a missing element
//! is. \throw InputError when cell_size is not positive and finite.
PlaneCoverage plane_coverage(const TriMesh& mesh, double cell_size, const PlaneCoverageOptions& options = {});

struct BaseCoverageOptions {
  std::optional<double> shell_height;  //!< H in units of the base's bbox diagonal; none: no top
  int64_t samples = 200000;            //!< about this many sample points on the base
  double below_tolerance = 1e-7;       //!< heights >= -this (bbox diagonals) count as on or above
};

struct BaseCoverage {
  double coverage = 0.0;    //!< area fraction of the base covered, in [0, 1]
  double height_min = 0.0;  //!< min signed height of the mesh's vertices, base bbox diagonals
  double height_max = 0.0;  //!< max signed height
  std::optional<int64_t> outside_shell_vertices;  //!< with shell_height: below 0 or above H
  double radius = 0.0;      //!< the coverage radius used (absolute units)
};

//! Signed distance of each point from the base surface, in units of the base's bbox diagonal:
//! the distance to the closest point of the base (FaceBvh), signed by the angle-weighted pseudo
//! normal of the closest feature (face, edge or vertex; Baerentzen and Aanaes 2005), which gives
//! the right side for closed bases and for open bases away from their border.
//! \pre base has faces, welded so that edges are shared by index.
std::vector<double> signed_heights(const std::vector<Vec3>& points, const TriMesh& base);

//! Heights of the mesh's vertices over `base` and the fraction of the base's area with output
//! geometry above it within the shell: a point of the base is covered when some vertex with
//! height in [-below_tolerance, H] (or >= -below_tolerance without H) has its closest point on
//! the base within `radius` of it. The base is sampled at about options.samples points spread by
//! area (stratified per face); coverage is the area-weighted covered fraction. With radius half
//! the median element extent the holes inside rings are not gaps, while a missing element is.
//! \pre base has faces and is welded. \throw InputError when radius is not positive and finite.
BaseCoverage base_coverage(const TriMesh& mesh, const TriMesh& base, double radius,
                           const BaseCoverageOptions& options = {});

//! The side of the largest axis-aligned square inside the x-y convex outline of `swatch`'s
//! geometry that no triangle's projection overlaps, rounded up to whole pixels of a raster with
//! `resolution` pixels along the longer side, plus one: a cell this large lies over geometry
//! wherever it sits inside the outline, so the gaps of a sparse swatch (the holes of rings) are
//! not counted as missing cover, while a missing element is. Two pixels for a swatch without a
//! free pixel (a sheet); 0 for a mesh without faces.
double largest_empty_square(const TriMesh& swatch, int resolution = 512);

//! The smallest cell, swatch_length / n for a whole n <= 64, at which `swatch` covers its own
//! footprint (plane_coverage 1.0) at four phases of the grid (origins a quarter cell apart, so
//! a sparse swatch does not pass because its wires happen to cross every cell): cells sized from
//! the swatch's largest gap, for measuring an output made of it at the swatch's own scale.
double self_covering_cell(const TriMesh& swatch, double swatch_length);

//! The faces of `mesh` whose centroid lies within the 2nd to 98th percentile of face centroids in
//! x and in y, with two tiny faces pinning the bounding box to that box: a quilted plane's body,
//! without the few elements that stick out past its border and would enlarge the footprint.
TriMesh plane_body(const TriMesh& mesh);

}  // namespace meshquilt
