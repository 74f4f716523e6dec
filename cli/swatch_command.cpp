// `meshquilt swatch KIND [options] -o FILE`: writes one of the built-in swatches;
// `meshquilt swatch check FILE`: says whether a swatch from anywhere will quilt well.
#include <algorithm>
#include <cstdio>
#include <map>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "commands.h"
#include "core/error.h"
#include "exit_codes.h"
#include "inspect/swatch_check.h"
#include "mesh/mesh_io.h"
#include "swatch/swatch_kinds.h"

namespace meshquilt::cli {
namespace {

// Options every kind takes.
struct Common {
  std::filesystem::path output;
  uint64_t seed = 1;
  std::string preset = "default";
  bool ascii = false;
};

void add_common(CLI::App* cmd, Common& common, bool random) {
  cmd->add_option("-o,--output", common.output, "output mesh (.ply .obj .off .stl)")->required();
  cmd->add_option("--seed", common.seed,
                  random ? "seed of every random choice" : "accepted for uniformity; this kind is not random")
      ->capture_default_str();
  cmd->add_option("--preset", common.preset,
                  "starting sizes: default (paper-sized) or small (a few hundred to 2,000 faces)")
      ->check(CLI::IsMember({"default", "small"}))
      ->capture_default_str();
  cmd->add_flag("--ascii", common.ascii, "ASCII PLY/STL instead of binary");
}

void write(const TriMesh& mesh, const Common& common) {
  WriteOptions options;
  options.binary = !common.ascii;
  write_mesh(mesh, common.output, options);
  std::cout << "wrote " << common.output.string() << ": " << mesh.num_faces() << " faces, "
            << mesh.num_vertices() << " vertices, "
            << (mesh.elements.empty() ? 0 : *std::max_element(mesh.elements.begin(), mesh.elements.end()) + 1)
            << " elements\n";
}

// "--ring-radius" for "ring_radius".
std::string flag_of(std::string name) {
  std::replace(name.begin(), name.end(), '_', '-');
  return "--" + name;
}

std::string shown(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

// `swatch KIND` for a registered kind: its options (defaults as the default preset has them),
// and for an animated kind --frames, which also writes one cycle beside the output.
void add_kind(CLI::App* parent, const SwatchKind& kind) {
  auto* cmd = parent->add_subcommand(kind.name, with_options(kind.help));
  auto common = std::make_shared<Common>();
  add_common(cmd, *common, kind.random);
  auto settings = std::make_shared<SwatchSettings>();
  const std::map<std::string, double> defaults = kind.defaults("default");
  for (const SwatchOption& option : kind.options) {
    const std::string name = option.name;
    switch (option.type) {
      case SwatchOption::Type::integer:
        cmd->add_option_function<long long>(
               flag_of(name), [settings, name](long long v) { settings->numbers[name] = static_cast<double>(v); },
               with_options(option.help))
            ->default_str(shown(defaults.at(name)));
        break;
      case SwatchOption::Type::real:
        cmd->add_option_function<double>(
               flag_of(name), [settings, name](double v) { settings->numbers[name] = v; }, with_options(option.help))
            ->default_str(shown(defaults.at(name)));
        break;
      case SwatchOption::Type::text: {
        CLI::Option* added = cmd->add_option_function<std::string>(
            flag_of(name), [settings, name](const std::string& v) { settings->texts[name] = v; },
            with_options(option.help));
        if (!option.choices.empty()) added->check(CLI::IsMember(option.choices))->default_str(option.choices.front());
        break;
      }
      case SwatchOption::Type::flag:
        cmd->add_flag_function(flag_of(name), [settings, name](int64_t) { settings->flags.insert(name); },
                               with_options(option.help));
        break;
    }
  }
  auto frames = std::make_shared<int>(0);
  if (kind.frames)
    cmd->add_option("--frames", *frames, "also write this many frames of one cycle to OUTPUT_STEM_frames/")
        ->capture_default_str();
  const std::string name = kind.name;
  cmd->callback([common, settings, frames, name] {
    settings->preset = common->preset;
    settings->seed = common->seed;
    if (*frames < 0)
      throw InputError("--frames: expected 0 or more, got " + std::to_string(*frames), ErrorKind::invalid_option);
    write(make_builtin_swatch(name, *settings), *common);
    if (*frames == 0) return;
    const std::filesystem::path folder = common->output.parent_path() / (common->output.stem().string() + "_frames");
    std::filesystem::create_directories(folder);
    const std::vector<TriMesh> sequence = swatch_kind(name).frames(*settings, *frames);
    WriteOptions write_options;
    write_options.binary = !common->ascii;
    for (size_t k = 0; k < sequence.size(); ++k) {
      char file[32];
      std::snprintf(file, sizeof file, "frame_%04zu", k);
      write_mesh(sequence[k], folder / (file + common->output.extension().string()), write_options);
    }
    std::cout << "wrote " << sequence.size() << " frames to " << folder.string() << "\n";
  });
}

// Prints one line per finding on stdout, then fails with swatch_unfit, as `batch --report` prints
// its table and then fails: the findings are the output, the error line their summary.
void add_check(CLI::App* parent) {
  auto* cmd = parent->add_subcommand(
      "check",
      "says whether a swatch file will quilt well: closed elements, none intersecting or cut by the "
      "border, thin along z");
  auto file = std::make_shared<std::filesystem::path>();
  cmd->add_option("FILE", *file, "swatch mesh to check (.ply .obj .off .stl)")->required();
  auto repair = std::make_shared<std::filesystem::path>();
  cmd->add_option("--repair", *repair, "write the swatch as synth repairs it on reading to this file");
  cmd->callback([file, repair] {
    const std::string name = file->string();
    const SwatchCheck check = check_swatch(read_mesh(*file), name);
    if (check.repairs.any())
      std::cout << name << ": repaired on reading (synth does the same): " << check.repairs.describe("elements")
                << (repair->empty() ? "; --repair OUT writes the repaired swatch" : "") << "\n";
    if (!repair->empty()) {
      TriMesh repaired = check.repaired;
      repaired.origins.clear();  // the file's own numbering, not a quilt's provenance
      write_mesh(repaired, *repair);
      std::cout << name << ": wrote the repaired swatch to " << repair->string() << "\n";
    }
    for (const std::string& finding : check.findings) std::cout << name << ": " << finding << "\n";
    if (!check.findings.empty()) {
      std::cout.flush();
      throw Error(ErrorKind::swatch_unfit, name + ": will not quilt well (" +
                                               std::to_string(check.findings.size()) +
                                               (check.findings.size() == 1 ? " problem)" : " problems)"));
    }
    std::ostringstream ratio;
    ratio << std::fixed << std::setprecision(2) << check.thickness_ratio;
    std::cout << name << ": fine: " << check.elements
              << (check.elements == 1 ? " closed element" : " closed elements") << ", thickness "
              << ratio.str() << " x the shorter x-y side\n";
  });
}

}  // namespace

void add_swatch_command(CLI::App& app) {
  std::string names;
  for (const SwatchKind& kind : swatch_kinds()) names += (names.empty() ? "" : ", ") + kind.name;
  auto* cmd = app.add_subcommand("swatch", "writes a built-in swatch (" + names + ") or checks one (check)");
  cmd->require_subcommand(1);
  for (const SwatchKind& kind : swatch_kinds()) add_kind(cmd, kind);
  add_check(cmd);
}

}  // namespace meshquilt::cli
