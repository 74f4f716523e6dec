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

namespace meshquilt {

//! The swatch as the kernel sees it; uploaded once per MatchingCost.
struct MatchingSwatch {
  std::vector<glm::vec3> positions;               //!< #V swatch vertices
  std::vector<std::array<uint32_t, 3>> triangles; //!< #F vertex indices (counter-clockwise)
  float cell_size = 0.0f;                         //!< x-y grid cell edge for the ring search (> 0)
  float lambda = 1.0f;                            //!< Eq. 1 weight (>= 0)
};

//! How invocations are mapped to work on the device.
enum class MatchingCostMapping {
  per_pair,  //!< one invocation per (candidate, point) pair
  per_point, //!< one invocation per point, looping over the candidates of the dispatch
};

//! Options of MatchingCost.
struct MatchingCostOptions {
  //! Work mapping; both give bit-identical results. Measured (perf/matching_cost_bench.cpp,
  //! 2,048 faces x 2,000 points x 64 candidates): on the CPU back end per_pair is ~6% faster;
  //! on lavapipe the two are within run-to-run noise (1.7-2.0e4 pairs per CPU-second each).
  //! per_pair is the default: it launches #T times more invocations, which a real GPU needs.
  MatchingCostMapping mapping = MatchingCostMapping::per_pair;
  //! Most (candidate, point) pairs per dispatch; 0 means as many as one storage binding holds
  //! (max_binding_bytes / 4: 32 Mi pairs on lavapipe). Larger inputs are split into batches.
  std::size_t max_pairs_per_dispatch = 0;
};

//! Scores candidate translations of one swatch against output points (Eq. 3): for each
//! translation t (in x-y; the swatch moved by t),
//!   E(t) = sum over points p of min over swatch faces f of D(p - t, f),
//!   D(v, f) = (1 + lambda * Dist(v, f)) * (1 + |n_v - n_f|)            (Eq. 1-2),
//! with Dist the exact point-triangle distance and n_f the unit face normal (zero for a
//! zero-area face). Each minimum is exact (a ring search over an x-y grid of the swatch that
//! stops once no unvisited face can beat the best D), computed in float32 on the device; the
//! sums are taken in double on the host, in point order. Vulkan and CPU agree within 1e-5
//! relative per point. A device with a loop limit (lavapipe) leaves searches longer than the
//! limit unfinished; the host finishes them with the C++ twin, so results never depend on it.
//! Reuse one object for all seeds of a synthesis.
class MatchingCost {
 public:
  //! Builds the grid and uploads the swatch. `device` must outlive this object.
  //! \throw InputError (ExitCode::invalid_option) when the swatch has no faces, an index is out
  //! of range, a coordinate is not finite, cell_size is not positive and finite, or lambda is
  //! negative. \throw DeviceError when the device fails. Grids of more than 4 Mi cells use a
  //! coarser cell (the results do not depend on the cell size).
  MatchingCost(engine::Device& device, const MatchingSwatch& swatch, MatchingCostOptions options = {});
  ~MatchingCost();
  MatchingCost(const MatchingCost&) = delete;
  MatchingCost& operator=(const MatchingCost&) = delete;

  //! E(t) for each translation: #T costs in double. One dispatch scores every candidate when
  //! the pairs fit one binding. Empty points give zeros; empty translations an empty result.
  //! \pre points.size() == normals.size(); normals unit length.
  //! \throw InputError when the sizes differ or a value is not finite; DeviceError when the
  //! device fails.
  std::vector<double> score(const std::vector<glm::vec3>& points, const std::vector<glm::vec3>& normals,
                            const std::vector<glm::vec2>& translations);

  //! The per-point minima E(p, M_in(t)) behind score() (Eq. 2): #T by #P floats, candidate-major
  //! (index t * #P + p). Same preconditions and errors as score().
  std::vector<float> point_costs(const std::vector<glm::vec3>& points, const std::vector<glm::vec3>& normals,
                                 const std::vector<glm::vec2>& translations);

  //! Dispatches made by the last score()/point_costs() call and their summed timing.
  std::size_t last_dispatch_count() const { return last_dispatches_; }
  //! Pairs of the last call that hit the device's loop limit (Device::max_loop_iterations) and
  //! were finished on the host by the C++ twin.
  std::size_t last_host_fallback_count() const { return last_fallbacks_; }
  const engine::DispatchTiming& last_timing() const { return last_timing_; }
  //! The grid actually used: cells along x and y, and the cell edge.
  int grid_nx() const { return grid_nx_; }
  int grid_ny() const { return grid_ny_; }
  float grid_cell_size() const { return cell_size_; }

 private:
  engine::Buffer& ensure(std::unique_ptr<engine::Buffer>& buffer, std::size_t bytes);

  engine::Device& device_;
  engine::Kernel& kernel_;
  MatchingCostOptions options_;
  float lambda_;
  float cell_size_ = 0.0f;
  int grid_nx_ = 0;
  int grid_ny_ = 0;
  glm::vec2 grid_origin_{0.0f};
  std::unique_ptr<engine::Buffer> faces_;
  std::unique_ptr<engine::Buffer> cell_start_;
  std::unique_ptr<engine::Buffer> cell_faces_;
  std::unique_ptr<engine::Buffer> cells_;
  std::unique_ptr<engine::Buffer> points_;
  std::unique_ptr<engine::Buffer> translations_;
  std::unique_ptr<engine::Buffer> costs_;
  std::vector<kernels::matching_cost_layout::MatchingFace> host_faces_;
  std::vector<std::uint32_t> host_cell_start_;
  std::vector<std::uint32_t> host_cell_faces_;
  std::vector<kernels::matching_cost_layout::MatchingCell> host_cells_;
  std::size_t last_dispatches_ = 0;
  std::size_t last_fallbacks_ = 0;
  engine::DispatchTiming last_timing_;
};

//! The kernel's description for engine::Device::kernel (SPIR-V, bindings, C++ twin).
const engine::KernelSpec& matching_cost_kernel();

}  // namespace meshquilt
