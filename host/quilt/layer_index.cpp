#include "quilt/layer_index.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace meshquilt {

LayerIndex::LayerIndex(double side) : side_(side) {}

int64_t LayerIndex::column(double x) const { return static_cast<int64_t>(std::floor(x / side_)); }

uint64_t LayerIndex::key(int64_t x, int64_t y) {
  return static_cast<uint64_t>(x) * 0x9e3779b97f4a7c15ull ^ static_cast<uint64_t>(y) * 0xc2b2ae3d27d4eb4full;
}

void LayerIndex::update(const std::vector<PlaneElement>& layer, int32_t k) {
  const Rect2& b = layer[k].bounds;
  for (int64_t y = column(b.lo.y); y <= column(b.hi.y); ++y)
    for (int64_t x = column(b.lo.x); x <= column(b.hi.x); ++x) {
      std::vector<int32_t>& bucket = buckets_[key(x, y)];
      if (bucket.empty() || bucket.back() != k) bucket.push_back(k);
    }
}

std::vector<int32_t> LayerIndex::near(const std::vector<PlaneElement>& layer, const Rect2& region) const {
  std::vector<int32_t> found;
  for (int64_t y = column(region.lo.y); y <= column(region.hi.y); ++y)
    for (int64_t x = column(region.lo.x); x <= column(region.hi.x); ++x) {
      const auto it = buckets_.find(key(x, y));
      if (it == buckets_.end()) continue;
      for (int32_t k : it->second)
        if (layer[k].alive && layer[k].bounds.overlaps(region)) found.push_back(k);
    }
  std::sort(found.begin(), found.end());
  found.erase(std::unique(found.begin(), found.end()), found.end());
  return found;
}

std::vector<int32_t> patch_neighbourhood(const LayerIndex& index, const std::vector<PlaneElement>& layer,
                                         const std::vector<glm::dvec2>& candidates, const glm::dvec2& extent,
                                         double margin) {
  Rect2 region{glm::dvec2(std::numeric_limits<double>::max()), glm::dvec2(std::numeric_limits<double>::lowest())};
  for (const glm::dvec2& t : candidates) {
    region.lo = glm::min(region.lo, t);
    region.hi = glm::max(region.hi, t + extent);
  }
  Rect2 reach = region;
  for (int32_t k : index.near(layer, region)) {
    reach.lo = glm::min(reach.lo, layer[k].bounds.lo);
    reach.hi = glm::max(reach.hi, layer[k].bounds.hi);
  }
  reach.lo -= glm::dvec2(margin);
  reach.hi += glm::dvec2(margin);
  return index.near(layer, reach);
}

}  // namespace meshquilt
