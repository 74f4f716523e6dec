#pragma once
//! A preview image of a mesh: orthographic rays cast through Embree (spatial/face_bvh.h), each
//! hit shaded with Lambert's law under a key light and a headlight plus ambient light, on a
//! light background. No GPU and no display are needed.

#include <optional>
#include <string>

#include "mesh/tri_mesh.h"
#include "render/camera_framing.h"
#include "render/rgb_image.h"

namespace meshquilt {

//! What the colours show.
enum class RenderMode {
  shaded,    //!< a neutral grey-blue, lightly tinted per element, so shape reads first
  elements,  //!< each element in its own flat colour (element_palette.h), lightly shaded
  colors,    //!< the mesh's vertex colours (`meshquilt edit --color-by`), averaged per face
};

//! Largest accepted image side, in pixels.
inline constexpr int kMaxImageSide = 8192;

//! A close-up: the elements with a vertex within `radius` of `point`, seen along the line from
//! `point` to the centre of the whole mesh's bounding box (from outside a convex base).
struct CloseUp {
  Vec3 point{0.0};
  double radius = 0.0;  //!< 0: a tenth of the mesh's bounding box diagonal
};

struct RenderOptions {
  int width = 1024;           //!< image width in pixels, 1..kMaxImageSide
  int height = 768;           //!< image height in pixels, 1..kMaxImageSide
  View view = View::oblique;  //!< camera direction (camera_framing.h)
  RenderMode mode = RenderMode::shaded;
  int samples = 2;                 //!< rays per pixel along each side (2: 4 rays, smoothed
                                   //!< edges; 1: one ray through each pixel centre), 1..4
  double margin = 0.05;            //!< empty share of the width (height) left at each side
  Rgb8 background{244, 245, 247};  //!< colour where no face is hit (lighter than any hit)
  //! Faces of this element id are drawn in a plain light grey in every mode (a base mesh shown
  //! under its texture); -1: none.
  int32_t plain_element = -1;
  int up = 2;  //!< the mesh's axis (0 x, 1 y, 2 z) shown upward, as z is: 1 for y-up scans
  std::optional<CloseUp> close_up;  //!< replaces `view` and the framing on the whole mesh
};

//! Parses `--view top|oblique|front|side`. \throw InputError(invalid_option) naming --view.
View parse_view(const std::string& text);

//! Parses `--mode shaded|elements|colors`. \throw InputError(invalid_option) naming --mode.
RenderMode parse_render_mode(const std::string& text);

//! Parses `--up x|y|z` into RenderOptions::up. \throw InputError(invalid_option) naming --up.
int parse_up_axis(const std::string& text);

//! \throw InputError(invalid_option) naming `--size WxH` when a side is outside
//!        1..kMaxImageSide, or naming the option when samples is outside 1..4 or margin outside
//!        [0, 0.45], or naming --radius when a close-up's radius is negative or not finite.
void validate_render_options(const RenderOptions& options);

//! Renders `mesh` framed by its bounding box (frame_box) in options.width x options.height
//! pixels. Faces are flat shaded and two-sided (a face seen from behind is lit as if seen from
//! the front). Elements come from mesh.elements, or connected components when it is empty
//! (face_element_ids). Rows are rendered in parallel; the image does not depend on the thread
//! count. Channels of a hit are capped at 240, so with the default background a pixel whose
//! rays all hit faces never takes the background colour.
//! With a close-up, only its elements are drawn, framed on their box.
//! \throw InputError(invalid_mesh) when the mesh has no faces, or no element comes within a
//!        close-up's radius; InputError(invalid_option) as
//!        validate_render_options, or for RenderMode::colors on a mesh without vertex colours; DeviceError/SolverError from Embree.
RgbImage render_mesh(const TriMesh& mesh, const RenderOptions& options = {});

//! close_up.radius, or a tenth of the mesh's bounding box diagonal where that is 0.
double close_up_radius(const TriMesh& mesh, const CloseUp& close_up);

//! The faces of the elements (face_element_ids) with a vertex within close_up_radius of
//! close_up.point, each keeping its element id. \throw InputError(invalid_mesh) when there are none.
TriMesh close_up_elements(const TriMesh& mesh, const CloseUp& close_up);

}  // namespace meshquilt
