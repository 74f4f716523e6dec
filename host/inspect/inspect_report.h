#pragma once
//! The quality report of a synthesized mesh (DESIGN.md section 8, `meshquilt inspect`): element
//! integrity, defects, intersections, size distribution against the swatch, coverage and heights.

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "inspect/coverage.h"
#include "mesh/topology.h"
#include "inspect/ring_links.h"
#include "mesh/tri_mesh.h"

namespace meshquilt {

struct InspectOptions {
  double weld_tolerance = kWeldTolerance;  //!< relative to the bbox diagonal (topology.h default 1e-6)
  bool plane = false;                      //!< measure coverage of the x-y footprint (planar output)
  std::optional<double> shell_height;      //!< H for --base, in units of the base's bbox diagonal
  bool rings = false;                      //!< the link graph of the elements taken as rings
  bool yarns = false;                      //!< the elements' lengths taken as tubes (yarns)
  //! With rings: also the rings within near_radius median ring radii of these points (cones).
  std::vector<Vec3> near_points;
  double near_radius = 3.0;
  //! With a swatch and a base: the scale synth was asked for (the swatch's longer side over the
  //! base's bounding-box diagonal), so that ring radii are reported over the radius asked.
  std::optional<double> scale;
  PlaneCoverageOptions plane_options;      //!< margin and grid limits for the plane coverage
  BaseCoverageOptions base_options;        //!< sampling of the base (shell_height above wins)
  // Names used in error messages (the CLI passes the file paths).
  std::string mesh_name = "mesh";
  std::string swatch_name = "swatch";
  std::string base_name = "base mesh";
};

struct InspectReport {
  // After welding coincident vertices within weld_tolerance x bbox diagonal.
  int64_t faces = 0;
  int64_t vertices = 0;
  double weld_tolerance = 0.0;
  // Elements are the vertex-connected components.
  int32_t elements = 0;
  int32_t closed_elements = 0;  //!< no boundary edge, no non-manifold edge, no pinched vertex
  int64_t boundary_edges = 0;
  int64_t nonmanifold_edges = 0;
  int64_t nonmanifold_vertices = 0;  //!< pinched vertices (more than one fan)
  int64_t intersecting_face_pairs = 0;       //!< between different elements
  int64_t self_intersecting_face_pairs = 0;  //!< within one element, faces sharing no vertex
  double median_element_area = 0.0;
  double median_element_extent = 0.0;  //!< largest bbox side of the median element

  struct Swatch {
    int32_t elements = 0;
    int64_t intersecting_face_pairs = 0;  //!< the swatch's own count, for comparison
    double element_area_ks = 0.0;         //!< two-sample KS distance of element areas
    double element_extent_ks = 0.0;       //!< the same for the largest bbox side
  };
  std::optional<Swatch> swatch;
  std::optional<PlaneCoverage> plane;  //!< with options.plane
  std::optional<BaseCoverage> base;    //!< with a base mesh
  std::optional<double> shell_height;  //!< H used for base.outside_shell_vertices

  //! With options.rings: which rings pass through which (inspect/ring_links.h).
  struct Rings {
    int32_t rings = 0;
    int64_t links = 0;
    std::vector<int32_t> histogram;  //!< rings with 0, 1, 2, ... links
    double linked_to_3_share = 0.0;
    double mean_links = 0.0;
    int32_t loose_rings = 0;
    int32_t pieces = 0;
    double largest_piece_share = 0.0;
    double median_radius = 0.0;
    double radius_p10 = 0.0, radius_p90 = 0.0;
    double median_aspect = 1.0, aspect_p90 = 1.0;  //!< longest over shortest axis of a ring
    std::optional<double> radius_ratio;    //!< with a swatch: median radius / the swatch's
    //! With a swatch, a base and a scale: the radius the scale asks for.
    std::optional<double> asked_radius;
    std::optional<double> expected_rings;  //!< with a swatch and a plane or base: its ring density x area
    //! With near_points: the rings near them (radius in mesh units).
    struct Near {
      int32_t points = 0;
      double radius = 0.0;
      RingsNear rings;
    };
    std::optional<Near> near;
  };
  std::optional<Rings> rings;

  //! With options.yarns: each closed element taken as a tube (inspect/yarn_lengths.h).
  struct Yarns {
    int32_t yarns = 0;                   //!< elements that enclose a volume
    double weighted_median_length = 0.0; //!< length-weighted median yarn length
    double median_radius = 0.0;
    std::optional<double> swatch_length;  //!< with a swatch: its length-weighted median yarn length
    std::optional<double> radius_ratio;   //!< with a swatch: median radius / the swatch's (its scale)
    //! weighted_median_length / (swatch_length x radius_ratio): yarn length in swatch lengths at
    //! the scale the output was made at.
    std::optional<double> in_swatch_lengths;
  };
  std::optional<Yarns> yarns;

  //! Seconds spent per stage (weld, topology, intersections, ...), in order; not in the JSON.
  std::vector<std::pair<std::string, double>> timings;
};

//! The full report of `mesh`, optionally against its swatch (element size distributions) and
//! over a plane (options.plane) or a base mesh (`base`: coverage and heights). Inputs are welded
//! here; the meshes are not modified.
//! \throw InputError when a mesh has no faces after welding, or --plane and a base are both asked;
//!        DeviceError/SolverError from the BVH.
InspectReport inspect_mesh(const TriMesh& mesh, const InspectOptions& options = {},
                           const TriMesh* swatch = nullptr, const TriMesh* base = nullptr);

//! The report as one JSON object with the keys of issue 3 (faces, vertices, elements,
//! closed_elements, boundary_edges, nonmanifold_edges, nonmanifold_vertices,
//! intersecting_face_pairs, self_intersecting_face_pairs; swatch_elements, element_area_ks,
//! element_extent_ks; coverage, largest_gap; height_min, height_max, outside_shell_vertices).
nlohmann::ordered_json to_json(const InspectReport& report);

//! A readable multi-line summary of the report.
std::string to_text(const InspectReport& report);

}  // namespace meshquilt
