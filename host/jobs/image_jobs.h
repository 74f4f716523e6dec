#pragma once
//! What `paint` and `relief` share between the front ends (the CLI and the Python module): the
//! sample's scale, a relief's sample taken from a model's detail, and the stats JSON of each.

#include <optional>

#include <nlohmann/json.hpp>

#include "device.h"
#include "mesh/tri_mesh.h"
#include "paint/colour_image.h"
#include "paint/detail_extraction.h"
#include "paint/surface_paint.h"
#include "paint/surface_relief.h"

namespace meshquilt {

//! \throw InputError(invalid_option) "{scale}: ..." unless pixels_per_unit > 0 or scale lies in
//!        (0, 10].
void check_sample_scale(double scale, double pixels_per_unit);

//! Sample pixels per base unit: `pixels_per_unit` when it is > 0, else the sample's
//! `sample_width` pixels over `scale` x the base's bounding-box diagonal.
//! \throw InputError(invalid_option) "{scale}: ..." for a scale outside (0, 10].
double sample_pixels_per_unit(const TriMesh& base, int sample_width, double scale, double pixels_per_unit);

//! A relief's sample made from a model's detail (its surface minus its smoothed self over a ball),
//! sized as an image sample is, and how it was made.
struct ModelSample {
  ColourImage image;
  double pixels_per_unit = 0.0;
  double height = 0.0;   //!< the detail's own height at that size (heights scale as widths do)
  nlohmann::json from;   //!< smoothing, region, detail_low, detail_high
};

//! See ModelSample. `model` prepared as a base; `region` empty: where its detail varies most.
ModelSample model_sample(const TriMesh& model, double smoothing, const std::optional<DetailRegion>& region,
                         int pixels, const TriMesh& base, double scale, double pixels_per_unit);

//! The figures of a paint, as `paint --stats` writes them (less the file names and seconds).
nlohmann::json paint_stats(const PaintResult& painted, const PaintOptions& options, const ColourImage& sample,
                           engine::Device& device);

//! The figures of a relief, as `relief --stats` writes them (less the file names and seconds).
nlohmann::json relief_stats(const ReliefResult& relief, const ReliefOptions& options, engine::Device& device);

}  // namespace meshquilt
