#pragma once
//! Manifests of `meshquilt batch`: a list of jobs, each a command (synth, the default, paint or
//! relief), an output path and the command's options.
//!
//! JSON lines (any extension but .json): one job object a line; blank lines and lines starting
//! with `#` are skipped. JSON (.json): an array of job objects, or {"jobs": [...]}. A job:
//!   {"output": "out/a.ply", "options": ["--swatch", "chain.ply", "--plane", "2x2", "--seed", 3]}
//!   {"output": "out/b.ply", "options": {"swatch": "chain.ply", "plane": "2x2", "no-cleanup": true}}
//!   {"command": "paint", "output": "out/c.ply", "options": {"base": "bunny.off", "image": "bark.png"}}
//! List entries are strings or numbers; object keys are option names without their dashes, with
//! a string or number value, or `true` for a flag (`false` leaves the flag out). Options are
//! parsed by the command's own registration (add_synth_options, add_paint_options,
//! add_relief_options). Relative paths, in `output` and in
//! the options, resolve against the manifest's folder: jobs run there.

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>


namespace meshquilt::cli {

struct BatchJob {
  size_t index = 0;                  //!< 0-based position in the manifest (what --shard splits)
  int line = 0;                      //!< 1-based manifest line where the job starts
  std::string command = "synth";     //!< the meshquilt command the job runs: synth, paint or relief
  std::string output;                //!< output mesh as written in the manifest
  std::vector<std::string> options;  //!< the command's options as given, without -o
  std::vector<std::string> inputs;   //!< files the options name for reading, as written
  std::vector<std::string> outputs;  //!< files the job writes, as written, the output mesh first
  std::string problem;               //!< non-empty: the job cannot run (e.g. its swatch is missing)

  //! The command's arguments for the job: options, then `-o OUTPUT`.
  std::vector<std::string> arguments() const;
};

struct Manifest {
  std::filesystem::path file;    //!< as given
  std::filesystem::path folder;  //!< absolute folder of the manifest, where jobs run
  std::vector<BatchJob> jobs;

  //! `path` as written in the manifest, made absolute against `folder`.
  std::filesystem::path resolve(const std::string& path) const;
  //! "FILE:LINE" for messages about `job`.
  std::string where(const BatchJob& job) const;
};

//! Reads and checks a manifest: JSON syntax, job keys, options (through the command's parser), no
//! output written by two jobs. A job whose input file is missing gets a `problem` instead of
//! failing the manifest, so the other jobs still run.
//! \throw IoError(file_unreadable) "FILE: cannot open: reason";
//!        InputError(bad_manifest) "FILE:LINE: problem" for anything else.
Manifest read_manifest(const std::filesystem::path& file);

}  // namespace meshquilt::cli
