#include "commands.h"
#include "error.h"

namespace meshquilt::cli {

void add_swatch_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("swatch", "(under construction)");
  cmd->callback([] { throw Error(ExitCode::internal, "swatch: under construction"); });
}

}  // namespace meshquilt::cli
