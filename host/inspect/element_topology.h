#pragma once
//! Manifold checks of a welded mesh and of each of its elements (connected components).

#include <cstdint>
#include <vector>

#include "mesh/tri_mesh.h"

namespace meshquilt {

//! Edge and vertex defects of a mesh, totals and per element.
struct ElementTopology {
  int32_t elements = 0;             //!< vertex-connected components of the faces
  int32_t closed_elements = 0;      //!< elements with no boundary edge, non-manifold edge or pinched vertex
  int64_t boundary_edges = 0;       //!< edges with exactly one incident face
  int64_t nonmanifold_edges = 0;    //!< edges with three or more incident faces
  int64_t nonmanifold_vertices = 0; //!< pinched vertices: incident faces form more than one fan
  std::vector<int32_t> face_element;  //!< #F element id per face, numbered by first face
  std::vector<char> element_closed;   //!< #elements: 1 when the element is closed
};

//! Topology of `mesh`, whose vertices are already welded (vertices are compared by index).
//! A fan of a vertex is a maximal set of its incident faces connected through edges incident to
//! the vertex; a vertex with more than one fan is pinched (two cones meeting at their apex, two
//! closed elements touching at a point, the middle of a bowtie). Edges are undirected; a face
//! listed twice counts twice. O(F log F).
ElementTopology element_topology(const TriMesh& mesh);

}  // namespace meshquilt
