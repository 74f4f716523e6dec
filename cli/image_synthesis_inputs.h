#pragma once
// What `paint` and `relief` read (the base, the image sample, the field and the sample's scale),
// and the field they write back with --write-field.

#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "device.h"
#include "mesh/tri_mesh.h"
#include "paint/colour_image.h"
#include "progress.h"
#include "surface/guidance_field.h"

namespace meshquilt::cli {

struct ImageSynthesisInputs {
  TriMesh base;                            //!< prepared as synth prepares a base
  ColourImage sample;
  std::vector<FieldConstraint> constraints;  //!< from the field file; empty: the default field
  double pixels_per_unit = 0.0;            //!< sample pixels per base unit (0 without an image)
};

//! Checks the output and stats paths, then reads the inputs (the sample left empty when `image`
//! is), the sample shrunk to sample_width pixels across (its aspect kept) when that is > 0.
//! pixels_per_unit > 0 is taken as given; otherwise --scale S makes the sample's width S x the
//! base's bounding-box diagonal (jobs/image_jobs.h).
//! \throw InputError for a scale outside (0, 10] or a sample width past the image's; what the
//!        readers throw.
ImageSynthesisInputs read_image_synthesis_inputs(const std::string& base, const std::string& image,
                                                 const std::string& field, double scale, double pixels_per_unit,
                                                 int sample_width, const std::string& output,
                                                 const std::string& stats);

//! The device of --backend (auto|vulkan|cpu) that scores neighbourhoods; why `auto` chose the
//! CPU, if it says, goes to stderr.
//! \throw InputError for another value; DeviceError when `vulkan` has no device.
std::unique_ptr<engine::Device> open_synthesis_device(const std::string& backend);

//! PaintOptions::progress for `reporter`: a line per half percent at most, not one per batch.
std::function<void(size_t, size_t)> paint_progress(ProgressReporter& reporter);

//! Writes one "x y z" line per direction (the field at each output vertex), atomically.
void write_field_lines(const std::string& file, const std::vector<Vec3>& directions);

}  // namespace meshquilt::cli
