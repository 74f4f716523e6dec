#pragma once
//! The options of `meshquilt paint` and `meshquilt relief`, registered in one place each: the
//! commands parse their command lines with them and `batch` parses a manifest job's option list
//! with a fresh CLI::App and the same function, as it does synth's (synth_options.h).

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "paint/surface_paint.h"
#include "paint/surface_relief.h"

namespace meshquilt::cli {

//! Values of paint's options as parsed; defaults are paint's defaults.
struct PaintArgs {
  std::string base, image, output, field, stats, write_field, backend = "auto", progress = "auto";
  double scale = 0.25;
  double pixels_per_unit = 0.0;
  int sample_width = 0;  //!< 0: the image as it is
  int atlas = 0;         //!< 0: vertex colours; N: an N x N texture
  PaintOptions options;
};

//! Values of relief's options as parsed; defaults are relief's defaults.
struct ReliefArgs {
  std::string base, image, output, field, stats, write_sample, write_field, backend = "auto", progress = "auto";
  double scale = 0.25;
  double pixels_per_unit = 0.0;
  int sample_width = 0;  //!< 0: the image as it is
  ReliefOptions options;
  // --from: the model whose detail is the sample.
  std::string model;
  std::vector<double> region;  //!< x, y, z, radius in model units
  double smoothing = 0.0;      //!< model units; 0: 0.01 of its bounding-box diagonal
  int pixels = 32;
};

//! Registers every option of paint on `cmd`, writing into `args` (which must outlive parsing).
void add_paint_options(CLI::App* cmd, PaintArgs& args);

//! Registers every option of relief on `cmd`; whether `--height` was given is
//! `cmd->get_option("--height")->count()`.
void add_relief_options(CLI::App* cmd, ReliefArgs& args);

//! Files a paint or relief job reads and writes, as given on its command line (empty entries
//! left out; the output mesh first among the outputs).
std::vector<std::string> paint_input_files(const PaintArgs& args);
std::vector<std::string> paint_output_files(const PaintArgs& args);
std::vector<std::string> relief_input_files(const ReliefArgs& args);
std::vector<std::string> relief_output_files(const ReliefArgs& args);

}  // namespace meshquilt::cli
