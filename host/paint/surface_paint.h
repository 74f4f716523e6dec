#pragma once
//! Colour synthesized over a surface from an image sample (Turk 2001, "Texture Synthesis on
//! Surfaces"): the base refined until a vertex falls at least every sample pixel, each vertex
//! coloured in a sweep along the orienting field by the sample position whose neighbourhood best
//! matches its coloured neighbours', read in the vertex's own frame (field, normal x field).
//!
//! Candidates come from the neighbours' own sample positions, each shifted by its offset
//! (coherent synthesis, Ashikhmin 2001), plus a few at random: a search over a handful of
//! positions instead of the whole sample, scored on the compute engine (neighbourhood_cost) and
//! chosen in double on the host, so both back ends choose alike. Turk's sweep is sequential; it
//! runs here in batches of vertices out of each other's windows, which give the same colours
//! (sweep_batches.h). It runs coarse to fine: the sample halved while it holds more than a window, the sweep on the matching
//! coarse split level, each finer level started from the positions carried over, their patches
//! made rigid (rigid_sources.h), and corrected; every level but the finest is then made rigid
//! and corrected once more.
//! Candidates that few neighbours propose are weighed down (coherence), so patches grow large.
//! A window reads one vertex per half-pixel cell at most, however dense the base.

#include <cstdint>
#include <functional>
#include <vector>

#include <glm/vec2.hpp>

#include "core/error.h"
#include "device.h"
#include "mesh/tri_mesh.h"
#include "paint/colour_image.h"
#include "surface/guidance_field.h"

namespace meshquilt {

struct PaintOptions {
  double pixels_per_unit = 0.0;   //!< sample pixels per base unit (> 0)
  int window = 7;                 //!< neighbourhood width in pixels, odd, 3..21
  int random_candidates = 4;      //!< sample positions tried at random per vertex, besides the coherent ones
  int passes = 2;                 //!< the sweep, then passes over whole neighbourhoods (1..8)
  double coherence = 2.0;         //!< a candidate no neighbour proposes costs 1 + this times its mismatch (0..100)
  uint64_t seed = 1;              //!< of every random choice
  size_t max_vertices = 4000000;  //!< refuse a refinement past this many vertices
  size_t max_batch = 4096;        //!< vertices scored in one dispatch; 1: the sweep one vertex at a time
  //! Called after each batch with the visits made and all the job will make (every level and
  //! pass): the last call has done == total.
  std::function<void(size_t done, size_t total)> progress;
  //! Polled after each batch: once cancelled, paint_surface throws Cancelled.
  const CancelToken* cancel = nullptr;
};

struct PaintResult {
  TriMesh mesh;                        //!< the base refined, with a colour per vertex
  std::vector<glm::dvec2> source;      //!< #V sample position (pixels) each vertex took its colour from
  std::vector<int32_t> order;          //!< the sweep: vertices in the order they were coloured
  std::vector<Vec3> directions;        //!< #V the field at each vertex: its frame's x axis
  int levels = 0;                      //!< 1-to-4 splits of the base
  int sample_levels = 0;               //!< samples run coarse to fine: the sample and its halvings
  double mean_cost = 0.0;              //!< mean neighbourhood mismatch of the last pass, per neighbour
  size_t visits = 0;                   //!< vertices coloured, over every level and pass
  size_t batches = 0;                  //!< batches of them scored side by side
  size_t neighbours = 0;               //!< window neighbours read, over every visit
};

//! Paints `base` from `sample`, oriented by the guidance field of `constraints` (synth's
//! --field; none: its default). Constraint vertices are the base's own (split_faces keeps them).
//! Deterministic for a seed, and the same on either back end of `device`.
//! \throw InputError(invalid_option) for options out of range or a refinement past max_vertices;
//!        InputError(invalid_mesh) for a base without faces; SolverError from the solves;
//!        Cancelled once options.cancel is.
PaintResult paint_surface(const TriMesh& base, const ColourImage& sample,
                          const std::vector<FieldConstraint>& constraints, const PaintOptions& options,
                          engine::Device& device);

}  // namespace meshquilt
