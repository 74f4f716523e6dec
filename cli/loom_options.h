#pragma once
//! The options of `meshquilt loom`, registered in one place: the command parses its command line
//! with them and `batch` parses a manifest job's option list with a fresh CLI::App and the same
//! function, as it does synth's (synth_options.h).

#include <cstdint>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace meshquilt::cli {

//! Values of loom's options as parsed; defaults are loom's defaults.
struct LoomArgs {
  std::string design, output, stats, picture, method = "structured", progress = "auto";
  std::string weaves, warp_colors, weft_colors, base;
  double scale = 0.8;
  std::vector<std::string> exemplars;
  uint64_t seed = 1;
  int stations = 8, sides = 8;
  bool assignment_only = false, periodic = false;
};

//! Registers every option of loom on `cmd`, writing into `args` (which must outlive parsing).
void add_loom_options(CLI::App* cmd, LoomArgs& args);

//! Files a loom job reads and writes, as given on its command line (the output first).
std::vector<std::string> loom_input_files(const LoomArgs& args);
std::vector<std::string> loom_output_files(const LoomArgs& args);

}  // namespace meshquilt::cli
