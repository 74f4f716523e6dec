#pragma once
//! Stretch minimization of the shell map (Section 3.2 of the mesh quilting paper): random line
//! searches (Sander et al. 2001) over the texture-plane positions of the top corners, lateral
//! chart boundaries and the base's boundary fixed, on the `stretch_linesearch` compute kernel.
//! Vertices that share no base face are independent; a greedy colouring of the base's vertex
//! graph gives batches searched in one dispatch each.

#include <cstdint>
#include <glm/vec2.hpp>
#include <vector>

#include "device.h"
#include "shell/shell.h"
#include "shell/texture_atlas.h"

namespace meshquilt {

struct StretchOptions {
  int sweeps = 20;    //!< every movable vertex searched once per sweep
  uint64_t seed = 1;  //!< random search directions
};

//! The top corners' texture positions after minimization (#A; boundary ones keep atlas.uv).
//! Same inputs and seed give the same result on a back end; Vulkan and CPU agree to float32
//! rounding. \throw DeviceError when the device fails.
std::vector<glm::dvec2> minimize_stretch(engine::Device& device, const BaseSurface& base,
                                         const TextureAtlas& atlas, const Shell& shell,
                                         const StretchOptions& options = {});

//! Greedy colouring of the movable atlas vertices: no two vertices of one colour share a face.
std::vector<std::vector<uint32_t>> independent_batches(const BaseSurface& base, const TextureAtlas& atlas);

}  // namespace meshquilt
