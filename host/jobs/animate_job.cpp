#include "jobs/animate_job.h"

#include <algorithm>

#include "core/error.h"
#include "mesh/topology.h"
#include "quilt/broken_elements.h"

namespace meshquilt {

void check_animated_quilt(const TriMesh& quilt, const std::string& name) {
  if (quilt.origins.empty())
    throw InputError(name + ": no vertex property `origin` (write it with synth {provenance})",
                     ErrorKind::invalid_option);
  if (quilt.elements.size() != quilt.num_faces() || quilt.origins.size() != quilt.num_vertices())
    throw InputError(name + ": element needs one entry per face and origin one per vertex",
                     ErrorKind::invalid_option);
}

void check_swatch_frame(size_t vertices, size_t rest_vertices, const std::string& frame_name,
                        const std::string& rest_name) {
  if (vertices != rest_vertices)
    throw InputError(frame_name + ": " + std::to_string(vertices) + " vertices, not the swatch's " +
                         std::to_string(rest_vertices) + " (" + rest_name + ")",
                     ErrorKind::invalid_option);
}

MeetingElements meeting_elements(const TriMesh& quilt, size_t frames,
                                 const std::function<std::vector<Vec3>(size_t)>& positions_at) {
  MeetingElements meeting;
  meeting.ids.assign(quilt.elements.begin(), quilt.elements.end());
  std::sort(meeting.ids.begin(), meeting.ids.end());
  meeting.ids.erase(std::unique(meeting.ids.begin(), meeting.ids.end()), meeting.ids.end());
  std::vector<uint8_t> alive(meeting.ids.size(), 1);
  TriMesh at = quilt;
  for (size_t k = 0; k < frames; ++k) {
    at.positions = positions_at(k);
    const std::vector<TriMesh> parts = split_elements(at);
    std::vector<const TriMesh*> pointers;
    for (const TriMesh& part : parts) pointers.push_back(&part);
    meeting.face_pairs += remove_broken_elements(pointers, false, true, alive).intersecting_face_pairs;
  }
  for (size_t i = 0; i < meeting.ids.size(); ++i)
    if (!alive[i]) meeting.dropped.push_back(meeting.ids[i]);
  return meeting;
}

nlohmann::json animate_stats(size_t frames, const MeetingElements& meeting) {
  return {{"frames", frames},
          {"elements", meeting.ids.size()},
          {"dropped_meeting", meeting.dropped.size()},
          {"meeting_face_pairs", meeting.face_pairs}};
}

}  // namespace meshquilt
