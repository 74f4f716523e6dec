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
TriMesh weld_vertices(const TriMesh& mesh, double relative_tolerance = kWeldTolerance);

//! Vertex-connected components of the faces: #F component id in [0, count), numbered in order of
//! their first face. Vertices are compared by index (weld first).
std::vector<int32_t> face_components(const TriMesh& mesh, int32_t* count = nullptr);

//! Splits a mesh into one compact mesh per element (by `elements`, or by face_components when
//! `elements` is empty), in element id order.
std::vector<TriMesh> split_elements(const TriMesh& mesh);

//! Concatenates meshes, setting `elements` to the index of the part each face came from.
TriMesh join_elements(const std::vector<TriMesh>& parts);

}  // namespace meshquilt
