#pragma once
//! One field-aligned layout of the whole base, shared by every surface patch: a seamless
//! parameterization whose gradients follow an n-direction field (u along it, v along normal x
//! it, lengths in base units as far as the field allows). The base is cut open through the
//! field's cones (and around handles); across a cut the layout continues by a rotation through a
//! multiple of 2 pi / n plus a translation, so a patch is a window of it unfolded across cuts and
//! two overlapping windows differ by such a rotation and translation alone. Where the texture
//! repeats on a lattice, every seam's translation is rounded to one of its periods, so that the
//! pattern placed by patches on either side of a seam, or all round a cone, lines up.

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include <glm/vec2.hpp>

#include "surface/direction_field.h"

namespace meshquilt {

struct SeamlessLayout {
  int symmetry = 1;                          //!< n of the field it follows
  std::vector<Vec3> axis;                    //!< #F, the layout's u direction on each face (the field, combed)
  std::vector<std::array<int8_t, 3>> turn;   //!< #F x 3: across edge k (t[k], t[k+1]) of f, the
                                             //!< neighbour's axis is f's carried over, turned by
                                             //!< turn x 2 pi / n (0 on an edge that is not cut)
  std::vector<std::array<uint8_t, 3>> cut;   //!< #F x 3: edge k of f is a seam of the layout
  std::vector<int32_t> corner_wedge;         //!< #F x 3: the layout vertex of each face corner
  std::vector<glm::dvec2> uv;                //!< #layout vertices, base units
  std::vector<int32_t> cones;                //!< vertices where the field has a nonzero index
  std::vector<int> cone_indices;             //!< each cone's index, in units of 1 / symmetry
  int flipped_faces = 0;                     //!< faces mirrored in the layout (near cones)
  bool on_lattice = false;                   //!< seams continue by periods of a lattice
};

//! The default size hold: the layout conformal but for a faint pull that fixes its scale.
inline constexpr double kDefaultSizeHold = 0.1;

//! Combs the field over a spanning tree of faces, cuts the base along the edges off that tree
//! that do not end in a dangling branch (which keeps the cones and the handles cut), and solves
//! min sum_f a_f (|grad u - axis_f|^2 + |grad v - normal_f x axis_f|^2) over the cut-open base with
//! the seams' transitions as constraints (a stiff penalty: one sparse solve).
//! lattice: the texture's periods in layout units (base units as the layout's median scale
//! holds them), with a point it turns about at the layout's origin; the seams' translations are
//! rounded to its periods and the layout solved again with them held; its median scale is then
//! taken over faces weighted by the geometric mean of base and layout area (else by base area),
//! so that the median element, not the median face, has the asked size.
//! size_hold: the weight, per unit of face area, holding the layout's scale to its unit in the
//! field's frame, against the conformal terms' 1: small keeps the layout conformal (round
//! elements whose size follows the base's curvature), large evens the size and lets elements
//! stretch (kDefaultSizeHold: conformal).
//! element_scale: elements on the layout come out this many times the size its median holds
//! (the layout shrunk by it before its seams are rounded).
//! \throw SolverError when the solve fails.
SeamlessLayout seamless_layout(const BaseSurface& base, const DirectionField& field,
                               const std::optional<std::array<glm::dvec2, 2>>& lattice = std::nullopt,
                               double size_hold = kDefaultSizeHold, double element_scale = 1.0);

//! A set of base faces laid out from the layout, unfolded from `start` across cuts.
struct LayoutWindow {
  std::vector<glm::dvec2> corner_uv;  //!< 3 x #faces, the plane position of each face corner
  std::vector<int> face_turn;         //!< #faces: the window's x axis on each face is its layout axis
                               //!< turned by face_turn x 2 pi / n
  bool consistent = true;             //!< false where a vertex unfolds to two places (the window
                                      //!< holds a cone or wraps round a handle)
};

//! Unfolds the layout over `faces` (a face-connected set holding `start`): the start face keeps
//! its layout coordinates, every other face is carried over by the transitions of the cut edges
//! crossed on the way to it.
//! corner_vertex  3 x #faces local vertex index of each corner; vertices: the number of them
LayoutWindow unfold_window(const BaseSurface& base, const SeamlessLayout& layout, const std::vector<int32_t>& faces,
                           int32_t start, const std::vector<int32_t>& corner_vertex, int32_t vertices);

//! p turned through quarter_turns x 90 degrees, exactly.
glm::dvec2 quarter_turned(const glm::dvec2& p, int quarter_turns);

}  // namespace meshquilt
