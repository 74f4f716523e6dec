#include "repair_report.h"
#include "image_synthesis_inputs.h"

#include <cstdio>
#include <iostream>

#include "atomic_file.h"
#include "core/error.h"
#include "exit_codes.h"
#include "jobs/image_jobs.h"
#include "mesh/base_mesh.h"
#include "mesh/mesh_io.h"

namespace meshquilt::cli {

ImageSynthesisInputs read_image_synthesis_inputs(const std::string& base, const std::string& image,
                                                 const std::string& field, double scale, double pixels_per_unit,
                                                 int sample_width, const std::string& output,
                                                 const std::string& stats) {
  check_sample_scale(scale, pixels_per_unit);
  check_mesh_output(output);
  check_writable(output);
  if (!stats.empty()) check_writable(stats);
  ImageSynthesisInputs in;
  MeshRepairs repairs;
  in.base = prepare_base(read_mesh(base), base, &repairs);
  say_repairs(base, repairs, "parts");
  if (!image.empty()) in.sample = read_colour_image(image);
  if (!image.empty() && sample_width > 0) in.sample = shrunk_to_width(in.sample, sample_width);
  if (!field.empty()) in.constraints = read_field_file(field, in.base);
  // A model's detail (relief --from) is sized when it is made.
  if (!image.empty()) in.pixels_per_unit = sample_pixels_per_unit(in.base, in.sample.width, scale, pixels_per_unit);
  return in;
}

void write_field_lines(const std::string& file, const std::vector<Vec3>& directions) {
  std::string lines;
  char line[96];
  for (const Vec3& d : directions) {
    std::snprintf(line, sizeof line, "%.9g %.9g %.9g\n", d.x, d.y, d.z);
    lines += line;
  }
  write_text_atomic(file, lines);
}

std::unique_ptr<engine::Device> open_synthesis_device(const std::string& backend) {
  std::string note;
  std::unique_ptr<engine::Device> device = engine::open_device(engine::parse_backend_choice(backend), &note);
  if (!note.empty()) std::cerr << "meshquilt: " << with_options(note) << "\n";
  return device;
}

std::function<void(size_t, size_t)> paint_progress(ProgressReporter& reporter) {
  return [&reporter, next = size_t{0}](size_t done, size_t total) mutable {
    if (done < next && done < total) return;
    next = done + total / 200;
    reporter.update(static_cast<double>(done), static_cast<double>(total));
  };
}

}  // namespace meshquilt::cli
