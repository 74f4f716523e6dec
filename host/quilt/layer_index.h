#pragma once
//! Which elements of a large planar layer lie where: a bucket grid over their x-y bounds, so that
//! a patch visits the elements near its footprint rather than the whole layer.

#include <cstdint>
#include <unordered_map>
#include <vector>

#include "quilt/patch_step.h"

namespace meshquilt {

class LayerIndex {
 public:
  //! Buckets of `side` x `side` plane units (about the swatch's size).
  explicit LayerIndex(double side);

  //! Element k of `layer` is new or has new bounds: it is listed under them from now on (under
  //! its old bounds too, which near() filters out).
  void update(const std::vector<PlaneElement>& layer, int32_t k);

  //! The alive elements whose bounds overlap `region`, ascending.
  std::vector<int32_t> near(const std::vector<PlaneElement>& layer, const Rect2& region) const;

 private:
  int64_t column(double x) const;
  static uint64_t key(int64_t x, int64_t y);

  double side_;
  std::unordered_map<uint64_t, std::vector<int32_t>> buckets_;
};

//! The elements a patch with these candidate placements may touch (PatchRequest::near): those
//! whose bounds meet the region the placements cover, then those whose bounds meet that region
//! grown to hold theirs and `margin` (a deformation's reach).
std::vector<int32_t> patch_neighbourhood(const LayerIndex& index, const std::vector<PlaneElement>& layer,
                                         const std::vector<glm::dvec2>& candidates, const glm::dvec2& extent,
                                         double margin);

}  // namespace meshquilt
