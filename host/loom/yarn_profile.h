#pragma once
//! The yarns of a registered exemplar sampled along their run: at each station the centreline
//! (off the yarn's nominal line, and up) and the cross-section's radius at evenly spaced angles.
//! Profiles are what blocks copy: yarns from exemplars of any tessellation (tube sides, samples
//! along the yarn) meet in one tube.

#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "loom/exemplar_weave.h"
#include "mesh/tri_mesh.h"

namespace meshquilt {

//! One yarn: stations at start + s step along its run (y for a warp, x for a weft).
struct YarnProfile {
  std::vector<glm::dvec2> centre;  //!< per station: (sideways from the nominal line, z)
  std::vector<double> radius;      //!< stations x sides: distance from the centre at angle 2 pi k / sides
};

//! An exemplar's yarns sampled `per_pitch` stations a pitch from half a pitch before its first
//! crossing to half a pitch past its last: warp i's station s lies at y = origin.y + (s /
//! per_pitch - 1/2) pitch.y. Angles turn from sideways (+x for warps, +y for wefts) toward +z.
struct ExemplarProfiles {
  ExemplarWeave weave;
  int per_pitch = 0, sides = 0;
  std::vector<YarnProfile> warps, wefts;
};

//! Samples `mesh`, registered as `weave`, in its registered frame. Stations or angles no vertex
//! falls near take their neighbours' values.
//! \throw InputError(invalid_mesh) naming `name` and the yarn when it has no vertex along its run.
ExemplarProfiles profile_exemplar(const TriMesh& mesh, const ExemplarWeave& weave, int per_pitch, int sides,
                                  const std::string& name);

}  // namespace meshquilt
