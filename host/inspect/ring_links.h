#pragma once
//! The link graph of a ring mail (chain mail): which rings pass through which. Each element is
//! reduced to the closed centre line of a ring: its vertices binned by angle about their centroid
//! in their best-fit plane and averaged per bin. Two rings are linked when the Gauss linking
//! number of their centre lines is nonzero (computed exactly for polygons, after Klenin and
//! Langowski 2000, "Computation of writhe in modeling of supercoiled DNA").

#include <cstdint>
#include <utility>
#include <vector>

#include "mesh/tri_mesh.h"

namespace meshquilt {

//! The centre line of one ring.
struct RingCentreLine {
  Vec3 centre{0.0};
  Vec3 normal{0.0, 0.0, 1.0};  //!< of the best-fit plane (least spread)
  double radius = 0.0;         //!< mean distance of the centre line from the centre
  double aspect = 1.0;         //!< its longest over its shortest principal axis in the plane: 1 when round
  std::vector<Vec3> points;    //!< closed polygon, in angular order about `normal`
};

//! One centre line per element; `face_element` is #F element ids in [0, elements). An element
//! with fewer than 3 vertices gets an empty polygon. `bins` angular bins (empty bins skipped).
std::vector<RingCentreLine> ring_centre_lines(const TriMesh& mesh, const std::vector<int32_t>& face_element,
                                              int32_t elements, int bins = 24);

//! Gauss linking number of two closed polygons (each point joined to the next, the last to the
//! first): an integer for disjoint curves, returned unrounded. Sign follows the orientations.
double linking_number(const std::vector<Vec3>& a, const std::vector<Vec3>& b);

//! The link graph of a mesh's elements taken as rings.
struct RingLinks {
  int32_t rings = 0;
  std::vector<std::pair<int32_t, int32_t>> links;  //!< linked element pairs, first < second, sorted
  std::vector<int32_t> links_per_ring;             //!< #rings
  std::vector<int32_t> histogram;                  //!< rings with 0, 1, 2, ... links
  double linked_to_3_share = 0.0;                  //!< share of rings linked to >= 3 others
  double mean_links = 0.0;
  int32_t loose_rings = 0;                         //!< linked to nothing
  int32_t pieces = 0;                              //!< connected parts of the link graph
  double largest_piece_share = 0.0;                //!< rings in the largest part / rings
  double median_radius = 0.0;                      //!< of the centre lines
  double radius_p10 = 0.0, radius_p90 = 0.0;       //!< their 10th and 90th percentiles
  double median_aspect = 1.0, aspect_p90 = 1.0;    //!< of the centre lines' aspects
};

//! The rings whose centre lines' centres lie within `radius` of one of `points` (a layout's cones,
//! say), with their links counted over the whole mail.
struct RingsNear {
  int32_t rings = 0;
  std::vector<int32_t> histogram;   //!< of them, with 0, 1, 2, ... links
  double linked_to_3_share = 0.0;   //!< of them, linked to >= 3 others
  int32_t loose_rings = 0;
  double median_radius = 0.0, radius_p10 = 0.0, radius_p90 = 0.0;  //!< of their centre lines
};

//! \pre lines and links of the same mesh (ring_centre_lines, ring_links).
RingsNear rings_near(const RingLinks& links, const std::vector<RingCentreLine>& lines, const std::vector<Vec3>& points,
                     double radius);

//! Rings whose centre lines could meet (centres closer than the sum of their radii plus a
//! margin) are tested by linking_number. \pre as ring_centre_lines.
RingLinks ring_links(const TriMesh& mesh, const std::vector<int32_t>& face_element, int32_t elements);
//! The same from the rings' centre lines (ring_centre_lines), one per element.
RingLinks ring_links(const std::vector<RingCentreLine>& lines);

}  // namespace meshquilt
