#include "commands.h"
#include "error.h"

namespace meshquilt::cli {

void add_synth_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("synth", "(under construction)");
  cmd->callback([] { throw Error(ExitCode::internal, "synth: under construction"); });
}

}  // namespace meshquilt::cli
