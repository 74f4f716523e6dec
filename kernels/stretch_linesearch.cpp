#include "stretch_linesearch.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <span>
#include <string>

#include "core/error.h"
#include "stretch_linesearch_cpu.h"
#include "stretch_linesearch_layout.h"
#if MESHQUILT_HAS_VULKAN
#include "stretch_linesearch_spv.h"
#endif

namespace meshquilt {
namespace {

using namespace kernels::stretch_linesearch_layout;

[[noreturn]] void invalid(const std::string& problem) {
  throw InputError("stretch_linesearch: " + problem, ErrorKind::invalid_option);
}

bool finite(const glm::vec2& v) { return std::isfinite(v.x) && std::isfinite(v.y); }
bool finite(const glm::vec4& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w);
}

std::unique_ptr<engine::Buffer> upload(engine::Device& device, const void* data, std::size_t bytes) {
  // A binding may not be empty: an empty array still gets one word.
  std::unique_ptr<engine::Buffer> buffer = device.create_buffer(std::max<std::size_t>(bytes, 4));
  if (bytes > 0) std::memcpy(buffer->data(), data, bytes);
  return buffer;
}

}  // namespace

const engine::KernelSpec& stretch_linesearch_kernel() {
  static const engine::KernelSpec spec{
      "stretch_linesearch",
#if MESHQUILT_HAS_VULKAN
      std::span<const std::uint32_t>(kernels::spirv::stretch_linesearch),
#else
      {},
#endif
      STRETCH_LINESEARCH_BINDING_COUNT,
      sizeof(StretchParams),
      STRETCH_LINESEARCH_WORKGROUP_SIZE,
      &kernels::stretch_linesearch_cpu};
  return spec;
}

StretchLineSearch::StretchLineSearch(engine::Device& device, const StretchProblem& problem)
    : device_(device), kernel_(device.kernel(stretch_linesearch_kernel())) {
  const std::size_t vertex_count = problem.bottom_uv.size();
  const std::size_t tet_count = problem.tets.size();
  // Corner codes and indices travel as uint32 (a code is 2a + 1).
  if (vertex_count >= std::numeric_limits<uint32_t>::max() / 2 ||
      tet_count >= std::numeric_limits<uint32_t>::max())
    invalid("too many vertices or tets");
  if (!(std::isfinite(problem.texture_height) && problem.texture_height > 0.0f))
    invalid("texture_height must be positive and finite (got " + std::to_string(problem.texture_height) +
            ")");
  for (std::size_t v = 0; v < vertex_count; ++v)
    if (!finite(problem.bottom_uv[v])) invalid("bottom_uv " + std::to_string(v) + " is not finite");
  const std::vector<uint32_t>& offsets = problem.vertex_tet_offsets;
  if (offsets.size() != vertex_count + 1)
    invalid(std::to_string(offsets.size()) + " vertex_tet_offsets for " + std::to_string(vertex_count) +
            " vertices (want #A + 1)");
  if (offsets.front() != 0 || offsets.back() != problem.vertex_tets.size())
    invalid("vertex_tet_offsets must run from 0 to vertex_tets.size() = " +
            std::to_string(problem.vertex_tets.size()));
  for (std::size_t a = 0; a < vertex_count; ++a)
    if (offsets[a] > offsets[a + 1]) invalid("vertex_tet_offsets decrease at vertex " + std::to_string(a));

  std::size_t top_corners = 0;
  for (std::size_t t = 0; t < tet_count; ++t) {
    const StretchTet& tet = problem.tets[t];
    const uint corners[4] = {tet.corners.x, tet.corners.y, tet.corners.z, tet.corners.w};
    for (int i = 0; i < 4; ++i) {
      if (corners[i] >= 2 * vertex_count)
        invalid("tet " + std::to_string(t) + " has corner code " + std::to_string(corners[i]) + " of " +
                std::to_string(2 * vertex_count));
      for (int j = 0; j < i; ++j)
        if (corners[i] == corners[j])
          invalid("tet " + std::to_string(t) + " repeats corner " + std::to_string(corners[i]));
      top_corners += corners[i] & 1u;
    }
    if (!finite(tet.s0) || !finite(tet.s1) || !finite(tet.s2))
      invalid("tet " + std::to_string(t) + " has a non-finite shell edge or weight");
    if (!(tet.s0.w > 0.0f))
      invalid("tet " + std::to_string(t) + " has weight " + std::to_string(tet.s0.w) + " (want > 0)");
  }
  // The lists must hold exactly the tets of each top corner: a missing tet would let two
  // vertices of a colour write and read the same corner.
  if (problem.vertex_tets.size() != top_corners)
    invalid("vertex_tets lists " + std::to_string(problem.vertex_tets.size()) + " tets but the tets have " +
            std::to_string(top_corners) + " top corners");
  std::vector<uint32_t> listed_for(tet_count, std::numeric_limits<uint32_t>::max());
  for (std::size_t a = 0; a < vertex_count; ++a)
    for (uint32_t k = offsets[a]; k < offsets[a + 1]; ++k) {
      const uint32_t t = problem.vertex_tets[k];
      if (t >= tet_count)
        invalid("vertex " + std::to_string(a) + " lists tet " + std::to_string(t) + " of " +
                std::to_string(tet_count));
      const glm::uvec4 c = problem.tets[t].corners;
      const auto code = static_cast<uint32_t>(2 * a + 1);
      if (c.x != code && c.y != code && c.z != code && c.w != code)
        invalid("vertex " + std::to_string(a) + " lists tet " + std::to_string(t) +
                ", which lacks its top corner");
      if (listed_for[t] == a)
        invalid("vertex " + std::to_string(a) + " lists tet " + std::to_string(t) + " twice");
      listed_for[t] = static_cast<uint32_t>(a);
    }

  vertex_count_ = vertex_count;
  tet_count_ = tet_count;
  texture_height_ = problem.texture_height;
  vertex_tet_offsets_ = offsets;
  vertex_tets_ = problem.vertex_tets;
  bottom_uv_ = upload(device_, problem.bottom_uv.data(), vertex_count * sizeof(vec2));
  top_uv_ = device_.create_buffer(std::max<std::size_t>(vertex_count * sizeof(vec2), 4));
  tets_ = upload(device_, problem.tets.data(), tet_count * sizeof(StretchTet));
  offsets_ = upload(device_, offsets.data(), offsets.size() * sizeof(uint));
  vertex_tets_buffer_ = upload(device_, vertex_tets_.data(), vertex_tets_.size() * sizeof(uint));
}

StretchLineSearch::~StretchLineSearch() = default;

void StretchLineSearch::run(std::vector<glm::vec2>& top_uv, const std::vector<std::vector<uint32_t>>& colours,
                            const StretchSearchOptions& options) {
  last_dispatches_ = 0;
  if (top_uv.size() != vertex_count_)
    invalid(std::to_string(top_uv.size()) + " top uvs for " + std::to_string(vertex_count_) + " vertices");
  for (std::size_t v = 0; v < vertex_count_; ++v)
    if (!finite(top_uv[v])) invalid("top_uv " + std::to_string(v) + " is not finite");
  if (options.sweeps < 0) invalid("sweeps must be >= 0 (got " + std::to_string(options.sweeps) + ")");
  if (!(options.min_volume_ratio >= 0.0f && options.min_volume_ratio < 1.0f))
    invalid("min_volume_ratio must lie in [0, 1) (got " + std::to_string(options.min_volume_ratio) + ")");

  // Colours: disjoint, and no two vertices of one colour on a tet.
  constexpr uint32_t unseen = std::numeric_limits<uint32_t>::max();
  std::vector<uint32_t> colour_of(vertex_count_, unseen);
  std::vector<uint32_t> tet_colour(tet_count_, unseen);
  std::vector<uint32_t> batch;
  std::size_t most_tets = 0;
  for (std::size_t c = 0; c < colours.size(); ++c)
    for (uint32_t a : colours[c]) {
      if (a >= vertex_count_)
        invalid("colour " + std::to_string(c) + " lists vertex " + std::to_string(a) + " of " +
                std::to_string(vertex_count_));
      if (colour_of[a] != unseen)
        invalid("vertex " + std::to_string(a) + " appears in colours " + std::to_string(colour_of[a]) +
                " and " + std::to_string(c));
      colour_of[a] = static_cast<uint32_t>(c);
      for (uint32_t k = vertex_tet_offsets_[a]; k < vertex_tet_offsets_[a + 1]; ++k) {
        if (tet_colour[vertex_tets_[k]] == c)
          invalid("colour " + std::to_string(c) + " holds two vertices of tet " +
                  std::to_string(vertex_tets_[k]));
        tet_colour[vertex_tets_[k]] = static_cast<uint32_t>(c);
      }
      most_tets = std::max<std::size_t>(most_tets, vertex_tet_offsets_[a + 1] - vertex_tet_offsets_[a]);
      batch.push_back(a);
    }
  // Loop iterations of one invocation: a pass over its tets, two more for the first golden
  // points, one per step and one for t*, plus the step loop itself.
  const std::uint32_t budget = device_.max_loop_iterations();
  const double iterations =
      (static_cast<double>(options.golden_steps) + 4.0) * (static_cast<double>(most_tets) + 1.0);
  if (budget != 0 && iterations > budget)
    invalid("golden_steps " + std::to_string(options.golden_steps) + " with " + std::to_string(most_tets) +
            " tets at a vertex exceeds the device's loop budget of " + std::to_string(budget) +
            " iterations");
  if (batch.empty() || options.sweeps == 0) return;

  if (!batch_ || batch_->size() < batch.size() * sizeof(uint)) {
    batch_.reset();  // free first: on lavapipe the old and new buffer would share one heap
    batch_ = device_.create_buffer(batch.size() * sizeof(uint));
  }
  std::memcpy(batch_->data(), batch.data(), batch.size() * sizeof(uint));
  std::memcpy(top_uv_->data(), top_uv.data(), vertex_count_ * sizeof(vec2));
  engine::Buffer* bindings[STRETCH_LINESEARCH_BINDING_COUNT];
  bindings[STRETCH_LINESEARCH_BINDING_BOTTOM_UV] = bottom_uv_.get();
  bindings[STRETCH_LINESEARCH_BINDING_TOP_UV] = top_uv_.get();
  bindings[STRETCH_LINESEARCH_BINDING_TETS] = tets_.get();
  bindings[STRETCH_LINESEARCH_BINDING_VERTEX_TET_OFFSETS] = offsets_.get();
  bindings[STRETCH_LINESEARCH_BINDING_VERTEX_TETS] = vertex_tets_buffer_.get();
  bindings[STRETCH_LINESEARCH_BINDING_BATCH] = batch_.get();

  StretchParams params{};
  params.seed_lo = static_cast<uint>(options.seed & 0xffffffffu);
  params.seed_hi = static_cast<uint>(options.seed >> 32);
  params.golden_steps = options.golden_steps;
  params.texture_height = texture_height_;
  params.min_volume_ratio = options.min_volume_ratio;
  for (int sweep = 0; sweep < options.sweeps; ++sweep) {
    params.iteration = static_cast<uint>(sweep);
    params.first = 0;
    for (const std::vector<uint32_t>& colour : colours) {
      params.count = static_cast<uint>(colour.size());
      // Device::dispatch waits for each dispatch: colour k + 1 sees colour k's moves.
      if (params.count > 0) {
        device_.dispatch(kernel_, bindings, std::as_bytes(std::span(&params, 1)), params.count);
        ++last_dispatches_;
      }
      params.first += params.count;
    }
  }
  std::memcpy(top_uv.data(), top_uv_->data(), vertex_count_ * sizeof(vec2));
}

}  // namespace meshquilt
