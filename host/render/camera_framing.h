#pragma once
//! An orthographic camera that frames a bounding box from one of a few fixed views.

#include "mesh/tri_mesh.h"

namespace meshquilt {

//! Where the camera looks from. Meshes lie in x-y with their thickness along z (as swatches and
//! quilts do), so `top` looks down -z with +y up; `front` looks along +y and `side` along -x,
//! both with +z up; `oblique` looks down at 35 degrees from the diagonal azimuth between -y
//! and +x (from the front right), with +z tilted up.
enum class View { top, oblique, front, side };

//! Elevation of the oblique view above the x-y plane, in degrees.
inline constexpr double kObliqueElevationDegrees = 35.0;

//! An orthographic camera: parallel rays along `forward`, one per pixel centre, starting on a
//! plane in front of everything framed. right, up, forward are orthonormal (right-handed:
//! right x up = -forward).
struct OrthographicCamera {
  Vec3 center{0.0};  //!< the point seen at the image centre
  Vec3 right{1, 0, 0}, up{0, 1, 0}, forward{0, 0, -1};
  double pixel_size = 1.0;    //!< world units per pixel, the same along x and y
  double depth = 1.0;         //!< rays start this far behind `center` (against forward)
  int width = 1, height = 1;  //!< image size in pixels

  //! Origin of the ray through image point (x, y), in pixels from the top left corner (pixel
  //! (i, j) has its centre at (i + 0.5, j + 0.5)). The ray's direction is `forward`.
  Vec3 ray_origin(double x, double y) const {
    return center + right * ((x - 0.5 * width) * pixel_size) + up * ((0.5 * height - y) * pixel_size) -
           forward * depth;
  }
};

//! The unit viewing direction of a view.
Vec3 view_direction(View view);

//! A camera of `view` that shows the whole box [lo, hi] as large as the image allows, centred,
//! with `margin` x width empty at the left and right and `margin` x height at the top and
//! bottom at least: the box's corners, projected on the image plane, span extents (ex, ey) and
//! pixel_size = max(ex / (width (1 - 2 margin)), ey / (height (1 - 2 margin))).
//! A box that projects to a point gets pixel_size 1.
//! \pre lo <= hi, width and height >= 1, 0 <= margin < 0.5.
OrthographicCamera frame_box(const Vec3& lo, const Vec3& hi, View view, int width, int height, double margin);

//! As frame_box, looking along the unit vector `forward`, with +z up in the image (+y when
//! `forward` is within a degree of the z axis).
OrthographicCamera frame_box_along(const Vec3& lo, const Vec3& hi, const Vec3& forward, int width, int height,
                                   double margin);

}  // namespace meshquilt
