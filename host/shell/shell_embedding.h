#pragma once
//! The shell embedding (Section 3.2 of the mesh quilting paper): atlas, shell, stretch-minimized
//! shell map, behind the surface driver's embedding interface. Also re-embedding: the same
//! texture space over an edited base with the same connectivity.

#include <memory>

#include "device.h"
#include "surface/surface_embedding.h"
#include "shell/shell_map.h"
#include "shell/stretch_minimization.h"

namespace meshquilt {

struct ShellEmbeddingOptions {
  bool minimize_stretch = true;  //!< false: the original shell map
  StretchOptions stretch;
  AtlasOptions atlas;
  ShellOptions shell;
};

//! What building a shell embedding measured.
struct ShellReport {
  double stretch_initial = 1.0;  //!< normalized L2 stretch of the original shell map
  double stretch_final = 1.0;    //!< after minimization (= initial without it)
  size_t tets = 0;
  int charts = 0;
  int reduced_vertices = 0;  //!< base vertices whose offset height was lowered
  int invalid_prisms = 0;
  int offset_intersections = 0;
  double seconds_atlas = 0.0, seconds_shell = 0.0, seconds_stretch = 0.0;
};

//! The texture space of a shell map: all that re-embedding over an edited base needs.
struct ShellTexture {
  TextureAtlas atlas;
  std::vector<glm::dvec2> top_uv;  //!< #A
  double height = 0.0;             //!< shell height, base units
};

class ShellEmbedding final : public SurfaceEmbedding {
 public:
  //! Maps `texture` onto `shell`, the shell of `base` at texture.height (build_shell); for
  //! re-embedding, a base edited from the one the texture was made over (same connectivity).
  ShellEmbedding(const BaseSurface& base, ShellTexture texture, Shell shell);
  ShellEmbedding(const ShellEmbedding&) = delete;
  ShellEmbedding& operator=(const ShellEmbedding&) = delete;

  Vec3 position(const SurfacePoint& point, double height) const override {
    return map_.to_shell(point, height);
  }
  //! The original shell map (top corners over their base corners): exact on the host, and near
  //! the minimized one, which the device computes in float32.
  Vec3 position_during_synthesis(const SurfacePoint& point, double height) const override {
    return original_.to_shell(point, height);
  }
  bool has_synthesis_map() const override { return texture_.top_uv != texture_.atlas.uv; }
  const ShellMap& map() const { return map_; }
  const ShellTexture& texture() const { return texture_; }

 private:
  ShellTexture texture_;
  Shell shell_;
  ShellMap map_;
  ShellMap original_;
};

//! Atlas, shell and (unless turned off) stretch minimization for `base` at `height`.
//! \throw SolverError from the atlas; DeviceError from the kernel.
std::unique_ptr<ShellEmbedding> build_shell_embedding(engine::Device& device, const BaseSurface& base,
                                                      double height,
                                                      const ShellEmbeddingOptions& options = {},
                                                      ShellReport* report = nullptr);

}  // namespace meshquilt
