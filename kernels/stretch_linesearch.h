#pragma once
//! L2-stretch minimization of a shell map by random line searches (Zhou et al. 2006, Sec. 3.2,
//! after Sander et al. 2001), run on the compute engine: the `stretch_linesearch` kernel
//! (stretch_linesearch.comp) on Vulkan, its C++ twin (stretch_linesearch_cpu.cpp) on the CPU
//! back end.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/vec2.hpp>

#include "device.h"
#include "stretch_linesearch_layout.h"

namespace meshquilt {

//! A shell map as the kernel sees it; uploaded once per StretchLineSearch. Corner code
//! c = 2 * atlas_vertex + layer: layer 0 sits in texture space at (bottom_uv[v], 0), layer 1 at
//! (top_uv[v], texture_height).
struct StretchProblem {
  std::vector<glm::vec2> bottom_uv;                                  //!< #A bottom texture corners (fixed)
  std::vector<kernels::stretch_linesearch_layout::StretchTet> tets;  //!< #T tets: corner codes, S, weight
  std::vector<uint32_t> vertex_tet_offsets;                          //!< #A + 1, CSR offsets into vertex_tets
  //! The tets holding the top corner 2a+1 of atlas vertex a are
  //! vertex_tets[vertex_tet_offsets[a] .. vertex_tet_offsets[a + 1]), each exactly once.
  std::vector<uint32_t> vertex_tets;
  float texture_height = 1.0f;  //!< H (> 0)
};

//! Options of StretchLineSearch::run.
struct StretchSearchOptions {
  int sweeps = 20;    //!< passes over all colours (>= 0)
  uint64_t seed = 1;  //!< hashed with the sweep and the vertex into each search direction
  //! Golden-section iterations per line search; each shrinks the bracket by 0.618.
  uint32_t golden_steps = 24;
  //! A move keeps every tet's texture determinant at least this fraction of its value before the
  //! move, in [0, 1): texture tets never invert.
  float min_volume_ratio = 0.25f;
};

//! Lowers the L2 stretch of a shell map by moving top texture corners: per tet the energy is
//! w |S T^-1|_F^2 (S the fixed shell edge matrix, T = [q1-q0, q2-q0, q3-q0] the texture one),
//! per atlas vertex the sum over the tets holding its top corner. Each search moves top_uv[a]
//! along a random direction d (a PCG hash of seed, sweep and a) by the golden-section minimum t*
//! over the interval where every tet keeps det >= min_volume_ratio * det(0) and |t| <= the
//! vertex's largest uv distance to the other corners of its tets, and keeps it only if the
//! energy drops. Vertices with a flat or inverted tet stay. Computed in float32, so a line
//! minimum is found only to about sqrt(float epsilon) of the local edge length (energies closer
//! than their rounding compare either way): Vulkan and CPU runs differ by up to about 5e-4 of an
//! edge in position and 1e-5 relative in energy. A run on the CPU back end is bit-for-bit
//! repeatable for a seed.
class StretchLineSearch {
 public:
  //! Validates and uploads the problem. `device` must outlive this object; `problem` need not.
  //! \throw InputError (ErrorKind::invalid_option) when a size does not match #A, an offset is
  //! out of order or the offsets do not end at vertex_tets.size(), a corner code is >= 2 #A or
  //! repeated within a tet, the vertex lists are not exactly the tets holding each top corner,
  //! a value is not finite, a weight is not positive or texture_height is not positive.
  //! \throw DeviceError when the device fails.
  StretchLineSearch(engine::Device& device, const StretchProblem& problem);
  ~StretchLineSearch();
  StretchLineSearch(const StretchLineSearch&) = delete;
  StretchLineSearch& operator=(const StretchLineSearch&) = delete;

  //! Runs options.sweeps sweeps on `top_uv` (#A, updated in place): sweep s dispatches the
  //! colours in order, one dispatch per non-empty colour, with iteration = s; each dispatch
  //! completes before the next starts. `colours` are lists of atlas vertices that move; a vertex
  //! appears in at most one colour, and no two vertices of a colour share a tet (so their searches
  //! are independent). Vertices in no colour keep their top uv bit for bit.
  //! \throw InputError (ErrorKind::invalid_option) when top_uv.size() != #A or holds a non-finite
  //! value, a colour lists a vertex >= #A, a vertex appears twice, two vertices of a colour share
  //! a tet, sweeps < 0, min_volume_ratio is outside [0, 1), or the searches would exceed the
  //! device's loop budget (Device::max_loop_iterations: about (golden_steps + 4) x the most tets
  //! of a moving vertex). \throw DeviceError when the device fails.
  void run(std::vector<glm::vec2>& top_uv, const std::vector<std::vector<uint32_t>>& colours,
           const StretchSearchOptions& options);

  //! Dispatches made by the last run(): sweeps x the number of non-empty colours.
  std::size_t last_dispatch_count() const { return last_dispatches_; }

 private:
  engine::Device& device_;
  engine::Kernel& kernel_;
  std::size_t vertex_count_ = 0;
  std::size_t tet_count_ = 0;
  float texture_height_ = 1.0f;
  std::vector<uint32_t> vertex_tet_offsets_;  //!< kept for validating colours
  std::vector<uint32_t> vertex_tets_;
  std::unique_ptr<engine::Buffer> bottom_uv_;
  std::unique_ptr<engine::Buffer> top_uv_;
  std::unique_ptr<engine::Buffer> tets_;
  std::unique_ptr<engine::Buffer> offsets_;
  std::unique_ptr<engine::Buffer> vertex_tets_buffer_;
  std::unique_ptr<engine::Buffer> batch_;
  std::size_t last_dispatches_ = 0;
};

//! The kernel's description for engine::Device::kernel (SPIR-V, bindings, C++ twin).
const engine::KernelSpec& stretch_linesearch_kernel();

}  // namespace meshquilt
