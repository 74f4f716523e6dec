#pragma once
//! The options of `meshquilt synth`, registered in one place: `synth` parses its command line
//! with them and `batch` parses each manifest job's option list with a fresh CLI::App and the same
//! function, so an option added here works in manifests too.

#include <cstdint>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace meshquilt::cli {

//! Values of synth's options as parsed; defaults are synth's defaults.
struct SynthArgs {
  std::string swatch;               //!< swatch mesh; empty: the built-in chain mail
  std::string plane = "4x4";        //!< WxH in swatch extents
  uint64_t seed = 1;                //!< seed of every random choice
  std::string backend = "auto";     //!< auto|vulkan|cpu
  std::string stats;                //!< statistics JSON; empty: none
  std::string progress = "auto";    //!< auto|json|none
  std::string output = "quilt.ply"; //!< output mesh
  int cells = 16;                   //!< grid cells along the swatch's shorter side
  int max_patches = 0;              //!< stop after this many patches (0: fill the plane)
  bool cleanup = true;              //!< remove elements that could not be made whole
  double fill_margin = 0.5;         //!< QuiltOptions::fill_margin
  bool provenance = false;          //!< write each vertex's swatch vertex (PLY `origin`, glTF `_ORIGIN`)
  std::string base;                 //!< base mesh; empty: a plane (--plane)
  double scale = 0.1;               //!< swatch's longer side / base's bounding-box diagonal
  std::string field;                //!< guidance field file (JSON); empty: the default field
  bool shared_layout = true;        //!< patches are windows of one layout of the base
  int symmetry = 0;                 //!< n of the layout's field; 0: the swatch's symmetry
  double size_hold = 0.1;           //!< SynthRequest::size_hold
  double cone_spread = 1.5625;      //!< SynthRequest::cone_spread
  double shell_height = 0.0;        //!< layer height in base units; 0: the swatch's thickness at scale
  std::string write_field;          //!< write the field used as OBJ line segments
  std::string preview;              //!< write a PNG preview of the result
  std::string embed = "shell";      //!< with --base: shell|normal
  bool distortion_min = true;       //!< with --embed shell: minimize the shell map's stretch
  std::string write_texture;        //!< with --base: write the result in texture space
};

//! Registers every option of synth on `cmd`, writing into `args` (which must outlive parsing).
//! `--max-memory` sets the process-wide memory budget when it is parsed.
//! A new option is one more add_option line here; a new file option also goes into
//! synth_input_files or synth_output_files, which batch uses for its completion records.
void add_synth_options(CLI::App* cmd, SynthArgs& args);

//! Files a job reads, as given on its command line (empty entries left out).
std::vector<std::string> synth_input_files(const SynthArgs& args);

//! Files a job writes, as given on its command line (the output mesh first).
std::vector<std::string> synth_output_files(const SynthArgs& args);

}  // namespace meshquilt::cli
