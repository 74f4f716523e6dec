#pragma once
//! An edit as every front end runs it (the CLI and the Python module): regions from numbers, the
//! checks, the elements removed and the stats JSON of `edit --stats`.

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "edit/element_edit.h"
#include "mesh/tri_mesh.h"

namespace meshquilt {

//! A box from X0 Y0 Z0 X1 Y1 Z1. \throw InputError(invalid_option) "{remove_box}: ..." unless
//!        six numbers.
EditRegion box_region(const std::vector<double>& corners);

//! A sphere from X Y Z R. \throw InputError(invalid_option) "{remove_sphere}: ..." unless four
//!        numbers.
EditRegion sphere_region(const std::vector<double>& centre_radius);

//! "element" or "source". \throw InputError(invalid_option) "{color_by}: ..." otherwise.
ColorBy parse_color_by(const std::string& text);

//! Which elements go and which faces stay.
struct EditOutcome {
  std::vector<int32_t> removed;  //!< sorted element ids
  std::vector<uint8_t> keep;     //!< per face
  EditCounts counts;
};

//! Applies `request` to `mesh`'s elements (positions may be empty when no region is asked).
//! \throw InputError(invalid_option) naming `name` when the mesh lacks one element (and, if it
//!        has sources, one source) per face; see elements_to_remove for the request's own checks.
EditOutcome plan_edit(const TriMesh& mesh, const EditRequest& request, const std::string& name);

//! The figures of an edit, as `edit --stats` writes them (less the file names and seconds).
nlohmann::json edit_stats(const EditCounts& counts);

}  // namespace meshquilt
