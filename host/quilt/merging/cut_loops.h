#pragma once
//! Cut loops of a kept face set (Section 2.7 of the mesh quilting paper): the closed boundaries
//! along which a graph cut separates the kept part of an element, and the tidying that makes a
//! kept set stitchable.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "mesh/tri_mesh.h"

namespace meshquilt {

//! A closed loop of cut-boundary edges of a kept face set.
//! vertices  #K vertex indices in order; edge k is vertices[k] -> vertices[(k+1) % K]
//! faces     #K the kept face holding edge k (as a half-edge in its own winding order), so the
//!           kept part lies to the left of the loop seen from outside
struct CutLoop {
  std::vector<int32_t> vertices;
  std::vector<int32_t> faces;
};

//! Cut loops of the kept faces: closed chains of half-edges of kept faces whose neighbour exists
//! but is not kept. Loops made only of the mesh's own boundary edges are not cut loops and are
//! skipped. Returns false (with `why`) when the cut boundary is not a set of simple closed loops:
//! a vertex with two outgoing cut edges (pinch), or a chain mixing cut and original boundary
//! edges. `neighbors` is face_neighbors(mesh); `keep` is #F.
bool cut_loops(const TriMesh& mesh, const std::vector<std::array<int32_t, 3>>& neighbors,
               const std::vector<uint8_t>& keep, std::vector<CutLoop>& loops, std::string* why = nullptr);

//! Makes a kept face set stitchable by removing kept faces (never adding): faces with two or three
//! cut edges (ears, islands) and all kept faces around a vertex where the kept region is pinched
//! (two outgoing cut edges), repeated until stable. Returns the number of faces removed.
int32_t tidy_cut(const TriMesh& mesh, const std::vector<std::array<int32_t, 3>>& neighbors,
                 std::vector<uint8_t>& keep);

}  // namespace meshquilt
