#pragma once
//! Welding and connected components (geometry elements) of a triangle mesh.

#include <cstdint>
#include <vector>

#include "mesh/tri_mesh.h"

namespace meshquilt {

//! Default welding tolerance, relative to the bounding-box diagonal.
inline constexpr double kWeldTolerance = 1e-6;

//! Merges vertices closer than `relative_tolerance` x bbox diagonal (exactly: grid hashing plus a
//! distance check), drops unreferenced vertices and faces that become degenerate (two equal
//! indices). Keeps `elements` aligned with the surviving faces.
//! Each vertex, in input order, joins the earliest kept vertex within the tolerance (greedy, not
//! transitive: a chain of points each closer than the tolerance may keep several); surviving
//! vertices keep their input order, so the result is deterministic.
//! \pre indices in range (validate_mesh). A tolerance of 0 merges exactly equal positions only.
//! \throw InputError(invalid_mesh) when a position is NaN or infinite.
TriMesh weld_vertices(const TriMesh& mesh, double relative_tolerance = kWeldTolerance);

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

}  // namespace meshquilt
