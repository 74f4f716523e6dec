#pragma once
//! Local surface patches and their conformal parameter planes (Section 3.1 of the mesh quilting
//! paper): a patch grows from a seed point over the base until it holds a disk of a given radius,
//! and is flattened by least-squares conformal maps (LSCM, Levy et al. 2002), one sparse solve.

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include <glm/vec2.hpp>

#include "mesh/tri_mesh.h"
#include "surface/surface_types.h"

namespace meshquilt {

class BaseLayout;

//! How a patch's plane was made.
enum class PatchChart {
  layout_window,  //!< a window of the shared layout (seamless_layout.h)
  field_aligned,  //!< the patch alone flattened along the field (field_aligned_chart.h)
  conformal,      //!< the patch alone flattened by LSCM, to be turned to the field at its seed
};

//! A patch of base faces with a parameter plane. Plane coordinates are in base units, the seed
//! point at the origin, orientation preserving (the base's outward normal is the plane's +z).
struct SurfacePatch {
  std::vector<int32_t> faces;     //!< base faces in the patch
  std::vector<int32_t> vertices;  //!< base vertices of those faces (patch vertex -> base vertex)
  std::vector<glm::dvec2> uv;     //!< #vertices plane coordinates
  double radius = 0.0;            //!< geodesic radius (along edges) it was grown to
  double area_distortion = 1.0;   //!< max over min over faces of plane area / base area
  int flipped_faces = 0;          //!< faces whose plane image is mirrored
  PatchChart chart = PatchChart::conformal;
  //! Where the seed lies in the chart the plane was cut from (for a layout window, the layout's
  //! coordinates on the seed face's side of its seams): the plane is that chart moved to put the
  //! seed at the origin.
  glm::dvec2 origin{0.0};

  //! Plane position of a surface point on a patch face. \pre face_index(p.face) >= 0
  glm::dvec2 to_plane(const SurfacePoint& p) const;
  //! The patch face holding a plane point, with barycentrics; std::nullopt outside the patch.
  std::optional<SurfacePoint> locate(const glm::dvec2& p) const;
  //! The patch face nearest to a plane point, barycentrics clamped to it (for points outside).
  SurfacePoint nearest(const glm::dvec2& p) const;
  //! Index of a base face in `faces`, or -1.
  int32_t face_index(int32_t base_face) const;
  //! Applies p -> rotation(angle) * p * scale to every plane coordinate and to `origin`.
  void transform(double angle, double scale);
  //! Builds the point-location grid; call after the last transform.
  void index();

  std::vector<int32_t> local_vertex_of_face_;  // #faces x 3, patch vertex indices
  std::vector<int32_t> sorted_faces_;          // (base face) sorted, with positions below
  std::vector<int32_t> sorted_positions_;
  glm::dvec2 grid_lo_{0.0};
  double grid_cell_ = 1.0;
  int grid_nx_ = 0, grid_ny_ = 0;
  std::vector<int32_t> grid_offsets_, grid_faces_;
};

//! Flattens a set of base faces by LSCM (Levy et al. 2002): one sparse least-squares solve with
//! two vertices pinned, orientation preserving, in arbitrary units (callers scale).
//! faces          base faces (zero-area ones add no equations)
//! corner_vertex  3 x #faces local vertex index of each corner
//! vertex_base    #local vertices, the base vertex of each
//! \throw SolverError when the system cannot be solved.
std::vector<glm::dvec2> conformal_flattening(const BaseSurface& base, const std::vector<int32_t>& faces,
                                             const std::vector<int32_t>& corner_vertex,
                                             const std::vector<int32_t>& vertex_base);

//! The faces reached along edges within `radius` of `seed` (a face joins when one of its
//! vertices does; the seed's face always), cut open where they are no disk.
std::vector<int32_t> ball_faces(const BaseSurface& base, const SurfacePoint& seed, double radius);

//! Grows a patch from `seed` over the faces reachable along edges within `radius` (a face joins
//! when one of its vertices does; distances start from the seed point) and flattens it by LSCM,
//! scaled so the plane area equals the base area, translated so the seed is the origin. Where
//! those faces are no disk (the ball wraps around a handle or covers a closed component), the
//! patch keeps the ones reached from the seed face across edges, nearest first, while they stay
//! a disk: it is cut open where its fronts meet. With `face_field` (#base faces, a tangent
//! direction each) and no layout the patch is flattened along the field (field_aligned_flattening,
//! in base units) wherever that chart does not fold. With a `layout` the patch is a window of it where
//! that unfolds without a cone or a fold, else flattened along its field (field_aligned_flattening,
//! in base units) where that does not fold; LSCM is the last resort. A layout window's
//! area_distortion is 1: its scale is the shared layout's, which no smaller window changes.
//! Without `layout_window` the layout's field is followed but no window is taken.
//! \throw SolverError when the LSCM system cannot be solved.
SurfacePatch grow_conformal_patch(const BaseSurface& base, const SurfacePoint& seed, double radius,
                                  const std::vector<Vec3>* face_field = nullptr,
                                  const BaseLayout* layout = nullptr, bool layout_window = true);

//! The patch grow_conformal_patch makes from a window of `layout`, without its fallbacks: nullopt
//! where the window folds.
std::optional<SurfacePatch> grow_layout_window(const BaseSurface& base, const SurfacePoint& seed, double radius,
                                               const BaseLayout& layout);

}  // namespace meshquilt
