#include "commands.h"
#include "error.h"

namespace meshquilt::cli {

void add_inspect_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("inspect", "(under construction)");
  cmd->callback([] { throw Error(ExitCode::internal, "inspect: under construction"); });
}

}  // namespace meshquilt::cli
