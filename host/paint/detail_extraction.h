#pragma once
//! Geometric detail of a model as heights (Lai et al. 2005): the model minus a smoothed copy of
//! itself, measured along the smoothed copy's normals, and a patch of it resampled into a height
//! image, which `relief` synthesizes over another base as it does a height image.

#include <optional>
#include <vector>

#include "mesh/tri_mesh.h"
#include "paint/colour_image.h"

namespace meshquilt {

//! Implicit cotangent-Laplacian smoothing, one sparse solve of (M + L^2 K) X = M X0 (M the
//! vertices' lumped areas, K the cotangent stiffness, L the smoothing length): a bump of
//! wavelength w keeps about 1 / (1 + (2 pi L / w)^2) of itself in the smoothed copy, so detail
//! well under 2 pi L goes wholly into the heights. The copy also shrinks where the model curves
//! (a sphere of radius R by about 2 L^2 / R), which the heights carry as an offset.
//! smoothing: L in model units, > 0.
//! \return #V heights along the smoothed copy's vertex normals, signed (outward positive).
//! \throw SolverError when the solve fails.
std::vector<double> extract_detail(const TriMesh& model, double smoothing);

struct DetailImage {
  ColourImage image;            //!< grey: 0 the region's lowest height, 1 its highest
  double low = 0.0, high = 0.0; //!< the heights black and white stand for
  double pixels_per_unit = 0.0; //!< image pixels per model unit

  //! The height white stands for over a base that takes `base_pixels_per_unit` image pixels per
  //! unit: the detail's own range, scaled as its width is.
  double height_over(double base_pixels_per_unit) const {
    return (high - low) * pixels_per_unit / base_pixels_per_unit;
  }
};

//! The heights over a geodesic ball of `radius` round the model's vertex nearest `centre`,
//! flattened conformally, resampled (linearly within faces) on `pixels` x `pixels` centres
//! filling the largest square about the centre that lies wholly over the ball.
//! \throw InputError(invalid_option) "{region}: ..." when the ball is no disk that flattens
//!        without folds, or holds no square of 8 pixels a side.
DetailImage detail_image(const TriMesh& model, const std::vector<double>& heights, const Vec3& centre, double radius,
                         int pixels);

//! Where the model's detail is strongest: of vertices spread evenly over it, the one whose
//! heights within `radius` (in space) vary most.
Vec3 richest_detail_centre(const TriMesh& model, const std::vector<double>& heights, double radius);

//! The sample `relief --from` takes from a model: its detail over a ball of it.
struct DetailSample {
  DetailImage detail;
  double smoothing = 0.0;  //!< L, model units
  Vec3 centre{0.0};        //!< of the ball sampled
  double radius = 0.0;
};

struct DetailRegion {
  Vec3 centre{0.0};
  double radius = 0.0;
};

//! smoothing: L in model units, or 0 for 0.01 of the model's bounding-box diagonal; region: the
//! ball sampled, or none for one of 0.1 of the diagonal round its richest detail.
//! \throw InputError(invalid_option) "{region}: ..." for a radius that is not positive, and as
//!        detail_image; "{from}: no detail ..." where the region is as smooth as its smoothed
//!        self; SolverError as extract_detail.
DetailSample detail_sample(const TriMesh& model, double smoothing, const std::optional<DetailRegion>& region,
                           int pixels);

}  // namespace meshquilt
