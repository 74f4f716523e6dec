#include "quilt/quilt_swatch.h"

#include <algorithm>
#include <numeric>

#include "mesh/border_cut.h"
#include "mesh/swatch_frame.h"
#include "mesh/topology.h"
#include "spatial/intersecting_pairs.h"

namespace meshquilt {
namespace {

// Elements cut open by the swatch's border (mesh/border_cut.h): where some other element is
// closed the swatch was cropped from a larger sheet (a mail or a weave) and these are left out;
// a swatch of open elements only (a relief sheet) keeps them.
std::vector<TriMesh> without_cut_elements(std::vector<TriMesh> elements, int& cut) {
  cut = 0;
  const bool any_closed = std::any_of(elements.begin(), elements.end(),
                                      [](const TriMesh& e) { return inspect_surface(e).closed_manifold(); });
  if (!any_closed) return elements;
  const std::vector<uint8_t> is_cut = cut_by_border(elements);
  std::vector<TriMesh> kept;
  for (size_t k = 0; k < elements.size(); ++k) {
    if (is_cut[k]) ++cut;
    else kept.push_back(std::move(elements[k]));
  }
  return kept;
}

}  // namespace

QuiltSwatch prepare_swatch(const TriMesh& input, const std::string& name) {
  QuiltSwatch swatch;
  TriMesh numbered = input;
  // Every output vertex will name the swatch vertex it was copied from, in the file's order.
  if (numbered.origins.size() != numbered.positions.size()) {
    numbered.origins.resize(numbered.positions.size());
    std::iota(numbered.origins.begin(), numbered.origins.end(), 0);
  }
  swatch.mesh = orient_swatch(numbered, name);
  swatch.elements = without_cut_elements(split_elements(swatch.mesh), swatch.cut_elements);
  if (swatch.cut_elements > 0) {
    swatch.mesh = orient_swatch(join_elements(swatch.elements), name);
    swatch.elements = split_elements(swatch.mesh);
  }
  const Rect2 bounds = xy_bounds(swatch.mesh);
  swatch.extent = bounds.hi - bounds.lo;
  std::vector<Vec3> from_corner = swatch.mesh.positions;
  for (Vec3& p : from_corner) p -= Vec3(bounds.lo, 0.0);
  swatch.outline = ConvexOutline(from_corner);
  for (const TriMesh& e : swatch.elements) {
    swatch.element_bounds.push_back(xy_bounds(e));
    swatch.element_widths.push_back(ConvexOutline(e.positions).width());
    swatch.closed_elements = swatch.closed_elements && inspect_surface(e).closed_manifold();
  }
  if (!swatch.element_widths.empty()) {
    std::vector<double> widths = swatch.element_widths;
    std::nth_element(widths.begin(), widths.begin() + widths.size() / 2, widths.end());
    swatch.outline_slack = 0.5 * widths[widths.size() / 2];
  }
  const TriMesh joined = join_elements(swatch.elements);
  swatch.unfolded_elements =
      intersecting_face_pairs(joined, joined.elements, IntersectionScope::same_element).empty();
  swatch.mean_edge = mean_edge_length(swatch.mesh);
  swatch.faces = std::make_shared<const SwatchFaces>(swatch.elements);
  return swatch;
}

}  // namespace meshquilt
