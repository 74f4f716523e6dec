#pragma once
//! Whether a mesh will quilt well as a swatch (`meshquilt swatch check`): closed elements that
//! do not pass through each other, laid out in x-y with their thickness along z, none cut open
//! by the swatch's border.

#include <cstdint>
#include <string>
#include <vector>

#include "mesh/mesh_repair.h"
#include "mesh/topology.h"
#include "mesh/tri_mesh.h"

namespace meshquilt {

struct SwatchCheckOptions {
  double weld_tolerance = kWeldTolerance;  //!< relative to the bbox diagonal, as inspect welds
  //! Largest z extent over the shorter x-y side of a swatch that counts as thin along z; our own
  //! swatches stay below 0.4.
  double max_thickness_ratio = 0.5;
};

struct SwatchCheck {
  int32_t elements = 0;                 //!< vertex-connected components after welding
  int32_t open_elements = 0;            //!< not closed 2-manifolds
  int32_t cut_elements = 0;             //!< open elements whose rim lies on the x-y hull (mesh/border_cut.h)
  int64_t intersecting_face_pairs = 0;  //!< face pairs of different elements that meet
  int64_t intersecting_element_pairs = 0;
  Vec3 extent{0.0};                     //!< bounding-box sides
  double thickness_ratio = 0.0;         //!< z extent / the shorter x-y side
  bool thin_along_z = true;             //!< z is the thinnest axis and thickness_ratio is small enough

  MeshRepairs repairs;  //!< what reading it as synth does repaired (mesh/mesh_repair.h)
  TriMesh repaired;     //!< the swatch after those repairs, in its own frame

  //! One line per problem found (no file name), in the order open, cut, intersecting, thickness;
  //! empty when the swatch will quilt well.
  std::vector<std::string> findings;
};

//! Checks `swatch` as synth reads it (repaired by repair_mesh, the repairs counted) with the element
//! topology and intersection tests of `meshquilt inspect`; `source` names it in messages.
//! \throw InputError(invalid_mesh) for repair_mesh's refusals; DeviceError/SolverError from the BVH.
SwatchCheck check_swatch(const TriMesh& swatch, const std::string& source, const SwatchCheckOptions& options = {});

}  // namespace meshquilt
