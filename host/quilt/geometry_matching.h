#pragma once
//! Geometry matching (Section 2.4 of the mesh quilting paper, Eq. 1-3): choose where to place the
//! swatch so that it agrees best with the output already synthesized around the seed.
//!
//! Every decision is made on the exact Eq. 3 in double, so the Vulkan and CPU back ends choose
//! alike. The rule: the candidates whose exact cost is within `rescore_margin` of the best are
//! the near set; its local minima (over the candidate grid's 8-neighbourhood), best first, are
//! refined continuously in x-y (a periodic swatch's period is rarely a whole number of cells);
//! a seeded pick among the refined costs within `choose_tolerance` of the best decides.
//!
//! The device kernel `matching_cost` gives a lower bound of Eq. 3 for every candidate with one
//! voxel fetch per (candidate, point) pair; the host evaluates candidates exactly in the order
//! of their bounds and stops once a bound exceeds the near set's threshold. Every candidate of
//! the near set is therefore evaluated, and the choice equals that of evaluating every
//! candidate exactly (`prune = false`, the reference). Exact costs use the same nearest-face
//! lists, falling back to the Embree BVH where a list cannot decide.

#include <filesystem>
#include <memory>
#include <random>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>

#include "mesh/measures.h"
#include "mesh/tri_mesh.h"
#include "spatial/near_face_grid.h"
#include "spatial/near_face_grid_cache.h"
#include "spatial/normal_bins.h"

namespace meshquilt {

namespace engine {
class Device;
}
class MatchingCost;
class FaceBvh;

struct MatchingOptions {
  double lambda = 1.0;           //!< Eq. 1 weight of distance against normal difference
  double rescore_margin = 0.1;   //!< the near set: candidates whose exact cost <= best x (1 + margin)
  int max_refined = 4;           //!< refine at most this many local minima of the exact cost
  double choose_tolerance = 0.01;  //!< choose at random among refined costs <= best x (1 + tolerance)
  int refine_iterations = 8;     //!< at most this many confirmed moves refine a local minimum
  bool prune = true;             //!< evaluate exactly only candidates whose bound can matter
  //! A pruned evaluation may stop between blocks of max(this, a 32nd of the points); the choice
  //! does not depend on it.
  int abandon_block = 256;
  //! Where nearest-face grids are kept between jobs (spatial/near_face_grid_cache.h); empty:
  //! built for every matcher. The answers are the same either way.
  std::filesystem::path grid_folder;
};

struct MatchResult {
  glm::dvec2 translation{0.0};  //!< where the swatch's origin goes in the output plane
  double cost = 0.0;            //!< exact E(t) (Eq. 3) at `translation`; 0 with no points
  int scored = 0;               //!< candidates bounded by the kernel
  int rescored = 0;             //!< candidates evaluated exactly on the host (or abandoned)
  int abandoned = 0;            //!< of those, evaluations stopped once the candidate was out of the near set
  int near = 0;                 //!< candidates within rescore_margin of the best (exact costs)
};

//! Places a swatch against output points. The swatch must be in its swatch frame (thin along z).
class GeometryMatcher {
 public:
  GeometryMatcher(engine::Device& device, const TriMesh& swatch, double cell_size,
                  const MatchingOptions& options = {});
  ~GeometryMatcher();

  //! Chooses among `candidates` (translations of the swatch on a grid of cell_size) the one
  //! minimizing Eq. 3 over the output `points` with unit `normals` (#P each), refined
  //! continuously within one cell (refine false: the candidates are the only placements that
  //! fit, as the periods of a shared surface layout are, and one of them is chosen as it is).
  //! With no points, a seeded random candidate.
  //! \pre candidates is not empty.
  MatchResult match(const std::vector<Vec3>& points, const std::vector<Vec3>& normals,
                    const std::vector<glm::dvec2>& candidates, std::mt19937_64& rng, bool refine = true) const;

  //! Eq. 3 in double precision: sum over points of min over swatch faces of Eq. 1.
  double exact_cost(const std::vector<Vec3>& points, const std::vector<Vec3>& normals,
                    const glm::dvec2& translation) const;
  //! Eq. 3, and per point the face that minimizes Eq. 1, the lowest index among faces of equal
  //! cost: `faces` (#P, -1 for none) holds faces to try first and receives the minimizing ones.
  //! Neither the cost nor the faces depend on the hints (or on how the search is accelerated).
  double exact_cost(const std::vector<Vec3>& points, const std::vector<Vec3>& normals,
                    const glm::dvec2& translation, std::vector<int32_t>& faces) const;

  //! Whether the nearest-face grid was built, read from grid_folder or written there.
  GridSource grid_source() const { return grid_source_; }

 private:
  //! The public exact_cost with `faces`, given `factors` = normal_factors(normals).
  double exact_cost(const std::vector<Vec3>& points, const std::vector<Vec3>& normals,
                    const std::vector<double>& factors, const glm::dvec2& translation,
                    std::vector<int32_t>& faces) const;
  //! The same, or infinity once the exact costs so far plus `lower` (#P lower bounds of each
  //! point's Eq. 2) of the points left exceed `ceiling`: then Eq. 3 does too. Without `lower`,
  //! exact_cost.
  double exact_cost_up_to(const std::vector<Vec3>& points, const std::vector<Vec3>& normals,
                          const std::vector<double>& factors, const glm::dvec2& translation,
                          std::vector<int32_t>& faces, const double* lower, double ceiling) const;
  //! Eq. 2 for one point moved into the swatch's frame, exact in double; `factors` are the
  //! point's normal bounds per bin; `face` as above.
  double point_cost(const Vec3& q, const Vec3& normal, const double* factors, int32_t& face) const;
  //! Per point, the lower bounds of its normal term over each normal bin (#P x bins).
  std::vector<double> normal_factors(const std::vector<Vec3>& normals) const;
  //! Lowers Eq. 3 in x-y from a grid candidate with exact cost `cost` and minimizing `faces`
  //! (as exact_cost finds them), within one cell of it, by majorize-minimize steps each
  //! confirmed exactly; (translation, cost).
  std::pair<glm::dvec2, double> refine(const std::vector<Vec3>& points, const std::vector<Vec3>& normals,
                                       const std::vector<double>& factors, const glm::dvec2& start,
                                       double cost, std::vector<int32_t> faces) const;

  const TriMesh& swatch_;
  MatchingOptions options_;
  double cell_size_;
  double mean_edge_;  //!< of the swatch's edges
  //! Absolute allowance for rounding in distances: the largest coordinate of the swatch x 1e-12
  //! (a plane distance and a closest point's distance may each be off by a few units in the last
  //! place of the coordinates, which near a face is not small relative to the distance).
  double rounding_;
  std::vector<FaceSphere> face_spheres_;  //!< a quick lower bound of Dist
  std::vector<FacePlane> face_planes_;    //!< Eq. 1's normals; where planar, another bound of Dist
  NormalBins normal_bins_;  //!< of the swatch's faces; grid_ groups its lists by them
  //! Per normal bin, a BVH over its faces: a search far from the swatch passes over bins facing
  //! away and searches the others within the radius their normal bound allows.
  std::vector<std::unique_ptr<FaceBvh>> bin_bvhs_;
  NearFaceGrid grid_;
  GridSource grid_source_ = GridSource::built;
  //! Normal bins per side of the octahedral map at most, and so groups per voxel at most.
  static constexpr int kMaxBinsPerSide = 6;
  static constexpr size_t kMaxBins = kMaxBinsPerSide * kMaxBinsPerSide;
  std::unique_ptr<MatchingCost> kernel_;
};

}  // namespace meshquilt
