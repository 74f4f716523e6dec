#pragma once
//! Connectivity of a triangle mesh: welding, connected components (geometry elements), face
//! adjacency and topological defects (closedness).

#include <array>
#include <cstdint>
#include <vector>

#include "mesh/tri_mesh.h"

namespace meshquilt {

//! Default welding tolerance, relative to the bounding-box diagonal.
inline constexpr double kWeldTolerance = 1e-6;

//! Merges vertices closer than `relative_tolerance` x bbox diagonal (exactly: grid hashing plus a
//! distance check), drops unreferenced vertices and faces that become degenerate (two equal
//! indices). Keeps `elements` and `sources` aligned with the surviving faces.
//! Each vertex, in input order, joins the earliest kept vertex within the tolerance (greedy, not
//! transitive: a chain of points each closer than the tolerance may keep several); surviving
//! vertices keep their input order, so the result is deterministic.
//! \pre indices in range (validate_mesh). A tolerance of 0 merges exactly equal positions only.
//! \throw InputError(invalid_mesh) when a position is NaN or infinite.
TriMesh weld_vertices(const TriMesh& mesh, double relative_tolerance = kWeldTolerance);

//! The clustering behind weld_vertices: per vertex, the earliest vertex it joins (itself when it
//! joins none), by the same greedy rule and tolerance.
//! \throw InputError(invalid_mesh) when a position is NaN or infinite.
std::vector<int32_t> weld_representatives(const std::vector<Vec3>& positions,
                                          double relative_tolerance = kWeldTolerance);

//! Vertex-connected components of the faces: #F component id in [0, count), numbered in order of
//! their first face. Vertices are compared by index (weld first).
std::vector<int32_t> face_components(const TriMesh& mesh, int32_t* count = nullptr);

//! Splits a mesh into one compact mesh per element (by `elements`, or by face_components when
//! `elements` is empty), in element id order. Ids without faces give no part; each part keeps
//! its faces' order and its vertices' relative order, and has empty `elements`.
std::vector<TriMesh> split_elements(const TriMesh& mesh);

//! Concatenates meshes, setting `elements` to the index of the part each face came from (so
//! split_elements(join_elements(parts)) gives back the non-empty parts).
TriMesh join_elements(const std::vector<TriMesh>& parts);

//! Key of the directed edge a -> b: a in the high 32 bits, b in the low ones.
inline uint64_t directed_edge_key(int32_t a, int32_t b) {
  return (static_cast<uint64_t>(static_cast<uint32_t>(a)) << 32) | static_cast<uint32_t>(b);
}

//! Key of the undirected edge {a, b}: directed_edge_key(min, max).
inline uint64_t undirected_edge_key(int32_t a, int32_t b) {
  return a < b ? directed_edge_key(a, b) : directed_edge_key(b, a);
}

//! Face adjacency across edges: #F x 3, entry k is the face across edge (v[k], v[k+1]); -1 for a
//! boundary edge, -2 for an edge shared by more than two faces (non-manifold).
std::vector<std::array<int32_t, 3>> face_neighbors(const TriMesh& mesh);

//! Topological defects of a triangle mesh; closed_manifold() is the closedness test of every
//! stage (stitched results, clean-up, swatch elements).
struct SurfaceReport {
  int64_t boundary_edges = 0;        //!< undirected edges used by one face
  int64_t nonmanifold_edges = 0;     //!< undirected edges used by three or more faces
  int64_t misoriented_edges = 0;     //!< two-face edges traversed in the same direction by both
  int64_t pinched_vertices = 0;      //!< vertices whose faces form more than one fan
  int64_t degenerate_faces = 0;      //!< faces repeating a vertex index
  int64_t components = 0;            //!< vertex-connected components of the faces
  int64_t euler = 0;                 //!< V - E + F over vertices used by faces
  //! Every edge shared by exactly two faces that traverse it in opposite directions.
  bool closed_oriented() const { return boundary_edges == 0 && nonmanifold_edges == 0 && misoriented_edges == 0; }
  //! closed_oriented, and no pinched vertex or degenerate face: a closed element.
  bool closed_manifold() const {
    return boundary_edges == 0 && nonmanifold_edges == 0 && misoriented_edges == 0 &&
           pinched_vertices == 0 && degenerate_faces == 0;
  }
};

//! Counts the topological defects of `mesh` (see SurfaceReport).
SurfaceReport inspect_surface(const TriMesh& mesh);

}  // namespace meshquilt
