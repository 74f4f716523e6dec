#pragma once
//! How the surface driver's local coordinates (a base point and a height above it, base units)
//! become positions in space: the one interface behind which the output is embedded (Section 3.2
//! of the mesh quilting paper). The shell map (shell/shell_embedding.h) is the default; normal
//! displacement is the simple alternative.

#include <functional>
#include <memory>

#include "surface/surface_types.h"

namespace meshquilt {

class SurfaceEmbedding {
 public:
  virtual ~SurfaceEmbedding() = default;
  virtual Vec3 position(const SurfacePoint& point, double height) const = 0;
  //! Where collision checks during synthesis see the point. An embedding whose final form comes
  //! from float32 device work gives a stand-in computed on the host in double here, so that both
  //! back ends make the same decisions; the rest give position().
  virtual Vec3 position_during_synthesis(const SurfacePoint& point, double height) const {
    return position(point, height);
  }
  //! Whether position_during_synthesis differs from position.
  virtual bool has_synthesis_map() const { return false; }
};

//! Displacement along interpolated vertex normals (Figure 8, left).
class NormalEmbedding final : public SurfaceEmbedding {
 public:
  explicit NormalEmbedding(const BaseSurface& base) : base_(base) {}
  Vec3 position(const SurfacePoint& point, double height) const override {
    return base_.position(point) + height * base_.normal(point);
  }

 private:
  const BaseSurface& base_;
};

//! Makes the embedding once the shell height (base units) is known, before synthesis, so that
//! collision checks see the geometry where it will end up. The embedding may keep a reference to
//! `base`, which lives until synthesis ends.
using EmbeddingFactory =
    std::function<std::unique_ptr<SurfaceEmbedding>(const BaseSurface& base, double shell_height)>;

}  // namespace meshquilt
