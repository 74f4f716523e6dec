#pragma once
//! Mismatch of image neighbourhoods against an image sample at candidate positions (the search
//! of texture synthesis on surfaces), scored on the compute engine: the `neighbourhood_cost`
//! kernel (neighbourhood_cost.comp) on Vulkan, its C++ twin on the CPU back end.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/vec4.hpp>

#include "device.h"
#include "neighbourhood_cost_layout.h"

namespace meshquilt {

//! Visits, their neighbours and the candidates to score, as the kernel reads them.
struct NeighbourhoodBatch {
  std::vector<kernels::neighbourhood_cost_layout::NeighbourhoodVisit> visits;
  std::vector<kernels::neighbourhood_cost_layout::NeighbourhoodNeighbour> neighbours;
  std::vector<kernels::neighbourhood_cost_layout::NeighbourhoodCandidate> candidates;

  void clear() {
    visits.clear();
    neighbours.clear();
    candidates.clear();
  }
};

//! For each candidate c of a visit with neighbours (offset o, weight w, colour q):
//!   cost(c) = sum over neighbours of w * |q - S(c + o)|^2,
//! S the sample read bilinearly between pixel centres (pixel i's centre at i + 0.5) and wrapped
//! round its borders. In float32: Vulkan and the C++ twin agree to about 1e-6 of the summed
//! weight plus the cost, which is what a caller choosing among candidates must allow for.
class NeighbourhoodCost {
 public:
  //! Uploads the sample: `rgb` (xyz used) row-major, width x height. `device` must outlive this.
  //! \throw InputError (ErrorKind::invalid_option) for an empty or mis-sized sample or a
  //! non-finite colour; DeviceError when the device fails.
  NeighbourhoodCost(engine::Device& device, int width, int height, const std::vector<glm::vec4>& rgb);
  ~NeighbourhoodCost();
  NeighbourhoodCost(const NeighbourhoodCost&) = delete;
  NeighbourhoodCost& operator=(const NeighbourhoodCost&) = delete;

  //! The cost of each candidate of `batch`, in order.
  //! \throw InputError when a candidate's pixel or visit, or a visit's neighbours, are out of
  //! range or a value is not finite; DeviceError when the device fails.
  std::vector<float> score(const NeighbourhoodBatch& batch);

  //! Dispatches made so far.
  std::size_t dispatches() const { return dispatches_; }

 private:
  engine::Buffer& ensure(std::unique_ptr<engine::Buffer>& buffer, std::size_t bytes);

  engine::Device& device_;
  engine::Kernel& kernel_;
  int width_ = 0, height_ = 0;
  std::unique_ptr<engine::Buffer> sample_;
  std::unique_ptr<engine::Buffer> visits_;
  std::unique_ptr<engine::Buffer> neighbours_;
  std::unique_ptr<engine::Buffer> candidates_;
  std::unique_ptr<engine::Buffer> costs_;
  std::size_t dispatches_ = 0;
};

//! The kernel's description for engine::Device::kernel (SPIR-V, bindings, C++ twin).
const engine::KernelSpec& neighbourhood_cost_kernel();

}  // namespace meshquilt
