#include "repair_report.h"

#include <iostream>

namespace meshquilt::cli {

void say_repairs(const std::string& file, const MeshRepairs& repairs, const std::string& parts) {
  if (repairs.any()) std::cerr << "meshquilt: " << file << ": repaired: " << repairs.describe(parts) << "\n";
}

nlohmann::json repairs_json(const MeshRepairs& repairs) {
  nlohmann::json counts = nlohmann::json::object();
  for (const auto& [name, count] : repairs.counts()) counts[name] = count;
  return counts;
}

}  // namespace meshquilt::cli
