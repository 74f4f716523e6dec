#include "jobs/edit_job.h"

#include "core/error.h"

namespace meshquilt {

EditRegion box_region(const std::vector<double>& corners) {
  if (corners.size() != 6)
    throw InputError("{remove_box}: expected X0 Y0 Z0 X1 Y1 Z1, got " + std::to_string(corners.size()) + " numbers",
                     ErrorKind::invalid_option);
  EditRegion box;
  box.lo = Vec3(corners[0], corners[1], corners[2]);
  box.hi = Vec3(corners[3], corners[4], corners[5]);
  return box;
}

EditRegion sphere_region(const std::vector<double>& centre_radius) {
  if (centre_radius.size() != 4)
    throw InputError("{remove_sphere}: expected X Y Z R, got " + std::to_string(centre_radius.size()) + " numbers",
                     ErrorKind::invalid_option);
  EditRegion sphere;
  sphere.kind = EditRegion::Kind::sphere;
  sphere.centre = Vec3(centre_radius[0], centre_radius[1], centre_radius[2]);
  sphere.radius = centre_radius[3];
  return sphere;
}

ColorBy parse_color_by(const std::string& text) {
  if (text == "element") return ColorBy::element;
  if (text == "source") return ColorBy::source;
  throw InputError("{color_by}: expected element or source, got '" + text + "'", ErrorKind::invalid_option);
}

EditOutcome plan_edit(const TriMesh& mesh, const EditRequest& request, const std::string& name) {
  if (mesh.elements.size() != mesh.num_faces() || (!mesh.sources.empty() && mesh.sources.size() != mesh.num_faces()))
    throw InputError(name + ": element and source need one entry per face", ErrorKind::invalid_option);
  EditOutcome outcome;
  outcome.removed =
      elements_to_remove({mesh.elements, mesh.sources, mesh.positions, mesh.triangles}, request, outcome.counts);
  outcome.keep = faces_kept(mesh.elements, outcome.removed);
  return outcome;
}

nlohmann::json edit_stats(const EditCounts& counts) {
  return {{"elements", counts.elements},
          {"kept", counts.kept},
          {"removed", counts.elements - counts.kept},
          {"removed_by_id", counts.by_id},
          {"removed_by_source", counts.by_source},
          {"removed_by_keep_source", counts.by_keep_source},
          {"removed_inside", counts.inside},
          {"removed_aged", counts.aged}};
}

}  // namespace meshquilt
