#pragma once
//! The texture atlas of a base mesh (Section 3.2 of the mesh quilting paper, Figure 6): the base
//! cut into charts, each a topological disk flattened by a conformal map, in base units. The
//! geometry texture space is every chart's plane times a height axis w.
//!
//! Charts grow from seed faces in order of distance, adding a face only where the chart stays a
//! disk (it shares one edge with the chart and its third vertex is new, or it fills a notch of two
//! edges), while the face's normal stays within a cone around the seed's. Each chart is
//! flattened by LSCM (the solver of the synthesis patches) and scaled to its base area; a chart
//! that folds or whose area distortion exceeds the limit is regrown with a narrower cone. LSCM is
//! conformal, so the texture-to-base map starts out nearly a similarity, which is what the shell
//! map's stretch is measured against, and large charts leave few fixed (lateral) boundaries.

#include <cstdint>
#include <glm/vec2.hpp>
#include <vector>

#include "surface/surface_types.h"

namespace meshquilt {

struct AtlasOptions {
  double max_normal_angle = 1.2;     //!< radians between a chart face's normal and its seed's
  double max_area_distortion = 2.5;  //!< max over min of plane area / base area in one chart
  int32_t max_chart_faces = 20000;   //!< keeps each LSCM solve small
};

struct TextureAtlas {
  int32_t charts = 0;
  std::vector<int32_t> face_chart;              //!< #F chart of each base face
  std::vector<std::array<int32_t, 3>> corners;  //!< #F atlas vertex of each face corner
  std::vector<int32_t> vertex_base;             //!< #A base vertex of each atlas vertex
  std::vector<int32_t> vertex_chart;            //!< #A its chart
  std::vector<glm::dvec2> uv;                   //!< #A chart-plane position, base units
  std::vector<uint8_t> on_boundary;             //!< #A on its chart's boundary or the base's

  //! Texture-plane position of a surface point.
  glm::dvec2 to_texture(const SurfacePoint& p) const;
};

//! Cuts `base` into charts and flattens them. Deterministic.
//! \throw SolverError when a chart's conformal map cannot be solved.
TextureAtlas build_texture_atlas(const BaseSurface& base, const AtlasOptions& options = {});

}  // namespace meshquilt
