#pragma once
//! Geometry-matching cost of candidate swatch translations (Eq. 1-3 of the mesh quilting paper),
//! scored on the compute engine: the `matching_cost` kernel (matching_cost.comp) on Vulkan, its
//! C++ twin (matching_cost_cpu.cpp) on the CPU back end.

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "device.h"
#include "matching_cost_layout.h"
#include "spatial/near_face_grid.h"

namespace meshquilt {

//! The swatch as the kernel sees it; uploaded once per MatchingCost.
struct MatchingSwatch {
  std::vector<glm::vec3> positions;               //!< #V swatch vertices
  std::vector<std::array<uint32_t, 3>> triangles; //!< #F vertex indices (counter-clockwise)
  std::vector<glm::vec3> normals;                 //!< #F unit face normals as Eq. 1 uses them
  float lambda = 1.0f;                            //!< Eq. 1 weight (>= 0)
  uint32_t normal_bins = 1;                       //!< the labels of the grid's groups are below this
};

//! Options of MatchingCost.
struct MatchingCostOptions {
  //! Most (candidate, point) pairs per dispatch; 0 means as many as one storage binding holds
  //! (max_binding_bytes / 4: 32 Mi pairs on lavapipe). Larger inputs are split into batches.
  std::size_t max_pairs_per_dispatch = 0;
};

//! Bounds the matching cost (Eq. 3) of candidate translations of one swatch against output
//! points: for each translation t (in x-y; the swatch moved by t),
//!   E(t) = sum over points p of min over swatch faces f of D(p - t, f),
//!   D(v, f) = (1 + lambda * Dist(v, f)) * (1 + |n_v - n_f|)            (Eq. 1-2),
//! with Dist the exact point-triangle distance. Per pair the kernel fetches the voxel of the
//! swatch's nearest-face grid that holds p - t and takes the minimum of D over its listed faces,
//! capped by 1 + lambda * reach (what every unlisted face must cost at least): a lower bound of
//! Eq. 2, equal to it wherever the list decides (points near the swatch with a close match).
//! Computed in float32 on the device; Vulkan and CPU agree within 1e-5 relative per pair.
//! Reuse one object for all seeds of a synthesis.
class MatchingCost {
 public:
  //! Uploads the swatch and its grid (built by build_near_face_grid over the same faces, in
  //! double). `device` must outlive this object; `grid` need not.
  //! \throw InputError (ErrorKind::invalid_option) when the swatch has no faces, an index is out
  //! of range, a coordinate or normal is not finite, the normals do not match the faces, lambda
  //! is negative or the grid does not belong to the swatch. \throw DeviceError when the device
  //! fails.
  MatchingCost(engine::Device& device, const MatchingSwatch& swatch, const NearFaceGrid& grid,
               MatchingCostOptions options = {});
  ~MatchingCost();
  MatchingCost(const MatchingCost&) = delete;
  MatchingCost& operator=(const MatchingCost&) = delete;

  //! A lower bound of E(t) for each translation, #T values in double that hold against the exact
  //! Eq. 3 in double: the per-pair bounds are lowered by a margin that covers float32 rounding
  //! (1e-5 relative, plus 3e-6 x lambda x the coordinates' magnitude) before they are summed in
  //! point order. Empty points give zeros; empty translations an empty result. `factors`
  //! (#P x normal_bins, point-major) bound each point's normal term 1 + |n - n_f| from below
  //! over the faces of each bin (NormalBins::factor_bounds); empty means 1 (no bound).
  //! \pre points.size() == normals.size(); normals unit length.
  //! \throw InputError when the sizes differ or a value is not finite; DeviceError when the
  //! device fails.
  std::vector<double> score(const std::vector<glm::vec3>& points, const std::vector<glm::vec3>& normals,
                            const std::vector<glm::vec2>& translations, const std::vector<double>& factors = {});

  //! The per-pair terms of score(): each pair's bound lowered by the margin, at least 1 (as
  //! every D is), #T by #P in double, candidate-major; score()'s sums are theirs in point order.
  //! Each holds against its point's exact Eq. 2, so the exact costs of some points plus the
  //! terms of the others bound a candidate's Eq. 3 from below. Same preconditions and errors.
  std::vector<double> pair_bounds(const std::vector<glm::vec3>& points, const std::vector<glm::vec3>& normals,
                                  const std::vector<glm::vec2>& translations, const std::vector<double>& factors = {});

  //! The per-pair bounds behind score(), as the kernel computed them (no margin): #T by #P
  //! floats, candidate-major (index t * #P + p). Same preconditions and errors as score().
  std::vector<float> point_costs(const std::vector<glm::vec3>& points, const std::vector<glm::vec3>& normals,
                                 const std::vector<glm::vec2>& translations, const std::vector<double>& factors = {});

  //! Dispatches made by the last score()/point_costs() call and their summed timing.
  std::size_t last_dispatch_count() const { return last_dispatches_; }
  const engine::DispatchTiming& last_timing() const { return last_timing_; }

 private:
  engine::Buffer& ensure(std::unique_ptr<engine::Buffer>& buffer, std::size_t bytes);

  engine::Device& device_;
  engine::Kernel& kernel_;
  MatchingCostOptions options_;
  kernels::matching_cost_layout::MatchingCostParams grid_params_{};
  float swatch_scale_ = 0.0f;  //!< largest |coordinate| of the swatch
  uint32_t bins_ = 1;
  std::unique_ptr<engine::Buffer> faces_;
  std::unique_ptr<engine::Buffer> voxel_faces_;
  std::unique_ptr<engine::Buffer> voxels_;
  std::unique_ptr<engine::Buffer> groups_;
  std::unique_ptr<engine::Buffer> factors_;
  std::unique_ptr<engine::Buffer> points_;
  std::unique_ptr<engine::Buffer> translations_;
  std::unique_ptr<engine::Buffer> costs_;
  std::size_t last_dispatches_ = 0;
  engine::DispatchTiming last_timing_;
};

//! The kernel's description for engine::Device::kernel (SPIR-V, bindings, C++ twin).
const engine::KernelSpec& matching_cost_kernel();

}  // namespace meshquilt
