#pragma once
// Repairs made to an input mesh, said once on stderr and kept for the stats JSON.

#include <string>

#include <nlohmann/json.hpp>

#include "mesh/mesh_repair.h"

namespace meshquilt::cli {

//! "meshquilt: FILE: repaired: rewound 288 faces in 18 elements, ..." on stderr when any repair
//! was made; `parts` names the mesh's parts ("elements" for a swatch, "parts" for a base).
void say_repairs(const std::string& file, const MeshRepairs& repairs, const std::string& parts);

//! The counts as the stats JSON's `repairs` entries: {"rewound_faces": 288, ...}, zeros kept.
nlohmann::json repairs_json(const MeshRepairs& repairs);

}  // namespace meshquilt::cli
