#pragma once
//! Distinct colours for element ids, the same for the same id on every run.

#include <cstdint>
#include <vector>

#include "mesh/tri_mesh.h"

namespace meshquilt {

//! The colour of element `id` as linear RGB in [0, 1]^3: hues step by the golden ratio
//! (0.618... of a turn per id, so consecutive ids and any short run of ids stay far apart on the
//! colour wheel), and saturation and value cycle through three levels, so ids whose hues come
//! close again (id and id + 21, id + 55, ...) still differ in lightness.
//! Saturated but not dark: value in [0.80, 0.95], saturation in [0.45, 0.70]. A negative id
//! is coloured as its 32-bit unsigned wrap.
Vec3 element_color(int32_t id);

//! #F element id per face: mesh.elements when present, else the vertex-connected components
//! (face_components), so unlabelled meshes colour each connected piece on its own.
std::vector<int32_t> face_element_ids(const TriMesh& mesh);

}  // namespace meshquilt
