#include "inspect/inspect_report.h"

#include <chrono>
#include <cmath>
#include <sstream>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "inspect/element_statistics.h"
#include "inspect/element_topology.h"
#include "inspect/ring_links.h"
#include "inspect/yarn_lengths.h"
#include "mesh/measures.h"
#include "spatial/intersecting_pairs.h"

namespace meshquilt {
namespace {

class StageTimer {
 public:
  explicit StageTimer(std::vector<std::pair<std::string, double>>& out) : out_(out) {}
  void lap(const char* name) {
    const auto now = std::chrono::steady_clock::now();
    out_.emplace_back(name, std::chrono::duration<double>(now - last_).count());
    last_ = now;
  }

 private:
  std::vector<std::pair<std::string, double>>& out_;
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

TriMesh welded_or_throw(const TriMesh& mesh, double tolerance, const std::string& name) {
  TriMesh welded = weld_vertices(mesh, tolerance);
  welded.elements.clear();  // elements are the connected components here
  if (welded.num_faces() == 0) throw InputError(name + ": no faces left after welding coincident vertices");
  return welded;
}

// The xy area a mesh's elements were grown over: the region asked, or the mesh's xy footprint.
double plane_area(const TriMesh& mesh, const PlaneCoverageOptions& options) {
  if (options.region) {
    const auto& [lo, hi] = *options.region;
    return (hi.x - lo.x) * (hi.y - lo.y);
  }
  const Box3 box = bounding_box(mesh.positions);
  return (box.hi.x - box.lo.x) * (box.hi.y - box.lo.y);
}

double surface_area(const TriMesh& mesh) {
  double area = 0.0;
  for (const Tri& t : mesh.triangles)
    area += 0.5 * glm::length(glm::cross(mesh.positions[t[1]] - mesh.positions[t[0]], mesh.positions[t[2]] - mesh.positions[t[0]]));
  return area;
}

// Rings per unit of x-y area in a swatch, counted in windows of its ring centres' span (each side
// 15% to 35% in, eleven windows averaged: a single window's edges fall on rows of a lattice or
// between them, and the count jumps), away from the border where the tiling's period and the
// swatch's extent differ. Nothing for a swatch too small for the windows to hold 4 rings.
std::optional<double> ring_density(const std::vector<RingCentreLine>& lines) {
  glm::dvec2 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (const RingCentreLine& l : lines) lo = glm::min(lo, glm::dvec2(l.centre)), hi = glm::max(hi, glm::dvec2(l.centre));
  double sum = 0.0;
  int windows = 0;
  for (int k = 0; k <= 10; ++k) {
    const double in = 0.15 + 0.02 * k;
    const glm::dvec2 a = lo + in * (hi - lo), b = hi - in * (hi - lo);
    int inside = 0;
    for (const RingCentreLine& l : lines)
      inside += l.centre.x >= a.x && l.centre.x <= b.x && l.centre.y >= a.y && l.centre.y <= b.y;
    const double window = (b.x - a.x) * (b.y - a.y);
    if (inside < 4 || !(window > 0.0)) continue;
    sum += inside / window;
    ++windows;
  }
  if (windows == 0) return std::nullopt;
  return sum / windows;
}

InspectReport::Rings ring_report(const RingLinks& links) {
  InspectReport::Rings r;
  r.rings = links.rings;
  r.links = static_cast<int64_t>(links.links.size());
  r.histogram = links.histogram;
  r.linked_to_3_share = links.linked_to_3_share;
  r.mean_links = links.mean_links;
  r.loose_rings = links.loose_rings;
  r.pieces = links.pieces;
  r.largest_piece_share = links.largest_piece_share;
  r.median_radius = links.median_radius;
  r.radius_p10 = links.radius_p10;
  r.radius_p90 = links.radius_p90;
  r.median_aspect = links.median_aspect;
  r.aspect_p90 = links.aspect_p90;
  return r;
}

// Median element size, with a fallback for flat or point-like elements so grids stay finite.
double positive_median(const std::vector<double>& values, double fallback) {
  const double m = median(values);
  return m > 0.0 && std::isfinite(m) ? m : fallback;
}

}  // namespace

InspectReport inspect_mesh(const TriMesh& input, const InspectOptions& options, const TriMesh* swatch_input,
                           const TriMesh* base_input) {
  if (options.plane && base_input) throw OptionError("inspect: {plane} and {base} exclude each other");
  InspectReport report;
  StageTimer timer(report.timings);
  report.weld_tolerance = options.weld_tolerance;
  const TriMesh mesh = welded_or_throw(input, options.weld_tolerance, options.mesh_name);
  report.faces = static_cast<int64_t>(mesh.num_faces());
  report.vertices = static_cast<int64_t>(mesh.num_vertices());
  timer.lap("weld");

  const ElementTopology topology = element_topology(mesh);
  report.elements = topology.elements;
  report.closed_elements = topology.closed_elements;
  report.boundary_edges = topology.boundary_edges;
  report.nonmanifold_edges = topology.nonmanifold_edges;
  report.nonmanifold_vertices = topology.nonmanifold_vertices;
  timer.lap("topology");

  const FaceIntersections pairs = find_intersecting_faces(mesh, topology.face_element);
  report.intersecting_face_pairs = static_cast<int64_t>(pairs.different_elements.size());
  report.self_intersecting_face_pairs = static_cast<int64_t>(pairs.same_element.size());
  timer.lap("intersections");

  Vec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (const Vec3& p : mesh.positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  const double diagonal = glm::length(hi - lo);
  const ElementMeasures measures = element_measures(mesh, topology.face_element, topology.elements);
  report.median_element_area = median(measures.area);
  report.median_element_extent = median(measures.extent);
  timer.lap("element sizes");

  if (options.rings) {
    const std::vector<RingCentreLine> lines = ring_centre_lines(mesh, topology.face_element, topology.elements);
    const RingLinks links = ring_links(lines);
    report.rings = ring_report(links);
    if (!options.near_points.empty()) {
      InspectReport::Rings::Near near;
      near.points = static_cast<int32_t>(options.near_points.size());
      near.radius = options.near_radius * links.median_radius;
      near.rings = rings_near(links, lines, options.near_points, near.radius);
      report.rings->near = near;
    }
    timer.lap("rings");
  }
  if (options.yarns) {
    const TubeMeasures tubes = tube_measures(mesh, topology.face_element, topology.elements);
    InspectReport::Yarns y;
    y.median_radius = median_tube_radius(tubes, &y.yarns);
    y.weighted_median_length = length_weighted_median(tubes.length);
    report.yarns = y;
    timer.lap("yarns");
  }

  double swatch_gap_cell = 0.0, output_edge = 0.0;
  if (swatch_input) {
    const TriMesh swatch = welded_or_throw(*swatch_input, options.weld_tolerance, options.swatch_name);
    int32_t count = 0;
    const std::vector<int32_t> swatch_elements = face_components(swatch, &count);
    if (report.yarns) {
      const TubeMeasures tubes = tube_measures(swatch, swatch_elements, count);
      const double length = length_weighted_median(tubes.length);
      const double radius = median_tube_radius(tubes);
      if (length > 0.0 && radius > 0.0 && report.yarns->median_radius > 0.0) {
        report.yarns->swatch_length = length;
        report.yarns->radius_ratio = report.yarns->median_radius / radius;
        report.yarns->in_swatch_lengths = report.yarns->weighted_median_length / (length * *report.yarns->radius_ratio);
      }
    }
    if (report.rings) {
      const std::vector<RingCentreLine> swatch_lines = ring_centre_lines(swatch, swatch_elements, count);
      const RingLinks swatch_rings = ring_links(swatch_lines);
      if (swatch_rings.median_radius > 0.0)
        report.rings->radius_ratio = report.rings->median_radius / swatch_rings.median_radius;
      if (options.scale && base_input && swatch_rings.median_radius > 0.0) {
        const Vec3 extent = bounding_box(swatch.positions).extent();
        const double longer = std::max(extent.x, extent.y);
        if (longer > 0.0)
          report.rings->asked_radius = swatch_rings.median_radius * *options.scale *
                                       glm::length(bounding_box(base_input->positions).extent()) / longer;
      }
      const std::optional<double> density = ring_density(swatch_lines);
      if (density && options.plane) report.rings->expected_rings = *density * plane_area(mesh, options.plane_options);
      // Over a base the swatch was scaled: its density follows from the ring sizes.
      if (density && base_input && report.rings->radius_ratio)
        report.rings->expected_rings =
            *density / (*report.rings->radius_ratio * *report.rings->radius_ratio) * surface_area(*base_input);
    }
    const ElementMeasures sm = element_measures(swatch, swatch_elements, count);
    // The swatch's own gaps are not missing cover. They are scaled as its edges are: elements
    // stitched into longer ones change their extents, not their tessellation.
    const double swatch_edge = mean_edge_length(swatch);
    output_edge = mean_edge_length(mesh);
    if ((options.plane || base_input) && swatch_edge > 0.0 && output_edge > 0.0)
      swatch_gap_cell = largest_empty_square(swatch) * output_edge / swatch_edge;
    InspectReport::Swatch s;
    s.elements = count;
    s.intersecting_face_pairs = static_cast<int64_t>(find_intersecting_faces(swatch, swatch_elements).different_elements.size());
    s.element_area_ks = ks_distance(measures.area, sm.area);
    s.element_extent_ks = ks_distance(measures.extent, sm.extent);
    report.swatch = s;
    timer.lap("swatch");
  }

  if (options.plane) {
    // With a swatch, cells as large as its largest gap; without, half the median element (which
    // for yarns stitched into long runs is far coarser).
    const double cell = swatch_gap_cell > 0.0
                            ? swatch_gap_cell
                            : 0.5 * positive_median(measures.xy_extent, 0.01 * std::max(hi.x - lo.x, hi.y - lo.y));
    report.plane = plane_coverage(mesh, cell > 0.0 ? cell : 1.0, options.plane_options);
    timer.lap("plane coverage");
  }

  if (base_input) {
    const TriMesh base = welded_or_throw(*base_input, options.weld_tolerance, options.base_name);
    BaseCoverageOptions base_options = options.base_options;
    if (options.shell_height) base_options.shell_height = options.shell_height;
    // With a swatch, as far as a base point inside its largest gap lies from the geometry round
    // it (half the gap's diagonal) and on to a vertex (an edge); without, half the median
    // element, which for yarns stitched into long runs passes over a bare ear.
    const double radius = swatch_gap_cell > 0.0
                              ? swatch_gap_cell * std::sqrt(0.5) + output_edge
                              : 0.5 * positive_median(measures.extent, 0.01 * (diagonal > 0.0 ? diagonal : 1.0));
    report.base = base_coverage(mesh, base, radius, base_options);
    report.shell_height = base_options.shell_height;
    timer.lap("base coverage");
  }
  return report;
}

nlohmann::ordered_json to_json(const InspectReport& r) {
  nlohmann::ordered_json j;
  j["faces"] = r.faces;
  j["vertices"] = r.vertices;
  j["weld_tolerance"] = r.weld_tolerance;
  j["elements"] = r.elements;
  j["closed_elements"] = r.closed_elements;
  j["boundary_edges"] = r.boundary_edges;
  j["nonmanifold_edges"] = r.nonmanifold_edges;
  j["nonmanifold_vertices"] = r.nonmanifold_vertices;
  j["intersecting_face_pairs"] = r.intersecting_face_pairs;
  j["self_intersecting_face_pairs"] = r.self_intersecting_face_pairs;
  j["median_element_area"] = r.median_element_area;
  j["median_element_extent"] = r.median_element_extent;
  if (r.swatch) {
    j["swatch_elements"] = r.swatch->elements;
    j["swatch_intersecting_face_pairs"] = r.swatch->intersecting_face_pairs;
    j["element_area_ks"] = r.swatch->element_area_ks;
    j["element_extent_ks"] = r.swatch->element_extent_ks;
  }
  if (r.plane) {
    j["coverage"] = r.plane->coverage;
    j["largest_gap"] = r.plane->largest_gap;
    j["coverage_cell_size"] = r.plane->cell_size;
    j["coverage_grid"] = {r.plane->cells_x, r.plane->cells_y};
  }
  if (r.rings) {
    nlohmann::ordered_json k;
    k["rings"] = r.rings->rings;
    k["links"] = r.rings->links;
    k["links_histogram"] = r.rings->histogram;
    k["linked_to_3_share"] = r.rings->linked_to_3_share;
    k["mean_links"] = r.rings->mean_links;
    k["loose_rings"] = r.rings->loose_rings;
    k["pieces"] = r.rings->pieces;
    k["largest_piece_share"] = r.rings->largest_piece_share;
    k["median_radius"] = r.rings->median_radius;
    k["radius_p10"] = r.rings->radius_p10;
    k["radius_p90"] = r.rings->radius_p90;
    if (r.rings->radius_ratio) k["radius_ratio"] = *r.rings->radius_ratio;
    k["median_aspect"] = r.rings->median_aspect;
    k["aspect_p90"] = r.rings->aspect_p90;
    if (r.rings->asked_radius) {
      k["asked_radius"] = *r.rings->asked_radius;
      const double asked = *r.rings->asked_radius;
      k["radius_over_asked"] = {{"p10", r.rings->radius_p10 / asked}, {"median", r.rings->median_radius / asked},
                                {"p90", r.rings->radius_p90 / asked}};
    }
    if (r.rings->expected_rings) {
      k["expected_rings"] = *r.rings->expected_rings;
      k["missing_rings"] = *r.rings->expected_rings - r.rings->rings;
    }
    if (r.rings->near) {
      const RingsNear& n = r.rings->near->rings;
      nlohmann::ordered_json near = {{"points", r.rings->near->points}, {"radius", r.rings->near->radius},
                             {"rings", n.rings}, {"links_histogram", n.histogram},
                             {"linked_to_3_share", n.linked_to_3_share}, {"loose_rings", n.loose_rings},
                             {"median_radius", n.median_radius}, {"radius_p10", n.radius_p10},
                             {"radius_p90", n.radius_p90}};
      if (r.rings->asked_radius && n.rings > 0) {
        const double asked = *r.rings->asked_radius;
        near["radius_over_asked"] = {{"p10", n.radius_p10 / asked}, {"median", n.median_radius / asked},
                                     {"p90", n.radius_p90 / asked}};
      }
      k["near"] = near;
    }
    j["rings"] = k;
  }
  if (r.yarns) {
    nlohmann::ordered_json y;
    y["yarns"] = r.yarns->yarns;
    y["weighted_median_length"] = r.yarns->weighted_median_length;
    y["median_radius"] = r.yarns->median_radius;
    if (r.yarns->swatch_length) y["swatch_length"] = *r.yarns->swatch_length;
    if (r.yarns->radius_ratio) y["radius_ratio"] = *r.yarns->radius_ratio;
    if (r.yarns->in_swatch_lengths) y["in_swatch_lengths"] = *r.yarns->in_swatch_lengths;
    j["yarns"] = y;
  }
  if (r.base) {
    j["coverage"] = r.base->coverage;
    j["coverage_radius"] = r.base->radius;
    j["height_min"] = r.base->height_min;
    j["height_max"] = r.base->height_max;
    if (r.shell_height) j["shell_height"] = *r.shell_height;
    if (r.base->outside_shell_vertices) j["outside_shell_vertices"] = *r.base->outside_shell_vertices;
  }
  return j;
}

std::string to_text(const InspectReport& r) {
  std::ostringstream s;
  s << "mesh:          " << r.faces << " faces, " << r.vertices << " vertices (welded at " << r.weld_tolerance
    << " x bbox diagonal)\n";
  s << "elements:      " << r.elements << ", of which " << r.closed_elements << " closed 2-manifolds\n";
  s << "defects:       " << r.boundary_edges << " boundary edges, " << r.nonmanifold_edges << " non-manifold edges, "
    << r.nonmanifold_vertices << " pinched vertices\n";
  s << "intersections: " << r.intersecting_face_pairs << " face pairs between elements, " << r.self_intersecting_face_pairs
    << " within elements\n";
  s << "element size:  median area " << r.median_element_area << ", median extent " << r.median_element_extent << "\n";
  if (r.swatch) {
    s << "swatch:        " << r.swatch->elements << " elements, " << r.swatch->intersecting_face_pairs
      << " intersecting pairs; KS distance of element areas " << r.swatch->element_area_ks << ", of extents "
      << r.swatch->element_extent_ks << "\n";
  }
  if (r.plane) {
    s << "coverage:      " << r.plane->coverage << " of the x-y footprint, largest gap " << r.plane->largest_gap << " ("
      << r.plane->cells_x << " x " << r.plane->cells_y << " cells of " << r.plane->cell_size << ")\n";
  }
  if (r.rings) {
    const InspectReport::Rings& k = *r.rings;
    s << "rings:         " << k.rings << " rings, " << k.links << " links; " << 100.0 * k.linked_to_3_share
      << "% linked to >= 3, mean " << k.mean_links << " links, " << k.loose_rings << " loose; " << k.pieces
      << " pieces, the largest " << 100.0 * k.largest_piece_share << "% of the rings\n";
    s << "ring links:    ";
    for (size_t n = 0; n < k.histogram.size(); ++n) s << (n ? ", " : "") << n << ": " << k.histogram[n];
    s << "\n";
    s << "ring radius:   median " << k.median_radius << " (10-90%: " << k.radius_p10 << " to " << k.radius_p90 << ")";
    if (k.radius_ratio) s << ", " << *k.radius_ratio << " x the swatch's";
    if (k.expected_rings) s << "; " << *k.expected_rings - k.rings << " missing of " << *k.expected_rings << " expected";
    s << "\n";
    if (k.asked_radius)
      s << "over asked:    " << k.radius_p10 / *k.asked_radius << " / " << k.median_radius / *k.asked_radius << " / "
        << k.radius_p90 / *k.asked_radius << " (p10 / median / p90 of radius over the " << *k.asked_radius
        << " asked)\n";
    s << "ring aspect:   median " << k.median_aspect << ", p90 " << k.aspect_p90 << " (longest over shortest axis)\n";
    if (k.near) {
      const RingsNear& n = k.near->rings;
      s << "near points:   " << n.rings << " rings within " << k.near->radius << " of " << k.near->points << " points; "
        << 100.0 * n.linked_to_3_share << "% linked to >= 3, " << n.loose_rings << " loose; links ";
      for (size_t c = 0; c < n.histogram.size(); ++c) s << (c ? ", " : "") << c << ": " << n.histogram[c];
      s << "\n";
      if (k.asked_radius && n.rings > 0)
        s << "near, asked:   " << n.radius_p10 / *k.asked_radius << " / " << n.median_radius / *k.asked_radius << " / "
          << n.radius_p90 / *k.asked_radius << " (p10 / median / p90 of their radius over the asked)\n";
    }
  }
  if (r.yarns) {
    s << "yarns:         " << r.yarns->yarns << " yarns, length-weighted median length " << r.yarns->weighted_median_length;
    if (r.yarns->in_swatch_lengths) s << " (" << *r.yarns->in_swatch_lengths << " swatch lengths)";
    s << ", median radius " << r.yarns->median_radius << "\n";
  }
  if (r.base) {
    s << "coverage:      " << r.base->coverage << " of the base area (radius " << r.base->radius << ")\n";
    s << "heights:       " << r.base->height_min << " to " << r.base->height_max << " base bbox diagonals";
    if (r.base->outside_shell_vertices) {
      s << ", " << *r.base->outside_shell_vertices << " vertices outside the shell [0, " << *r.shell_height << "]";
    }
    s << "\n";
  }
  return s.str();
}

}  // namespace meshquilt
