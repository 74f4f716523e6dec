#pragma once
//! Meshes as other tools export them, made what every stage expects, or refused by name: the
//! safe, standard repairs (welding, dropping unused vertices, collapsed, duplicate and zero-area
//! faces, closing T-junctions, splitting pinched vertices, winding each part coherently and
//! outward), counted; what cannot be repaired safely (an edge of three or more faces, a
//! Moebius-like part) is refused with the face it was found at. docs/swatches.md and docs/cli.md
//! hold the table of cases.

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "mesh/tri_mesh.h"

namespace meshquilt {

//! How often each repair was made; all zero for a mesh that needed none.
struct MeshRepairs {
  int64_t unused_vertices = 0;  //!< referenced by no face, dropped
  int64_t welded_vertices = 0;  //!< joined to a coincident vertex
  int64_t collapsed_faces = 0;  //!< two corners the same after welding, dropped
  int64_t duplicate_faces = 0;  //!< the same three corners as an earlier face, dropped
  int64_t zero_area_faces = 0;  //!< corners on a line, dropped (the neighbours' T-junction closed)
  int64_t t_junctions = 0;      //!< faces split at a vertex lying on their open edge
  int64_t split_vertices = 0;   //!< copies made of vertices where separate fans of faces meet
  int64_t rewound_faces = 0;    //!< faces turned to agree with their part and face outward
  int64_t rewound_parts = 0;    //!< parts with any face turned

  bool any() const;
  //! (name, count) of every repair, in the order above; the stats JSON's `repairs` keys.
  std::vector<std::pair<std::string, int64_t>> counts() const;
  //! The repairs made, as "rewound 288 faces in 18 parts, welded 12 vertices"; "" when none.
  std::string describe(const std::string& part_name = "parts") const;
};

struct RepairedMesh {
  TriMesh mesh;
  MeshRepairs repairs;
};

//! `mesh` repaired: unused vertices dropped; vertices within `relative_tolerance` x the bounding
//! box diagonal (at most 1e-3 x the median edge, so a stray face cannot weld the rest) welded; faces collapsed by welding, repeating an earlier face's corners, or with a
//! height below the tolerance dropped; open edges with another open vertex lying on them split at
//! it (a T-junction; dropped zero-area faces leave these); vertices where several fans meet split
//! per fan; then each edge-connected part wound coherently by a breadth-first walk from its first
//! face and turned outward: a closed part by its signed volume, an open one by the volume of the
//! cone from its area centroid, a nearly flat open part kept as its first face runs.
//! Per-face (`elements`, `sources`) and per-vertex (`origins`, `colors`) data follow; `origins`
//! is filled with the file's vertex order first when the mesh changes and had none. A mesh that
//! needs no repair comes back unchanged. `source` names the mesh in messages.
//! \throw InputError(invalid_mesh) "SOURCE: problem" for validate_mesh's problems, no faces left,
//!        an edge shared by three or more faces (naming the faces, in the file's numbering), or a
//!        part that cannot be oriented (naming a face).
RepairedMesh repair_mesh(const TriMesh& mesh, const std::string& source,
                         double relative_tolerance = 1e-6);

}  // namespace meshquilt
