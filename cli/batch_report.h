#pragma once
//! `meshquilt batch MANIFEST --report`: every job's state, seconds and quality figures from its
//! completion record (synth's stats summary), and totals, as a table, JSON or CSV.

#include <cstddef>
#include <ostream>
#include <string>

#include "batch_manifest.h"

namespace meshquilt::cli {

enum class ReportFormat { table, json, csv };

//! Parses "table", "json" or "csv". \throw InputError(invalid_option) naming --format.
ReportFormat parse_report_format(const std::string& text);

struct ReportTotals {
  size_t jobs = 0, done = 0, failed = 0, running = 0, missing = 0;  //!< missing includes stale records
  bool complete() const { return done == jobs; }
};

//! Writes the report of every job (all shards) to `out`. Reads records only; never blocks.
ReportTotals write_report(const Manifest& manifest, ReportFormat format, std::ostream& out);

}  // namespace meshquilt::cli
