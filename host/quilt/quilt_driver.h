#pragma once
//! The skeleton both quilting drivers share (Section 2.3 of the mesh quilting paper, and the
//! clean-up of Section 4): the setup (swatch, scheduling cells, matcher), the seed loop (the next
//! seed with the most processed neighbours, a patch there, until every cell is processed or given
//! up on as a hole), and the end (broken elements removed, the rest joined). Each driver brings
//! its domain: how a patch is quilted at a seed cell, and how far synthesis has come.

#include <cstdint>
#include <functional>
#include <vector>

#include "device.h"
#include "mesh/tri_mesh.h"
#include "quilt/broken_elements.h"
#include "quilt/geometry_matching.h"
#include "quilt/hole_tracker.h"
#include "quilt/patch_step.h"
#include "quilt/quilt_options.h"
#include "quilt/seed_finding.h"

namespace meshquilt {

//! What both drivers prepare before the seed loop. Built in place (the matcher refers to the
//! swatch), timed as the stages "swatch" and "index".
struct QuiltSetup {
  //! \throw InputError for a degenerate swatch; DeviceError from the matcher's buffers.
  QuiltSetup(const TriMesh& input_swatch, engine::Device& device, const QuiltOptions& options, QuiltStats& stats);
  QuiltSetup(const QuiltSetup&) = delete;
  QuiltSetup& operator=(const QuiltSetup&) = delete;

  const QuiltSwatch swatch;
  const double cell;              //!< scheduling cell side, swatch units
  const int swatch_nx, swatch_ny;  //!< whole cells across the swatch
  const PatchStepOptions step;    //!< options.step, lambda in the swatch's mean edges
  const GeometryMatcher matcher;  //!< the swatch's nearest-face grid, BVH and device buffers
};

//! A driver's domain, as the seed loop sees it.
struct SeedLoopDomain {
  //! Quilts one patch seeded on `cell` and marks the cells it covered processed.
  std::function<void(int cell)> quilt_patch_at;
  //! Optional: `cell` was given up on as a hole (marked processed without being covered).
  std::function<void(int cell)> given_up;
  //! How far synthesis has come (patches filled in by the loop), for options.progress.
  std::function<QuiltProgress()> progress;
};

//! Seeds patches until every cell is processed (covered, or given up on after
//! options.seed_attempts tries) or options.max_patches patches were made; counts stats.patches.
//! \throw Cancelled when options.cancel is set.
void run_seed_loop(SeedFinder& seeds, HoleTracker& holes, const QuiltOptions& options, QuiltStats& stats,
                   const SeedLoopDomain& domain);

//! The end of synthesis: with options.cleanup, elements that are not closed where the swatch's
//! are, and the smaller of two that pass through each other, are dropped from `alive`; the alive
//! ones of `elements` (moved out) are joined in order, each face carrying its element's source.
//! Counts the dropped elements in `stats`; `removed`, when given, gets the clean-up's report;
//! `known`: as remove_broken_elements takes it.
TriMesh finish_quilt(std::vector<TriMesh>& elements, std::vector<uint8_t>& alive, const std::vector<int32_t>& sources,
                     const QuiltSetup& setup, const QuiltOptions& options, QuiltStats& stats,
                     BrokenElements* removed = nullptr, const FaceIntersections* known = nullptr);

}  // namespace meshquilt
