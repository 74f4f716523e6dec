#pragma once
//! Geometry matching (Section 2.4 of the mesh quilting paper, Eq. 1-3): choose where to place the
//! swatch so that it agrees best with the output already synthesized around the seed.
//!
//! The device kernel `matching_cost` scores every grid-unit candidate in float32 (it proposes);
//! the host re-scores the candidates near the best exactly in double with Embree (it decides), so
//! the Vulkan and CPU back ends make the same choice. The choice is refined continuously in x-y
//! because a periodic swatch's period is rarely a whole number of cells.

#include <memory>
#include <random>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>

#include "mesh/tri_mesh.h"

namespace meshquilt {

namespace engine {
class Device;
}
class MatchingCost;
class FaceBvh;

struct MatchingOptions {
  double lambda = 1.0;           //!< Eq. 1 weight of distance against normal difference
  double rescore_margin = 0.1;   //!< re-score candidates whose kernel cost <= best x (1 + margin)
  int max_refined = 4;           //!< refine at most this many local minima of the exact cost
  double choose_tolerance = 0.01;  //!< choose at random among refined costs <= best x (1 + tolerance)
  int refine_steps = 3;          //!< pattern-search step halvings before the ICP steps
};

struct MatchResult {
  glm::dvec2 translation{0.0};  //!< where the swatch's origin goes in the output plane
  double cost = 0.0;            //!< exact E(t) (Eq. 3) at `translation`; 0 with no points
  int scored = 0;               //!< candidates scored by the kernel
  int rescored = 0;             //!< candidates re-scored exactly on the host
};

//! Places a swatch against output points. The swatch must be in its swatch frame (thin along z).
class GeometryMatcher {
 public:
  GeometryMatcher(engine::Device& device, const TriMesh& swatch, double cell_size,
                  const MatchingOptions& options = {});
  ~GeometryMatcher();

  //! Chooses among `candidates` (translations of the swatch on a grid of cell_size) the one
  //! minimizing Eq. 3 over the output `points` with unit `normals` (#P each), refined
  //! continuously within one cell. With no points, a seeded random candidate.
  //! \pre candidates is not empty.
  MatchResult match(const std::vector<Vec3>& points, const std::vector<Vec3>& normals,
                    const std::vector<glm::dvec2>& candidates, std::mt19937_64& rng) const;

  //! Eq. 3 in double precision: sum over points of min over swatch faces of Eq. 1.
  double exact_cost(const std::vector<Vec3>& points, const std::vector<Vec3>& normals,
                    const glm::dvec2& translation) const;

 private:
  //! Pattern search in x-y from a grid candidate with exact cost `cost`; (translation, cost).
  std::pair<glm::dvec2, double> refine(const std::vector<Vec3>& points, const std::vector<Vec3>& normals,
                                       const glm::dvec2& start, double cost) const;

  const TriMesh& swatch_;
  MatchingOptions options_;
  double cell_size_;
  std::vector<Vec3> face_normals_;
  std::unique_ptr<FaceBvh> bvh_;
  std::unique_ptr<MatchingCost> kernel_;
};

}  // namespace meshquilt
