#include "jobs/repairs_json.h"

namespace meshquilt {

nlohmann::json repairs_json(const MeshRepairs& repairs) {
  nlohmann::json counts = nlohmann::json::object();
  for (const auto& [name, count] : repairs.counts()) counts[name] = count;
  return counts;
}

}  // namespace meshquilt
