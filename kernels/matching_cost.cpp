#include "matching_cost.h"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <span>
#include <string>

#include "error.h"
#include "matching_cost_cpu.h"
#include "matching_cost_layout.h"
#if MESHQUILT_HAS_VULKAN
#include "matching_cost_spv.h"
#endif

namespace meshquilt {
namespace {

using namespace kernels::matching_cost_layout;

constexpr long long kMaxGridCells = 1LL << 22;

[[noreturn]] void invalid(const std::string& problem) {
  throw InputError("matching_cost: " + problem, ExitCode::invalid_option);
}

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

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

MatchingCost::MatchingCost(engine::Device& device, const MatchingSwatch& swatch, MatchingCostOptions options)
    : device_(device), kernel_(device.kernel(matching_cost_kernel())), options_(options), lambda_(swatch.lambda) {
  const std::size_t vertex_count = swatch.positions.size();
  const std::size_t face_count = swatch.triangles.size();
  if (face_count == 0) invalid("the swatch has no faces");
  if (!(std::isfinite(swatch.cell_size) && swatch.cell_size > 0.0f))
    invalid("cell_size must be positive and finite (got " + std::to_string(swatch.cell_size) + ")");
  if (!(std::isfinite(swatch.lambda) && swatch.lambda >= 0.0f))
    invalid("lambda must be non-negative and finite (got " + std::to_string(swatch.lambda) + ")");

  glm::dvec2 low(INFINITY), high(-INFINITY);
  for (const glm::vec3& p : swatch.positions) {
    if (!finite(glm::dvec3(p))) invalid("swatch vertex with a non-finite coordinate");
  }
  std::vector<MatchingFace> faces(face_count);
  std::vector<glm::dvec2> face_low(face_count), face_high(face_count);
  for (std::size_t f = 0; f < face_count; ++f) {
    const auto& tri = swatch.triangles[f];
    for (std::uint32_t v : tri)
      if (v >= vertex_count)
        invalid("face " + std::to_string(f) + " refers to vertex " + std::to_string(v) + " of " +
                std::to_string(vertex_count));
    const glm::vec3 a = swatch.positions[tri[0]], b = swatch.positions[tri[1]], c = swatch.positions[tri[2]];
    const glm::dvec3 da(a), db(b), dc(c);
    const glm::dvec3 cross = glm::cross(db - da, dc - da);
    const double twice_area = glm::length(cross);
    const double longest2 =
        std::max({glm::dot(db - da, db - da), glm::dot(dc - da, dc - da), glm::dot(dc - db, dc - db)});
    // A triangle thinner than ~1e-6 of its longest edge has no usable plane in float; the kernel
    // then measures the distance to its three edges, which is exact for a flat sliver.
    const bool degenerate = !(twice_area > 1e-6 * longest2);
    const glm::dvec3 normal = twice_area > 0.0 ? cross / twice_area : glm::dvec3(0.0);
    // The radius is measured from the float centroid and padded, so the bounding-sphere test
    // never rejects a face it should keep.
    const glm::vec3 middle = (a + b + c) * (1.0f / 3.0f);
    const double radius = std::max({glm::length(da - glm::dvec3(middle)), glm::length(db - glm::dvec3(middle)),
                                    glm::length(dc - glm::dvec3(middle))});
    const float padded = static_cast<float>(radius * (1.0 + 1e-5) + 1e-7 * std::sqrt(longest2));
    faces[f] = {glm::vec4(middle, padded), glm::vec4(glm::vec3(normal), degenerate ? 1.0f : 0.0f),
                glm::vec4(a, 0.0f), glm::vec4(b, 0.0f), glm::vec4(c, 0.0f)};
    face_low[f] = glm::min(glm::min(glm::dvec2(da), glm::dvec2(db)), glm::dvec2(dc));
    face_high[f] = glm::max(glm::max(glm::dvec2(da), glm::dvec2(db)), glm::dvec2(dc));
    low = glm::min(low, face_low[f]);
    high = glm::max(high, face_high[f]);
  }

  // One whole cell of margin past the far corner, so float rounding of the origin and cell
  // size on the device cannot leave a face outside the grid.
  const glm::dvec2 extent = high - low;
  double cell = swatch.cell_size;
  auto cells = [&](double size, double length) { return static_cast<long long>(std::floor(length / size)) + 1; };
  while (cells(cell, extent.x) * cells(cell, extent.y) > kMaxGridCells) cell *= 1.5;
  grid_nx_ = static_cast<int>(cells(cell, extent.x));
  grid_ny_ = static_cast<int>(cells(cell, extent.y));
  cell_size_ = static_cast<float>(cell);
  grid_origin_ = glm::vec2(low);

  // CSR lists: every face goes into each cell its x-y bounding box touches.
  const glm::dvec2 origin(grid_origin_);
  const double pad = 1e-6 * cell;
  auto cell_range = [&](std::size_t f) {
    const glm::dvec2 lo = glm::floor((face_low[f] - pad - origin) / cell);
    const glm::dvec2 hi = glm::floor((face_high[f] + pad - origin) / cell);
    return std::array<int, 4>{std::clamp(static_cast<int>(lo.x), 0, grid_nx_ - 1),
                              std::clamp(static_cast<int>(lo.y), 0, grid_ny_ - 1),
                              std::clamp(static_cast<int>(hi.x), 0, grid_nx_ - 1),
                              std::clamp(static_cast<int>(hi.y), 0, grid_ny_ - 1)};
  };
  const std::size_t cell_count = static_cast<std::size_t>(grid_nx_) * grid_ny_;
  std::vector<std::uint32_t> start(cell_count + 1, 0);
  for (std::size_t f = 0; f < face_count; ++f) {
    const auto r = cell_range(f);
    for (int j = r[1]; j <= r[3]; ++j)
      for (int i = r[0]; i <= r[2]; ++i) ++start[static_cast<std::size_t>(j) * grid_nx_ + i + 1];
  }
  for (std::size_t c = 0; c < cell_count; ++c) start[c + 1] += start[c];
  std::vector<std::uint32_t> members(start[cell_count]);
  std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
  for (std::size_t f = 0; f < face_count; ++f) {
    const auto r = cell_range(f);
    for (int j = r[1]; j <= r[3]; ++j)
      for (int i = r[0]; i <= r[2]; ++i)
        members[fill[static_cast<std::size_t>(j) * grid_nx_ + i]++] = static_cast<std::uint32_t>(f);
  }

  // Per-cell bounds: the faces' 3D box and a cone around their normals.
  std::vector<MatchingCell> cell_bounds(cell_count);
  for (std::size_t cell = 0; cell < cell_count; ++cell) {
    glm::vec3 box_low(INFINITY), box_high(-INFINITY);
    glm::dvec3 normal_sum(0.0);
    bool unbounded = false;
    for (std::uint32_t k = start[cell]; k < start[cell + 1]; ++k) {
      const MatchingFace& face = faces[members[k]];
      for (const glm::vec4* corner : {&face.a, &face.b, &face.c}) {
        box_low = glm::min(box_low, glm::vec3(*corner));
        box_high = glm::max(box_high, glm::vec3(*corner));
      }
      const glm::dvec3 normal(face.normal);
      unbounded = unbounded || glm::dot(normal, normal) < 0.5;  // a zero normal fits no cone
      normal_sum += normal;
    }
    double half_angle = M_PI;
    glm::dvec3 axis(0.0, 0.0, 1.0);
    if (!unbounded && glm::length(normal_sum) > 1e-6) {
      axis = glm::normalize(normal_sum);
      half_angle = 0.0;
      for (std::uint32_t k = start[cell]; k < start[cell + 1]; ++k)
        half_angle = std::max(half_angle, std::acos(std::clamp(glm::dot(axis, glm::dvec3(faces[members[k]].normal)), -1.0, 1.0)));
      // Padding covers float rounding of the normals and of the bound on the device.
      half_angle = std::min(half_angle + 1e-3, M_PI);
    }
    cell_bounds[cell] = {glm::vec4(box_low, static_cast<float>(std::cos(half_angle))),
                         glm::vec4(box_high, static_cast<float>(half_angle >= M_PI ? 0.0 : std::sin(half_angle))),
                         glm::vec4(glm::vec3(axis), 0.0f)};
  }

  auto upload = [&](std::unique_ptr<engine::Buffer>& buffer, const void* data, std::size_t bytes) {
    buffer = device_.create_buffer(bytes);
    if (bytes > 0) std::memcpy(buffer->data(), data, bytes);
  };
  upload(faces_, faces.data(), faces.size() * sizeof(MatchingFace));
  upload(cell_start_, start.data(), start.size() * sizeof(std::uint32_t));
  upload(cell_faces_, members.data(), members.size() * sizeof(std::uint32_t));
  upload(cells_, cell_bounds.data(), cell_bounds.size() * sizeof(MatchingCell));
  // Host copies for pairs the device leaves unfinished (device memory may be slow to read).
  host_faces_ = std::move(faces);
  host_cell_start_ = std::move(start);
  host_cell_faces_ = std::move(members);
  host_cells_ = std::move(cell_bounds);
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
                                             const std::vector<glm::vec2>& translations) {
  if (points.size() != normals.size())
    invalid(std::to_string(points.size()) + " points but " + std::to_string(normals.size()) + " normals");
  // A NaN would reach float-to-int conversions in the ring search.
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!finite(glm::dvec3(points[i])) || !finite(glm::dvec3(normals[i])))
      invalid("point " + std::to_string(i) + " has a non-finite position or normal");
  for (std::size_t c = 0; c < translations.size(); ++c)
    if (!std::isfinite(translations[c].x) || !std::isfinite(translations[c].y))
      invalid("translation " + std::to_string(c) + " is not finite");
  last_dispatches_ = 0;
  last_fallbacks_ = 0;
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
  const std::size_t chunk_points = std::min({point_count, max_pairs, binding / sizeof(MatchingPoint)});
  const std::size_t batch_candidates =
      std::min({candidate_count, std::max<std::size_t>(1, max_pairs / chunk_points), binding / sizeof(vec2)});

  engine::Buffer& point_buffer = ensure(points_, chunk_points * sizeof(MatchingPoint));
  engine::Buffer& translation_buffer = ensure(translations_, batch_candidates * sizeof(vec2));
  engine::Buffer& cost_buffer = ensure(costs_, chunk_points * batch_candidates * sizeof(float));
  engine::Buffer* bindings[MATCHING_COST_BINDING_COUNT];
  bindings[MATCHING_COST_BINDING_FACES] = faces_.get();
  bindings[MATCHING_COST_BINDING_CELL_START] = cell_start_.get();
  bindings[MATCHING_COST_BINDING_CELL_FACES] = cell_faces_.get();
  bindings[MATCHING_COST_BINDING_POINTS] = &point_buffer;
  bindings[MATCHING_COST_BINDING_TRANSLATIONS] = &translation_buffer;
  bindings[MATCHING_COST_BINDING_COSTS] = &cost_buffer;
  bindings[MATCHING_COST_BINDING_CELL_BOUNDS] = cells_.get();

  MatchingCostParams params{};
  params.grid_origin = grid_origin_;
  params.cell_size = cell_size_;
  params.lambda = lambda_;
  params.grid_nx = grid_nx_;
  params.grid_ny = grid_ny_;
  params.mapping = options_.mapping == MatchingCostMapping::per_pair ? MATCHING_COST_PER_PAIR : MATCHING_COST_PER_POINT;
  // A margin below the driver's limit for the few loops the compiler may add around ours.
  const std::uint32_t loop_limit = device_.max_loop_iterations();
  params.iteration_budget = loop_limit == 0 ? 0u : loop_limit - std::min<std::uint32_t>(loop_limit / 2, 256u);

  // Points go to the device sorted by grid cell: neighbouring invocations then search the same
  // cells and faces (for grid-unit translations, in the same order), which keeps SIMD lanes and
  // caches coherent. Results are written back in the caller's order.
  std::vector<std::uint32_t> order(point_count);
  {
    std::vector<std::uint64_t> keys(point_count);
    for (std::size_t i = 0; i < point_count; ++i) {
      const glm::vec2 cell = glm::floor((glm::vec2(points[i]) - grid_origin_) / cell_size_);
      const auto x = static_cast<std::uint32_t>(std::clamp(cell.x + 1e6f, 0.0f, 2e6f));
      const auto y = static_cast<std::uint32_t>(std::clamp(cell.y + 1e6f, 0.0f, 2e6f));
      keys[i] = (std::uint64_t{y} << 32 | x);
      order[i] = static_cast<std::uint32_t>(i);
    }
    std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return keys[a] < keys[b]; });
  }

  for (std::size_t p0 = 0; p0 < point_count; p0 += chunk_points) {
    const std::size_t pn = std::min(chunk_points, point_count - p0);
    auto* gpu_points = static_cast<MatchingPoint*>(point_buffer.data());
    for (std::size_t i = 0; i < pn; ++i) {
      const std::uint32_t source = order[p0 + i];
      gpu_points[i] = {glm::vec4(points[source], 1.0f), glm::vec4(normals[source], 0.0f)};
    }
    for (std::size_t c0 = 0; c0 < candidate_count; c0 += batch_candidates) {
      const std::size_t cn = std::min(batch_candidates, candidate_count - c0);
      std::memcpy(translation_buffer.data(), translations.data() + c0, cn * sizeof(vec2));
      // Costs are >= 1; a negative one after the dispatch marks a pair the device left unfinished.
      std::fill_n(static_cast<float*>(cost_buffer.data()), pn * cn, -1.0f);
      params.point_count = static_cast<std::uint32_t>(pn);
      params.candidate_count = static_cast<std::uint32_t>(cn);
      params.invocation_count =
          static_cast<std::uint32_t>(params.mapping == MATCHING_COST_PER_PAIR ? pn * cn : pn);
      const engine::DispatchTiming timing =
          device_.dispatch(kernel_, bindings, std::as_bytes(std::span(&params, 1)), params.invocation_count);
      ++last_dispatches_;
      last_timing_.wall_seconds += timing.wall_seconds;
      if (timing.device_seconds >= 0.0)
        last_timing_.device_seconds = std::max(last_timing_.device_seconds, 0.0) + timing.device_seconds;
      const auto* costs = static_cast<const float*>(cost_buffer.data());
      for (std::size_t c = 0; c < cn; ++c) {
        float* row = result.data() + (c0 + c) * point_count;
        const glm::vec2 t = translations[c0 + c];
        for (std::size_t i = 0; i < pn; ++i) {
          const std::uint32_t target = order[p0 + i];
          float value = costs[c * pn + i];
          if (value < 0.0f) {
            value = kernels::matching_cost_cpu_point(host_faces_.data(), host_cell_start_.data(),
                                                     host_cell_faces_.data(), host_cells_.data(), params,
                                                     points[target] - glm::vec3(t, 0.0f), normals[target]);
            ++last_fallbacks_;
          }
          row[target] = value;
        }
      }
    }
  }
  return result;
}

std::vector<double> MatchingCost::score(const std::vector<glm::vec3>& points, const std::vector<glm::vec3>& normals,
                                        const std::vector<glm::vec2>& translations) {
  const std::vector<float> costs = point_costs(points, normals, translations);
  std::vector<double> sums(translations.size(), 0.0);
  const std::size_t point_count = points.size();
  for (std::size_t c = 0; c < sums.size(); ++c) {
    double sum = 0.0;
    for (std::size_t i = 0; i < point_count; ++i) sum += costs[c * point_count + i];
    sums[c] = sum;
  }
  return sums;
}

}  // namespace meshquilt
