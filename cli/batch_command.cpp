// `meshquilt batch`: runs a manifest of synth, paint and relief jobs (sharded, resumable) or reports on it.
#include <iostream>
#include <memory>
#include <string>

#include "batch_manifest.h"
#include "batch_records.h"
#include "batch_report.h"
#include "batch_runner.h"
#include "batch_shard.h"
#include "commands.h"
#include "core/error.h"

namespace meshquilt::cli {
namespace {

struct BatchArgs {
  std::string manifest;
  std::string shard;
  int jobs = 1;
  int threads = 0;
  std::string progress = "auto";
  bool report = false;
  std::string format = "table";
  bool count = false;
};

void run_batch_command(const BatchArgs& args) {
  if (args.jobs < 1) throw InputError("--jobs: expected at least 1, got " + std::to_string(args.jobs), ErrorKind::invalid_option);
  if (args.threads < 0)
    throw InputError("--threads: expected 0 (automatic) or more, got " + std::to_string(args.threads), ErrorKind::invalid_option);
  const ProgressMode progress = parse_progress_mode(args.progress);
  const ReportFormat format = parse_report_format(args.format);
  const Manifest manifest = read_manifest(args.manifest);
  if (args.count) {
    std::cout << manifest.jobs.size() << std::endl;
    return;
  }
  if (args.report) {
    const ReportTotals totals = write_report(manifest, format, std::cout);
    std::cout.flush();
    if (!totals.complete())
      throw Error(ErrorKind::batch_incomplete,
                  args.manifest + ": " + std::to_string(totals.jobs - totals.done) + " of " + std::to_string(totals.jobs) +
                      " jobs not done (" + std::to_string(totals.failed) + " failed, " + std::to_string(totals.running) +
                      " running, " + std::to_string(totals.missing) + " missing)");
    return;
  }
  BatchOptions options;
  options.shard = args.shard.empty() ? shard_from_environment() : parse_shard(args.shard);
  options.jobs = args.jobs;
  options.threads = args.threads;
  options.progress = progress;
  const BatchOutcome outcome = run_batch(manifest, options);
  if (outcome.failed > 0)
    throw Error(ErrorKind::batch_incomplete, args.manifest + ": " + std::to_string(outcome.failed) + " of " +
                                                std::to_string(outcome.selected) + " jobs of shard " +
                                                options.shard.text() + " failed (see --report)");
}

}  // namespace

void add_batch_command(CLI::App& app) {
  auto args = std::make_shared<BatchArgs>();
  CLI::App* cmd = app.add_subcommand("batch", "Run a manifest of synth, paint and relief jobs (sharded, resumable) or report on it");
  cmd->add_option("manifest", args->manifest, "jobs as JSON lines, or a .json array; see docs/cli.md")->required();
  cmd->add_option("--shard", args->shard,
                  "run jobs whose index is I modulo N (I/N); default: from a Slurm array task's variables, else 0/1");
  cmd->add_option("--jobs", args->jobs, "jobs running at once")->capture_default_str();
  cmd->add_option("--threads", args->threads, "CPUs per job (0: this process's CPUs / --jobs)")->capture_default_str();
  cmd->add_option("--progress", args->progress, "auto|json|none")->capture_default_str();
  CLI::Option* report = cmd->add_flag("--report", args->report, "report each job's state and figures instead of running");
  cmd->add_option("--format", args->format, "table|json|csv (with --report)")->capture_default_str()->needs(report);
  cmd->add_flag("--count", args->count, "check the manifest and print its number of jobs");
  cmd->callback([args] { run_batch_command(*args); });
}

}  // namespace meshquilt::cli
