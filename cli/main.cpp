// The meshquilt executable: sub-commands, and the one place errors become exit codes.
#include <cstdio>
#include <exception>
#include <iostream>

#include <CLI/CLI.hpp>

#include "commands.h"
#include "core/error.h"
#include "exit_codes.h"
#include "heap_reuse.h"
#include "signals.h"

int main(int argc, char** argv) {
  using meshquilt::cli::ExitCode;
  // Ctrl-C and SIGTERM cancel long work through a token (exit code `interrupted`), never mid-write.
  meshquilt::cli::install_interrupt_handlers();
  meshquilt::cli::keep_freed_memory();
  CLI::App app{"meshquilt: grows 3D geometric textures over planes and meshes by mesh quilting"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "meshquilt " MESHQUILT_VERSION);
  meshquilt::cli::add_swatch_command(app);
  meshquilt::cli::add_inspect_command(app);
  meshquilt::cli::add_synth_command(app);
  meshquilt::cli::add_render_command(app);
  meshquilt::cli::add_embed_command(app);
  meshquilt::cli::add_edit_command(app);
  meshquilt::cli::add_animate_command(app);
  meshquilt::cli::add_paint_command(app);
  meshquilt::cli::add_relief_command(app);
  meshquilt::cli::add_loom_command(app);
  meshquilt::cli::add_batch_command(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "meshquilt: " << e.what() << " (see --help)\n";
    return static_cast<int>(ExitCode::usage);
  } catch (const meshquilt::Error& e) {
    std::cerr << "meshquilt: " << meshquilt::cli::message(e) << "\n";
    return meshquilt::cli::exit_code(e.kind());
  } catch (const std::exception& e) {
    std::cerr << "meshquilt: internal error: " << e.what() << "\n";
    return static_cast<int>(ExitCode::internal);
  }
  return 0;
}
