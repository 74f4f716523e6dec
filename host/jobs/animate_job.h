#pragma once
//! An animation as every front end runs it (the CLI and the Python module): the result's checks,
//! the frames' checks, the elements that meet in some frame, and the stats JSON of
//! `animate --stats`.

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "mesh/tri_mesh.h"

namespace meshquilt {

//! \throw InputError(invalid_option) naming `name` unless `quilt` has one element per face and
//!        one origin (swatch vertex) per vertex.
void check_animated_quilt(const TriMesh& quilt, const std::string& name);

//! \throw InputError(invalid_option) naming `frame_name` unless a swatch frame of `vertices`
//!        vertices matches the swatch at rest (`rest_vertices`, named `rest_name`).
void check_swatch_frame(size_t vertices, size_t rest_vertices, const std::string& frame_name,
                        const std::string& rest_name);

//! Elements that meet another, or themselves, in some frame: the clean-up of synthesis over time.
struct MeetingElements {
  std::vector<int32_t> ids;      //!< every element of the result, sorted
  std::vector<int32_t> dropped;  //!< those that meet in some frame, sorted
  int face_pairs = 0;            //!< intersecting face pairs summed over the frames
};

//! Tests `frames` frames of `quilt` (its elements) moved to `positions_at(k)`.
MeetingElements meeting_elements(const TriMesh& quilt, size_t frames,
                                 const std::function<std::vector<Vec3>(size_t)>& positions_at);

//! The figures of an animation, as `animate --stats` writes them (less the file names, seconds
//! and the frames' own).
nlohmann::json animate_stats(size_t frames, const MeetingElements& meeting);

}  // namespace meshquilt
