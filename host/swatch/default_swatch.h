#pragma once
//! The swatch `meshquilt synth` (and the Python module) uses when none is given, so the main job needs no files.

#include "mesh/tri_mesh.h"

namespace meshquilt {

//! A 4-in-1 chain mail of 4 x 4 rings (3,072 faces), generated in memory.
TriMesh default_swatch();

}  // namespace meshquilt
