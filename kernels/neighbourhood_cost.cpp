#include "neighbourhood_cost.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <span>
#include <string>


#include "core/error.h"
#include "neighbourhood_cost_cpu.h"
#if MESHQUILT_HAS_VULKAN
#include "neighbourhood_cost_spv.h"
#endif

namespace meshquilt {
namespace {

using namespace kernels::neighbourhood_cost_layout;

[[noreturn]] void invalid(const std::string& problem) {
  throw InputError("neighbourhood_cost: " + problem, ErrorKind::invalid_option);
}

bool finite(const vec4& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w); }

}  // namespace

const engine::KernelSpec& neighbourhood_cost_kernel() {
  static const engine::KernelSpec spec{"neighbourhood_cost",
#if MESHQUILT_HAS_VULKAN
                                       std::span<const std::uint32_t>(kernels::spirv::neighbourhood_cost),
#else
                                       {},
#endif
                                       NEIGHBOURHOOD_COST_BINDING_COUNT, sizeof(NeighbourhoodCostParams),
                                       NEIGHBOURHOOD_COST_WORKGROUP_SIZE, &kernels::neighbourhood_cost_cpu};
  return spec;
}

NeighbourhoodCost::NeighbourhoodCost(engine::Device& device, int width, int height, const std::vector<glm::vec4>& rgb)
    : device_(device), kernel_(device.kernel(neighbourhood_cost_kernel())), width_(width), height_(height) {
  if (width < 1 || height < 1 || rgb.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height))
    invalid("a " + std::to_string(width) + " x " + std::to_string(height) + " sample with " +
            std::to_string(rgb.size()) + " pixels");
  for (std::size_t i = 0; i < rgb.size(); ++i)
    if (!finite(rgb[i])) invalid("sample pixel " + std::to_string(i) + " is not finite");
  sample_ = device_.create_buffer(rgb.size() * sizeof(vec4));
  std::memcpy(sample_->data(), rgb.data(), rgb.size() * sizeof(vec4));
}

NeighbourhoodCost::~NeighbourhoodCost() = default;

engine::Buffer& NeighbourhoodCost::ensure(std::unique_ptr<engine::Buffer>& buffer, std::size_t bytes) {
  bytes = std::max<std::size_t>(bytes, 16);  // a binding may not be empty
  if (!buffer || buffer->size() < bytes) {
    buffer.reset();  // free first: on lavapipe the old and new buffer would share one heap
    buffer = device_.create_buffer(bytes);
  }
  return *buffer;
}

std::vector<float> NeighbourhoodCost::score(const NeighbourhoodBatch& batch) {
  for (std::size_t v = 0; v < batch.visits.size(); ++v) {
    const NeighbourhoodVisit& visit = batch.visits[v];
    if (visit.first > batch.neighbours.size() || visit.count > batch.neighbours.size() - visit.first)
      invalid("visit " + std::to_string(v) + " lists neighbours past the " + std::to_string(batch.neighbours.size()) +
              " given");
  }
  for (std::size_t k = 0; k < batch.neighbours.size(); ++k)
    if (!finite(batch.neighbours[k].offset) || !finite(batch.neighbours[k].colour))
      invalid("neighbour " + std::to_string(k) + " is not finite");
  for (std::size_t k = 0; k < batch.candidates.size(); ++k) {
    const NeighbourhoodCandidate& c = batch.candidates[k];
    if (c.pixel.x < 0 || c.pixel.x >= width_ || c.pixel.y < 0 || c.pixel.y >= height_ || c.visit >= batch.visits.size() ||
        !(c.fraction.x >= 0.0f && c.fraction.x < 1.0f && c.fraction.y >= 0.0f && c.fraction.y < 1.0f))
      invalid("candidate " + std::to_string(k) + " lies outside the sample or its visits");
  }
  std::vector<float> costs(batch.candidates.size());
  if (batch.candidates.empty()) return costs;
  const std::size_t limit = device_.max_binding_bytes();
  if (batch.neighbours.size() * sizeof(NeighbourhoodNeighbour) > limit || batch.visits.size() * sizeof(NeighbourhoodVisit) > limit)
    invalid("a batch of " + std::to_string(batch.neighbours.size()) + " neighbours exceeds one binding");
  engine::Buffer& visits = ensure(visits_, batch.visits.size() * sizeof(NeighbourhoodVisit));
  engine::Buffer& neighbours = ensure(neighbours_, batch.neighbours.size() * sizeof(NeighbourhoodNeighbour));
  // Visits without neighbours (the first vertex of a sweep) leave the list empty.
  if (!batch.visits.empty()) std::memcpy(visits.data(), batch.visits.data(), batch.visits.size() * sizeof(NeighbourhoodVisit));
  if (!batch.neighbours.empty())
    std::memcpy(neighbours.data(), batch.neighbours.data(), batch.neighbours.size() * sizeof(NeighbourhoodNeighbour));
  const std::size_t per_dispatch = std::min(batch.candidates.size(), limit / sizeof(NeighbourhoodCandidate));
  engine::Buffer& candidates = ensure(candidates_, per_dispatch * sizeof(NeighbourhoodCandidate));
  engine::Buffer& out = ensure(costs_, per_dispatch * sizeof(float));
  engine::Buffer* bindings[NEIGHBOURHOOD_COST_BINDING_COUNT];
  bindings[NEIGHBOURHOOD_COST_BINDING_SAMPLE] = sample_.get();
  bindings[NEIGHBOURHOOD_COST_BINDING_VISITS] = &visits;
  bindings[NEIGHBOURHOOD_COST_BINDING_NEIGHBOURS] = &neighbours;
  bindings[NEIGHBOURHOOD_COST_BINDING_CANDIDATES] = &candidates;
  bindings[NEIGHBOURHOOD_COST_BINDING_COSTS] = &out;
  for (std::size_t first = 0; first < batch.candidates.size(); first += per_dispatch) {
    const std::size_t count = std::min(per_dispatch, batch.candidates.size() - first);
    std::memcpy(candidates.data(), batch.candidates.data() + first, count * sizeof(NeighbourhoodCandidate));
    const NeighbourhoodCostParams params{static_cast<uint>(width_), static_cast<uint>(height_), static_cast<uint>(count), 0};
    device_.dispatch(kernel_, bindings, std::as_bytes(std::span(&params, 1)), static_cast<uint>(count));
    std::memcpy(costs.data() + first, out.data(), count * sizeof(float));
    ++dispatches_;
  }
  return costs;
}

}  // namespace meshquilt
