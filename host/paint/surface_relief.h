#pragma once
//! Relief from an image over a surface: a height signal synthesized as paint synthesizes colour
//! (the sample's luma, 0 black to 1 white), then the refined base displaced by height x signal
//! (each vertex's signal averaged half and half with its neighbours', so that a zigzag between
//! patches a pixel apart does not stand as teeth) along the base's smooth normals (its vertex
//! normals interpolated over each face). Heights are clamped where the displaced surface would
//! pass through itself: each to a share of the room along its normal (the distance to the
//! surface met by a ray along it) and of the radius of curvature where the surface is concave
//! (neighbouring normals converge there); then a face turned over at a steep step has its
//! highest corner brought down, and where faces still cross their vertices' heights are halved
//! until none do (or, where the base itself crosses, until they reach it). Connectivity is the
//! base's refined one, so a closed base stays closed.

#include <vector>

#include "paint/surface_paint.h"

namespace meshquilt {

struct ReliefOptions {
  PaintOptions paint;      //!< the synthesis of the height signal
  double height = 0.0;     //!< the displacement of white, base units (> 0)
  double clearance = 0.4;  //!< share of the room along a normal a height may take, in (0, 1)
};

struct ReliefResult {
  TriMesh mesh;                 //!< the base refined and displaced, vertex colours the signal in grey
  std::vector<double> heights;  //!< #V displacement of each vertex along its normal, after clamping
  std::vector<Vec3> directions; //!< #V the field the signal was synthesized along
  int clamped = 0;              //!< vertices whose height was lowered to their room
  int lowered_crossing = 0;     //!< vertices lowered further where raised faces crossed or turned over
  size_t crossing_left = 0;     //!< face pairs crossing at the end: where the base passes through itself
  int levels = 0;               //!< 1-to-4 splits of the base
};

//! \throw InputError(invalid_option) for a height that is not positive and finite or a clearance
//!        outside (0, 1); what paint_surface throws.
ReliefResult relief_surface(const TriMesh& base, const ColourImage& sample,
                            const std::vector<FieldConstraint>& constraints, const ReliefOptions& options,
                            engine::Device& device);

}  // namespace meshquilt
