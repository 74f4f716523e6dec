#include "repair_report.h"

#include <iostream>

namespace meshquilt::cli {

void say_repairs(const std::string& file, const MeshRepairs& repairs, const std::string& parts) {
  if (repairs.any()) std::cerr << "meshquilt: " << file << ": repaired: " << repairs.describe(parts) << "\n";
}

}  // namespace meshquilt::cli
