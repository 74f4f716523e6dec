#pragma once
//! Swatch animation carried over to a synthesized result (Section 4 of the mesh quilting paper:
//! ivy whose leaves play back a precomputed animation "stored as a set of position displacements
//! in time in the local frame of each vertex").
//!
//! Each output vertex knows its swatch vertex (TriMesh::origins). Its local frame is the map from
//! the swatch to the output at that vertex: the least-squares linear map J taking the swatch
//! offsets of its neighbours (the vertices within `rings` edges in its element) to their output
//! offsets, split by its polar decomposition J = R S into a rotation R and, from S, a uniform
//! scale s (the cube root of det S). On a plane, where copies are only moved, J is the identity.
//! A swatch vertex's displacement d then moves the output vertex by s R d.

#include <glm/mat3x3.hpp>
#include <vector>

#include "mesh/tri_mesh.h"

namespace meshquilt {

//! The frame s R of every vertex of `output` (#V; the identity where its origin is unknown).
//! swatch_rest  #S the swatch's vertices (in its file's coordinates) that origins index
//! \throw InputError(invalid_mesh) when output.origins is missing or names a vertex past #S.
std::vector<glm::dmat3> vertex_frames(const TriMesh& output, const std::vector<Vec3>& swatch_rest,
                                      int rings = 6);

//! `output`'s positions with each vertex moved by its frame times its swatch vertex's
//! displacement from swatch_rest to swatch_frame (both #S).
std::vector<Vec3> animated_positions(const TriMesh& output, const std::vector<glm::dmat3>& frames,
                                     const std::vector<Vec3>& swatch_rest,
                                     const std::vector<Vec3>& swatch_frame);

}  // namespace meshquilt
