#pragma once
//! Manifests of `meshquilt batch`: a list of synth jobs, each an output path plus synth's options.
//!
//! JSON lines (any extension but .json): one job object a line; blank lines and lines starting
//! with `#` are skipped. JSON (.json): an array of job objects, or {"jobs": [...]}. A job:
//!   {"output": "out/a.ply", "options": ["--swatch", "chain.ply", "--plane", "2x2", "--seed", 3]}
//!   {"output": "out/b.ply", "options": {"swatch": "chain.ply", "plane": "2x2", "no-cleanup": true}}
//! List entries are strings or numbers; object keys are option names without their dashes, with
//! a string or number value, or `true` for a flag (`false` leaves the flag out). Options are
//! parsed by synth's own registration (add_synth_options). Relative paths, in `output` and in
//! the options, resolve against the manifest's folder: jobs run there.

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "synth_options.h"

namespace meshquilt::cli {

struct BatchJob {
  size_t index = 0;                  //!< 0-based position in the manifest (what --shard splits)
  int line = 0;                      //!< 1-based manifest line where the job starts
  std::string output;                //!< output mesh as written in the manifest
  std::vector<std::string> options;  //!< synth's options as given, without -o
  SynthArgs args;                    //!< the options as synth parses them, output included
  std::string problem;               //!< non-empty: the job cannot run (e.g. its swatch is missing)

  //! `synth` arguments for the job: options, then `-o OUTPUT`.
  std::vector<std::string> synth_arguments() const;
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

//! Reads and checks a manifest: JSON syntax, job keys, options (through synth's parser), no
//! output written by two jobs. A job whose input file is missing gets a `problem` instead of
//! failing the manifest, so the other jobs still run.
//! \throw IoError(file_unreadable) "FILE: cannot open: reason";
//!        InputError(bad_manifest) "FILE:LINE: problem" for anything else.
Manifest read_manifest(const std::filesystem::path& file);

}  // namespace meshquilt::cli
