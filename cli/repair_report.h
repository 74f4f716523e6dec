#pragma once
// Repairs made to an input mesh, said once on stderr.

#include <string>

#include "mesh/mesh_repair.h"

namespace meshquilt::cli {

//! "meshquilt: FILE: repaired: rewound 288 faces in 18 elements, ..." on stderr when any repair
//! was made; `parts` names the mesh's parts ("elements" for a swatch, "parts" for a base).
void say_repairs(const std::string& file, const MeshRepairs& repairs, const std::string& parts);

}  // namespace meshquilt::cli
