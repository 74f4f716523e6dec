#include "inspect/swatch_check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <set>

#include <glm/common.hpp>

#include "core/error.h"
#include "inspect/element_topology.h"
#include "mesh/border_cut.h"
#include "mesh/measures.h"
#include "mesh/topology.h"
#include "spatial/intersecting_pairs.h"

namespace meshquilt {
namespace {

std::string format(const char* pattern, double a, double b = 0.0, double c = 0.0) {
  char text[256];
  std::snprintf(text, sizeof text, pattern, a, b, c);
  return text;
}

std::string plural(int64_t n, const std::string& one, const std::string& many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

}  // namespace

SwatchCheck check_swatch(const TriMesh& swatch, const std::string& source, const SwatchCheckOptions& options) {
  SwatchCheck check;
  RepairedMesh repaired = repair_mesh(swatch, source, options.weld_tolerance);
  check.repairs = repaired.repairs;
  check.repaired = repaired.mesh;
  TriMesh mesh = std::move(repaired.mesh);
  mesh.elements.clear();  // elements are the connected components, as synth splits them
  const ElementTopology topology = element_topology(mesh);
  check.elements = topology.elements;
  check.open_elements = topology.elements - topology.closed_elements;

  const Box3 box = bounding_box(mesh.positions);
  check.extent = box.hi - box.lo;
  if (check.open_elements > 0) {
    const std::vector<uint8_t> cut = cut_by_border(split_elements(mesh));
    check.cut_elements = static_cast<int32_t>(std::count(cut.begin(), cut.end(), 1));
  }

  const std::vector<FacePair> pairs =
      intersecting_face_pairs(mesh, topology.face_element, IntersectionScope::different_elements);
  check.intersecting_face_pairs = static_cast<int64_t>(pairs.size());
  std::set<std::pair<int32_t, int32_t>> element_pairs;
  for (const auto& [f, g] : pairs) {
    const int32_t a = topology.face_element[f], b = topology.face_element[g];
    element_pairs.emplace(std::min(a, b), std::max(a, b));
  }
  check.intersecting_element_pairs = static_cast<int64_t>(element_pairs.size());

  const double shorter = std::min(check.extent.x, check.extent.y);
  check.thickness_ratio = shorter > 0.0 ? check.extent.z / shorter : std::numeric_limits<double>::infinity();
  check.thin_along_z = check.thickness_ratio <= options.max_thickness_ratio;

  // Elements cut by the border are open elements too: say so once, where the cause is known.
  const int32_t open_inside = check.open_elements - check.cut_elements;
  if (open_inside > 0)
    check.findings.push_back(plural(open_inside, "open element", "open elements") + " of " +
                             std::to_string(check.elements) +
                             " (boundary or non-manifold edges, pinched vertices): every element must be a closed "
                             "2-manifold, or synth drops its copies");
  if (check.cut_elements > 0)
    check.findings.push_back(plural(check.cut_elements, "element", "elements") +
                             " cut open by the border (open, its rim on the x-y hull): crop between elements, "
                             "not through them");
  if (check.intersecting_element_pairs > 0)
    check.findings.push_back(plural(check.intersecting_element_pairs, "pair", "pairs") +
                             " of elements intersecting (" +
                             plural(check.intersecting_face_pairs, "face pair", "face pairs") +
                             "): elements must not touch or pass through each other");
  if (!check.thin_along_z)
    check.findings.push_back(
        format("not thin along z: z extent %.4g is %.2f x the shorter x-y side", check.extent.z, check.thickness_ratio) +
        format(" (at most %.2f): lay the elements out in x-y with their thickness along z", options.max_thickness_ratio));
  return check;
}

}  // namespace meshquilt
