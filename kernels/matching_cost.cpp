#include "matching_cost.h"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <span>
#include <string>

#include "core/error.h"
#include "matching_cost_cpu.h"
#include "matching_cost_layout.h"
#if MESHQUILT_HAS_VULKAN
#include "matching_cost_spv.h"
#endif

namespace meshquilt {
namespace {

using namespace kernels::matching_cost_layout;

[[noreturn]] void invalid(const std::string& problem) {
  throw InputError("matching_cost: " + problem, ErrorKind::invalid_option);
}

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// A buffer of `count` T, to be written through the pointer returned (mapped device memory, or
// host memory on the CPU back end): no staging copy, which for large grids cost more than the
// upload itself. A binding may not be empty: an empty
// array still gets one word.
template <typename T>
T* allocate(engine::Device& device, std::unique_ptr<engine::Buffer>& target, std::size_t count) {
  target = device.create_buffer(std::max<std::size_t>(count * sizeof(T), 4));
  return static_cast<T*>(target->data());
}

}  // namespace

const engine::KernelSpec& matching_cost_kernel() {
  static const engine::KernelSpec spec{
      "matching_cost",
#if MESHQUILT_HAS_VULKAN
      std::span<const std::uint32_t>(kernels::spirv::matching_cost),
#else
      {},
#endif
      MATCHING_COST_BINDING_COUNT,
      sizeof(MatchingCostParams),
      MATCHING_COST_WORKGROUP_SIZE,
      &kernels::matching_cost_cpu};
  return spec;
}

MatchingCost::MatchingCost(engine::Device& device, const MatchingSwatch& swatch, const NearFaceGrid& grid,
                           MatchingCostOptions options)
    : device_(device), kernel_(device.kernel(matching_cost_kernel())), options_(options) {
  const std::size_t vertex_count = swatch.positions.size();
  const std::size_t face_count = swatch.triangles.size();
  if (face_count == 0) invalid("the swatch has no faces");
  if (swatch.normals.size() != face_count)
    invalid(std::to_string(swatch.normals.size()) + " normals for " + std::to_string(face_count) + " faces");
  if (!(std::isfinite(swatch.lambda) && swatch.lambda >= 0.0f))
    invalid("lambda must be non-negative and finite (got " + std::to_string(swatch.lambda) + ")");
  for (const glm::vec3& p : swatch.positions) {
    if (!finite(glm::dvec3(p))) invalid("swatch vertex with a non-finite coordinate");
    swatch_scale_ = std::max({swatch_scale_, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  }
  const std::size_t voxel_count = static_cast<std::size_t>(grid.size.x) * grid.size.y * grid.size.z;
  if (!(grid.voxel > 0.0) || grid.start.size() != voxel_count + 1 || grid.reach.size() != voxel_count ||
      grid.faces.size() != grid.start.back())
    invalid("the nearest-face grid is malformed");
  for (std::uint32_t f : grid.faces)
    if (f >= face_count) invalid("the nearest-face grid lists face " + std::to_string(f) + " of " + std::to_string(face_count));

  // Each array is written straight into its buffer (see allocate).
  auto* faces = allocate<MatchingFace>(device_, faces_, face_count);
  for (std::size_t f = 0; f < face_count; ++f) {
    const auto& tri = swatch.triangles[f];
    for (std::uint32_t v : tri)
      if (v >= vertex_count)
        invalid("face " + std::to_string(f) + " refers to vertex " + std::to_string(v) + " of " +
                std::to_string(vertex_count));
    if (!finite(glm::dvec3(swatch.normals[f]))) invalid("face " + std::to_string(f) + " has a non-finite normal");
    const glm::vec3 a = swatch.positions[tri[0]], b = swatch.positions[tri[1]], c = swatch.positions[tri[2]];
    const glm::dvec3 da(a), db(b), dc(c);
    const double twice_area = glm::length(glm::cross(db - da, dc - da));
    const double longest2 =
        std::max({glm::dot(db - da, db - da), glm::dot(dc - da, dc - da), glm::dot(dc - db, dc - db)});
    // A triangle thinner than ~1e-6 of its longest edge has no usable plane in float; the kernel
    // then measures the distance to its three edges, which is exact for a flat sliver.
    const bool degenerate = !(twice_area > 1e-6 * longest2);
    // The radius is measured from the float centroid and padded, so the bounding-sphere test
    // never rejects a face it should keep.
    const glm::vec3 middle = (a + b + c) * (1.0f / 3.0f);
    const double radius = std::max({glm::length(da - glm::dvec3(middle)), glm::length(db - glm::dvec3(middle)),
                                    glm::length(dc - glm::dvec3(middle))});
    const float padded = static_cast<float>(radius * (1.0 + 1e-5) + 1e-7 * std::sqrt(longest2));
    // Twice the area at least a tenth of the longest edge squared: no corner sharper than about
    // 5.7 degrees, where finding the nearest feature by region is safe in float.
    const bool well_shaped = twice_area > 0.1 * longest2;
    faces[f] = {glm::vec4(middle, padded), glm::vec4(swatch.normals[f], degenerate ? 1.0f : 0.0f),
                glm::vec4(a, well_shaped ? 1.0f : 0.0f), glm::vec4(b, 0.0f), glm::vec4(c, 0.0f)};
  }
  // Distances rounded down, so no bound on the device exceeds what the grid guarantees.
  auto round_down = [](double value) {
    float rounded = static_cast<float>(std::min(value, static_cast<double>(std::numeric_limits<float>::max())));
    if (static_cast<double>(rounded) > value) rounded = std::nextafter(rounded, -INFINITY);
    return rounded;
  };
  if (grid.near.size() != grid.faces.size() || grid.group_start.size() != voxel_count + 1 ||
      grid.group_start.back() != grid.groups.size())
    invalid("the nearest-face grid is malformed");
  if (swatch.normal_bins == 0) invalid("no normal bins");
  bins_ = swatch.normal_bins;
  auto* listed = allocate<MatchingListed>(device_, voxel_faces_, grid.faces.size());
  for (std::size_t k = 0; k < grid.faces.size(); ++k) listed[k] = {grid.faces[k], grid.near[k]};
  auto* groups = allocate<MatchingGroup>(device_, groups_, grid.groups.size());
  for (std::size_t g = 0; g < grid.groups.size(); ++g) {
    const FaceGroup& group = grid.groups[g];
    if (group.label >= bins_ || group.first >= group.end || group.end > grid.faces.size())
      invalid("the nearest-face grid is malformed");
    groups[g] = {group.first, group.end, group.label, group.near};
  }
  auto* voxels = allocate<MatchingVoxel>(device_, voxels_, voxel_count);
  for (std::size_t v = 0; v < voxel_count; ++v) {
    voxels[v] = {grid.group_start[v], grid.group_start[v + 1] - grid.group_start[v], round_down(grid.reach[v]), 0.0f};
  }
  grid_params_.origin = glm::vec4(glm::vec3(grid.origin), static_cast<float>(grid.voxel));
  grid_params_.box_low = glm::vec4(glm::vec3(grid.box_low), swatch.lambda);
  grid_params_.box_high = glm::vec4(glm::vec3(grid.box_high), 0.0f);
  grid_params_.grid_nx = grid.size.x;
  grid_params_.grid_ny = grid.size.y;
  grid_params_.grid_nz = grid.size.z;
}

MatchingCost::~MatchingCost() = default;

engine::Buffer& MatchingCost::ensure(std::unique_ptr<engine::Buffer>& buffer, std::size_t bytes) {
  if (!buffer || buffer->size() < bytes) {
    buffer.reset();  // free first: on lavapipe the old and new buffer would share one heap
    buffer = device_.create_buffer(bytes);
  }
  return *buffer;
}

std::vector<float> MatchingCost::point_costs(const std::vector<glm::vec3>& points,
                                             const std::vector<glm::vec3>& normals,
                                             const std::vector<glm::vec2>& translations,
                                             const std::vector<double>& factors) {
  if (points.size() != normals.size())
    invalid(std::to_string(points.size()) + " points but " + std::to_string(normals.size()) + " normals");
  if (!factors.empty() && factors.size() != points.size() * bins_)
    invalid(std::to_string(factors.size()) + " normal factors for " + std::to_string(points.size()) + " points and " +
            std::to_string(bins_) + " bins");
  for (double f : factors)
    if (!(f >= 0.0 && std::isfinite(f))) invalid("a normal factor is negative or not finite");
  // A NaN would reach float-to-int conversions in the voxel lookup.
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!finite(glm::dvec3(points[i])) || !finite(glm::dvec3(normals[i])))
      invalid("point " + std::to_string(i) + " has a non-finite position or normal");
  for (std::size_t c = 0; c < translations.size(); ++c)
    if (!std::isfinite(translations[c].x) || !std::isfinite(translations[c].y))
      invalid("translation " + std::to_string(c) + " is not finite");
  last_dispatches_ = 0;
  last_timing_ = {};
  const std::size_t point_count = points.size();
  const std::size_t candidate_count = translations.size();
  std::vector<float> result(point_count * candidate_count);
  if (result.empty()) return result;

  // Batches: a chunk of points (all of them unless one candidate's costs overflow a binding)
  // times as many candidates as fit; every batch is one dispatch.
  const std::size_t binding = device_.max_binding_bytes();
  std::size_t max_pairs = binding / sizeof(float);
  if (options_.max_pairs_per_dispatch > 0) max_pairs = std::min(max_pairs, options_.max_pairs_per_dispatch);
  max_pairs = std::min<std::size_t>(max_pairs, 1u << 30);
  const std::size_t chunk_points =
      std::min({point_count, max_pairs, binding / sizeof(MatchingPoint), binding / (bins_ * sizeof(float))});
  const std::size_t batch_candidates =
      std::min({candidate_count, std::max<std::size_t>(1, max_pairs / chunk_points), binding / sizeof(vec2)});
  engine::Buffer& point_buffer = ensure(points_, chunk_points * sizeof(MatchingPoint));
  engine::Buffer& translation_buffer = ensure(translations_, batch_candidates * sizeof(vec2));
  engine::Buffer& cost_buffer = ensure(costs_, chunk_points * batch_candidates * sizeof(float));
  engine::Buffer& factor_buffer = ensure(factors_, chunk_points * bins_ * sizeof(float));
  engine::Buffer* bindings[MATCHING_COST_BINDING_COUNT];
  bindings[MATCHING_COST_BINDING_FACES] = faces_.get();
  bindings[MATCHING_COST_BINDING_VOXEL_FACES] = voxel_faces_.get();
  bindings[MATCHING_COST_BINDING_VOXELS] = voxels_.get();
  bindings[MATCHING_COST_BINDING_POINTS] = &point_buffer;
  bindings[MATCHING_COST_BINDING_TRANSLATIONS] = &translation_buffer;
  bindings[MATCHING_COST_BINDING_COSTS] = &cost_buffer;
  bindings[MATCHING_COST_BINDING_GROUPS] = groups_.get();
  bindings[MATCHING_COST_BINDING_FACTORS] = &factor_buffer;
  MatchingCostParams params = grid_params_;
  params.bin_count = bins_;

  for (std::size_t p0 = 0; p0 < point_count; p0 += chunk_points) {
    const std::size_t pn = std::min(chunk_points, point_count - p0);
    auto* gpu_points = static_cast<MatchingPoint*>(point_buffer.data());
    for (std::size_t i = 0; i < pn; ++i)
      gpu_points[i] = {glm::vec4(points[p0 + i], 1.0f), glm::vec4(normals[p0 + i], 0.0f)};
    // Rounded down, with room for the kernel's float normal term (a few ulps off in 1e-6).
    auto* gpu_factors = static_cast<float*>(factor_buffer.data());
    for (std::size_t k = 0; k < pn * bins_; ++k) {
      if (factors.empty()) {
        gpu_factors[k] = 1.0f;
        continue;
      }
      const double bound = factors[p0 * bins_ + k] * (1.0 - 1e-6);
      float rounded = static_cast<float>(bound);
      if (static_cast<double>(rounded) > bound) rounded = std::nextafter(rounded, 0.0f);
      gpu_factors[k] = rounded;
    }
    for (std::size_t c0 = 0; c0 < candidate_count; c0 += batch_candidates) {
      const std::size_t cn = std::min(batch_candidates, candidate_count - c0);
      std::memcpy(translation_buffer.data(), translations.data() + c0, cn * sizeof(vec2));
      params.point_count = static_cast<std::uint32_t>(pn);
      params.candidate_count = static_cast<std::uint32_t>(cn);
      params.invocation_count = static_cast<std::uint32_t>(pn * cn);
      const engine::DispatchTiming timing =
          device_.dispatch(kernel_, bindings, std::as_bytes(std::span(&params, 1)), params.invocation_count);
      ++last_dispatches_;
      last_timing_.wall_seconds += timing.wall_seconds;
      if (timing.device_seconds >= 0.0)
        last_timing_.device_seconds = std::max(last_timing_.device_seconds, 0.0) + timing.device_seconds;
      const auto* costs = static_cast<const float*>(cost_buffer.data());
      for (std::size_t c = 0; c < cn; ++c)
        std::copy_n(costs + c * pn, pn, result.data() + (c0 + c) * point_count + p0);
    }
  }
  return result;
}

std::vector<double> MatchingCost::score(const std::vector<glm::vec3>& points, const std::vector<glm::vec3>& normals,
                                        const std::vector<glm::vec2>& translations,
                                        const std::vector<double>& factors) {
  const std::vector<double> pairs = pair_bounds(points, normals, translations, factors);
  std::vector<double> sums(translations.size(), 0.0);
  const std::size_t point_count = points.size();
  for (std::size_t c = 0; c < sums.size(); ++c) {
    double sum = 0.0;
    for (std::size_t i = 0; i < point_count; ++i) sum += pairs[c * point_count + i];
    sums[c] = sum;
  }
  return sums;
}

std::vector<double> MatchingCost::pair_bounds(const std::vector<glm::vec3>& points,
                                              const std::vector<glm::vec3>& normals,
                                              const std::vector<glm::vec2>& translations,
                                              const std::vector<double>& factors) {
  const std::vector<float> costs = point_costs(points, normals, translations, factors);
  // Float32 moves a query by a few ulps of the largest coordinate involved and each distance
  // by a few ulps of the swatch's: 3e-6 x that scale (times lambda and the normal factor, at
  // most 3) covers both with room; 1e-5 relative covers the products.
  float scale = swatch_scale_;
  for (const glm::vec3& p : points) scale = std::max({scale, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  float shift = 0.0f;
  for (const glm::vec2& t : translations) shift = std::max({shift, std::abs(t.x), std::abs(t.y)});
  const double margin = 3.0 * grid_params_.box_low.w * 3e-6 * (static_cast<double>(scale) + shift);
  std::vector<double> pairs(costs.size());
  for (std::size_t k = 0; k < costs.size(); ++k) pairs[k] = std::max(1.0, costs[k] * (1.0 - 1e-5) - margin);
  return pairs;
}

}  // namespace meshquilt
