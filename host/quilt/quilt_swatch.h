#pragma once
//! The swatch as every patch step uses it (Section 2.1): in its frame, split into elements,
//! measured and indexed once per run.

#include <memory>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "mesh/convex_outline.h"
#include "mesh/measures.h"
#include "mesh/tri_mesh.h"
#include "quilt/correspondence.h"
#include "quilt/plane_rect.h"

namespace meshquilt {

//! The swatch as the step uses it; prepared once per run by prepare_swatch.
struct QuiltSwatch {
  TriMesh mesh;                       //!< in its swatch frame (thin along z)
  std::vector<TriMesh> elements;      //!< its elements, in element order
  std::vector<Rect2> element_bounds;  //!< x-y bounds of each element
  std::vector<double> element_widths; //!< x-y width of each element (ConvexOutline::width)
  glm::dvec2 extent{0.0};             //!< x-y size of the swatch
  ConvexOutline outline;              //!< x-y convex hull of its geometry, from its bounds' low corner
  //! Half the median element width: how far past the outline a cell
  //! may lie and still count as under the swatch (the rows of an upright mail end in rounded
  //! corners).
  double outline_slack = 0.0;
  double mean_edge = 1.0;             //!< mean edge length: the unit of Eq. 1 distances
  bool closed_elements = true;        //!< every element a closed 2-manifold
  bool unfolded_elements = true;      //!< no element passes through itself
  int cut_elements = 0;               //!< open elements cut by the input's border, left out
  //! Its elements' faces indexed once for every patch's correspondences.
  std::shared_ptr<const SwatchFaces> faces;
};

//! Puts `input` in its swatch frame and splits it into elements. Open elements cut by its border
//! (mesh/border_cut.h) are left out (and counted) where some other element is closed: the
//! swatch was cropped from a larger sheet through them, and copies of them would stay open.
//! \throw InputError naming `name` for a degenerate swatch.
QuiltSwatch prepare_swatch(const TriMesh& input, const std::string& name = "swatch");

}  // namespace meshquilt
