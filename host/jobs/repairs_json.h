#pragma once
//! What reading a mesh repaired, as every job's stats JSON writes it (`repairs`).

#include <nlohmann/json.hpp>

#include "mesh/mesh_repair.h"

namespace meshquilt {

//! Each repair's count by name (MeshRepairs::counts), zeros included.
nlohmann::json repairs_json(const MeshRepairs& repairs);

}  // namespace meshquilt
