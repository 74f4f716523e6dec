#include "jobs/image_jobs.h"

#include <algorithm>
#include <string>

#include <glm/geometric.hpp>

#include "core/error.h"
#include "mesh/measures.h"

namespace meshquilt {

void check_sample_scale(double scale, double pixels_per_unit) {
  if (!(pixels_per_unit > 0.0) && !(scale > 0.0 && scale <= 10.0))
    throw InputError("{scale}: expected a value in (0, 10], got " + std::to_string(scale), ErrorKind::invalid_option);
}

double sample_pixels_per_unit(const TriMesh& base, int sample_width, double scale, double pixels_per_unit) {
  check_sample_scale(scale, pixels_per_unit);
  if (pixels_per_unit > 0.0) return pixels_per_unit;
  return sample_width / (scale * glm::length(bounding_box(base.positions).extent()));
}

ModelSample model_sample(const TriMesh& model, double smoothing, const std::optional<DetailRegion>& region,
                         int pixels, const TriMesh& base, double scale, double pixels_per_unit) {
  const DetailSample detail = detail_sample(model, smoothing, region, pixels);
  ModelSample out;
  out.image = detail.detail.image;
  out.pixels_per_unit = sample_pixels_per_unit(base, out.image.width, scale, pixels_per_unit);
  out.height = detail.detail.height_over(out.pixels_per_unit);
  out.from = {{"smoothing", detail.smoothing},
              {"region", {detail.centre.x, detail.centre.y, detail.centre.z, detail.radius}},
              {"detail_low", detail.detail.low},
              {"detail_high", detail.detail.high}};
  return out;
}

nlohmann::json paint_stats(const PaintResult& painted, const PaintOptions& options, const ColourImage& sample,
                           engine::Device& device) {
  return {{"sample", {sample.width, sample.height}},
          {"pixels_per_unit", options.pixels_per_unit},
          {"levels", painted.levels},
          {"sample_levels", painted.sample_levels},
          {"vertices", painted.mesh.num_vertices()},
          {"faces", painted.mesh.num_faces()},
          {"mean_cost", painted.mean_cost},
          {"visits", painted.visits},
          {"batches", painted.batches},
          {"neighbours", painted.neighbours},
          {"backend", engine::backend_name(device.backend())},
          {"device", device.name()}};
}

nlohmann::json relief_stats(const ReliefResult& relief, const ReliefOptions& options, engine::Device& device) {
  double highest = 0.0;
  for (double h : relief.heights) highest = std::max(highest, h);
  return {{"pixels_per_unit", options.paint.pixels_per_unit},
          {"levels", relief.levels},
          {"vertices", relief.mesh.num_vertices()},
          {"faces", relief.mesh.num_faces()},
          {"height", options.height},
          {"highest", highest},
          {"clamped_vertices", relief.clamped},
          {"crossing_lowered_vertices", relief.lowered_crossing},
          {"crossing_face_pairs_left", relief.crossing_left},
          {"backend", engine::backend_name(device.backend())},
          {"device", device.name()}};
}

}  // namespace meshquilt
