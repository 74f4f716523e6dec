#pragma once
//! The sub-commands of the `meshquilt` executable; each registers itself on the app. Callbacks
//! throw meshquilt::Error, which main() turns into one line on stderr and an exit code.

#include <CLI/CLI.hpp>

namespace meshquilt::cli {

void add_swatch_command(CLI::App& app);
void add_inspect_command(CLI::App& app);
void add_synth_command(CLI::App& app);
void add_render_command(CLI::App& app);
void add_batch_command(CLI::App& app);
void add_loom_command(CLI::App& app);
void add_embed_command(CLI::App& app);
void add_edit_command(CLI::App& app);
void add_animate_command(CLI::App& app);
void add_paint_command(CLI::App& app);
void add_relief_command(CLI::App& app);

}  // namespace meshquilt::cli
