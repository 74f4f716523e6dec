// `meshquilt swatch KIND [options] -o FILE`: writes one of the built-in swatches;
// `meshquilt swatch check FILE`: says whether a swatch from anywhere will quilt well.
#include <algorithm>
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
#include "inspect/swatch_check.h"
#include "mesh/mesh_io.h"
#include "swatch/chainmail.h"
#include "swatch/fruit.h"
#include "swatch/heightfield.h"
#include "swatch/netpbm.h"
#include "swatch/nuts.h"
#include "swatch/vine.h"
#include "swatch/weave.h"
#include "swatch/weave_pattern.h"

namespace meshquilt::cli {
namespace {

// Options every kind takes.
struct Common {
  std::filesystem::path output;
  uint64_t seed = 1;
  std::string preset = "default";
  bool ascii = false;
};

// Binds command-line options to fields of an XxxOptions struct so that only the options given
// on the command line override the chosen preset.
template <class Options>
class Binder {
 public:
  //! shown: the values the help prints as defaults (the preset's own, not the struct's).
  explicit Binder(const Options& shown = Options{}) : given_(shown) {}

  template <class T>
  void add(CLI::App* cmd, const std::string& flag, T Options::*field, const std::string& help) {
    CLI::Option* option = cmd->add_option(flag, given_.*field, help)->capture_default_str();
    overrides_.push_back([option, field, this](Options& target) {
      if (option->count() > 0) target.*field = given_.*field;
    });
  }

  Options resolve(const Options& preset) const {
    Options result = preset;
    for (const auto& apply : overrides_) apply(result);
    return result;
  }

 private:
  Options given_;
  std::vector<std::function<void(Options&)>> overrides_;
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

void add_chainmail(CLI::App* parent, const std::shared_ptr<Common>& common) {
  auto* cmd = parent->add_subcommand(
      "chainmail", "European 4-in-1 chain mail: tilted rings, each linked through four neighbours");
  add_common(cmd, *common, false);
  auto b = std::make_shared<Binder<ChainmailOptions>>();
  b->add(cmd, "--rows", &ChainmailOptions::rows, "ring rows along y (even)");
  b->add(cmd, "--columns", &ChainmailOptions::columns, "rings per row along x");
  b->add(cmd, "--ring-radius", &ChainmailOptions::ring_radius, "radius of a ring's centreline");
  b->add(cmd, "--wire-radius", &ChainmailOptions::wire_radius, "radius of the wire");
  b->add(cmd, "--pitch-x", &ChainmailOptions::pitch_x, "ring spacing along a row");
  b->add(cmd, "--pitch-y", &ChainmailOptions::pitch_y, "row spacing");
  b->add(cmd, "--tilt", &ChainmailOptions::tilt_degrees, "ring tilt out of the x-y plane, degrees");
  b->add(cmd, "--ring-segments", &ChainmailOptions::ring_segments, "segments around a ring");
  b->add(cmd, "--wire-segments", &ChainmailOptions::wire_segments, "segments around the wire");
  cmd->callback([common, b] {
    const ChainmailOptions preset =
        common->preset == "small" ? ChainmailOptions::small() : ChainmailOptions{};
    write(make_chainmail(b->resolve(preset)), *common);
  });
}

// `--only warps|wefts`: one yarn direction; unset, both.
std::shared_ptr<std::string> add_only(CLI::App* cmd) {
  auto only = std::make_shared<std::string>("both");
  cmd->add_option("--only", *only, "build one direction alone: warps (along y) or wefts (along x)")
      ->check(CLI::IsMember({"both", "warps", "wefts"}))
      ->capture_default_str();
  return only;
}

WeaveYarns yarns_named(const std::string& name) {
  return name == "warps" ? WeaveYarns::warps : name == "wefts" ? WeaveYarns::wefts : WeaveYarns::both;
}

void add_weave(CLI::App* parent, const std::shared_ptr<Common>& common) {
  auto* cmd = parent->add_subcommand(
      "weave", "woven yarns: warps along y and wefts along x, over and under by a weave pattern");
  add_common(cmd, *common, false);
  auto pattern = std::make_shared<std::string>("plain");
  cmd->add_option("--pattern", *pattern, "plain, twill:M/N, satin:M/N, or a PBM/PGM image (dark: warp over)")
      ->capture_default_str();
  auto b = std::make_shared<Binder<WeaveOptions>>();
  b->add(cmd, "--warps", &WeaveOptions::warps, "warps (a multiple of the pattern's ends; 0: about 10)");
  b->add(cmd, "--wefts", &WeaveOptions::wefts, "wefts (a multiple of the pattern's picks; 0: about 10)");
  b->add(cmd, "--pitch", &WeaveOptions::pitch, "distance between neighbouring yarns");
  b->add(cmd, "--yarn-radius", &WeaveOptions::yarn_radius, "yarn radius");
  b->add(cmd, "--amplitude", &WeaveOptions::amplitude, "height of a yarn above or below z = 0 at a crossing");
  b->add(cmd, "--segments", &WeaveOptions::segments_per_pitch, "segments per pitch along a yarn");
  b->add(cmd, "--sides", &WeaveOptions::sides, "vertices around a yarn");
  auto only = add_only(cmd);
  cmd->callback([common, b, pattern, only] {
    WeaveOptions options = b->resolve(common->preset == "small" ? WeaveOptions::small() : WeaveOptions{});
    options.pattern = parse_weave_pattern(*pattern);
    options.yarns = yarns_named(*only);
    write(make_weave(options), *common);
  });
}

void add_wire(CLI::App* parent, const std::shared_ptr<Common>& common) {
  auto* cmd = parent->add_subcommand(
      "wire", "a sparse square mesh of thin crimped wires: a plain weave, any wire count");
  add_common(cmd, *common, false);
  auto wires = std::make_shared<int>(0);
  cmd->add_option("--wires", *wires, "wires each way (default 9; small preset 5)")
      ->check(CLI::PositiveNumber);
  auto b = std::make_shared<Binder<WeaveOptions>>(WeaveOptions::wire());
  b->add(cmd, "--warps", &WeaveOptions::warps, "wires along y (overrides --wires)");
  b->add(cmd, "--wefts", &WeaveOptions::wefts, "wires along x (overrides --wires)");
  b->add(cmd, "--radius", &WeaveOptions::yarn_radius, "wire radius");
  b->add(cmd, "--pitch", &WeaveOptions::pitch, "distance between neighbouring parallel wires");
  b->add(cmd, "--crimp", &WeaveOptions::amplitude, "height of a wire above or below z = 0 at a crossing");
  b->add(cmd, "--segments", &WeaveOptions::segments_per_pitch, "segments per pitch along a wire");
  b->add(cmd, "--sides", &WeaveOptions::sides, "vertices around a wire");
  auto only = add_only(cmd);
  cmd->callback([common, wires, b, only] {
    WeaveOptions preset = common->preset == "small" ? WeaveOptions::small_wire() : WeaveOptions::wire();
    if (*wires != 0) preset.warps = preset.wefts = *wires;
    WeaveOptions options = b->resolve(preset);
    options.yarns = yarns_named(*only);
    write(make_weave(options), *common);
  });
}

void add_fruit(CLI::App* parent, const std::shared_ptr<Common>& common) {
  auto* cmd =
      parent->add_subcommand("fruit", "apple-like blobs of varied size and shape in one layer, not touching");
  add_common(cmd, *common, true);
  auto b = std::make_shared<Binder<FruitOptions>>();
  b->add(cmd, "--columns", &FruitOptions::columns, "fruit per row");
  b->add(cmd, "--rows", &FruitOptions::rows, "rows");
  b->add(cmd, "--radius", &FruitOptions::radius, "mean radius");
  b->add(cmd, "--size-variation", &FruitOptions::size_variation, "relative spread of sizes, 0..0.5");
  b->add(cmd, "--gap", &FruitOptions::gap, "smallest distance between two fruit");
  b->add(cmd, "--subdivisions", &FruitOptions::subdivisions, "icosahedron subdivisions (20*4^n faces each)");
  cmd->callback([common, b] {
    FruitOptions options = b->resolve(common->preset == "small" ? FruitOptions::small() : FruitOptions{});
    options.seed = common->seed;
    write(make_fruit(options), *common);
  });
}

void add_vine(CLI::App* parent, const std::shared_ptr<Common>& common) {
  auto* cmd = parent->add_subcommand(
      "vine", "swaying stalks, closed tubes in one layer; with --frames, its animation");
  add_common(cmd, *common, true);
  auto b = std::make_shared<Binder<VineOptions>>();
  b->add(cmd, "--columns", &VineOptions::columns, "stalks per row");
  b->add(cmd, "--rows", &VineOptions::rows, "rows");
  b->add(cmd, "--spacing", &VineOptions::spacing, "distance between roots");
  b->add(cmd, "--height", &VineOptions::height, "stalk height");
  b->add(cmd, "--radius", &VineOptions::radius, "tube radius");
  b->add(cmd, "--curl", &VineOptions::curl, "rest lean of the tips along x, in heights");
  b->add(cmd, "--sway", &VineOptions::sway, "largest tip displacement of the animation, in heights (0..0.5)");
  b->add(cmd, "--segments", &VineOptions::segments, "centreline points per stalk");
  b->add(cmd, "--sides", &VineOptions::sides, "tube sides");
  auto frames = std::make_shared<int>(0);
  cmd->add_option("--frames", *frames, "also write this many frames of one sway cycle to OUTPUT_STEM_frames/")
      ->capture_default_str();
  cmd->callback([common, b, frames] {
    VineOptions options = b->resolve(common->preset == "small" ? VineOptions::small() : VineOptions{});
    options.seed = common->seed;
    if (*frames < 0)
      throw InputError("--frames: expected 0 or more, got " + std::to_string(*frames),
                       ErrorKind::invalid_option);
    write(make_vine(options), *common);
    if (*frames == 0) return;
    const std::filesystem::path folder =
        common->output.parent_path() / (common->output.stem().string() + "_frames");
    std::filesystem::create_directories(folder);
    const std::vector<TriMesh> sequence = make_vine_frames(options, *frames);
    WriteOptions write_options;
    write_options.binary = !common->ascii;
    for (size_t k = 0; k < sequence.size(); ++k) {
      char name[32];
      std::snprintf(name, sizeof name, "frame_%04zu", k);
      write_mesh(sequence[k], folder / (name + common->output.extension().string()), write_options);
    }
    std::cout << "wrote " << sequence.size() << " frames to " << folder.string() << "\n";
  });
}

void add_nuts(CLI::App* parent, const std::shared_ptr<Common>& common) {
  auto* cmd =
      parent->add_subcommand("nuts", "hex nuts (genus 1) at varied rotations in one layer, not touching");
  add_common(cmd, *common, true);
  auto b = std::make_shared<Binder<NutOptions>>();
  b->add(cmd, "--columns", &NutOptions::columns, "nuts per row");
  b->add(cmd, "--rows", &NutOptions::rows, "rows");
  b->add(cmd, "--across-flats", &NutOptions::across_flats, "hexagon width across flats");
  b->add(cmd, "--hole-radius", &NutOptions::hole_radius, "hole radius");
  b->add(cmd, "--thickness", &NutOptions::thickness, "nut height");
  b->add(cmd, "--size-variation", &NutOptions::size_variation, "relative spread of sizes, 0..0.5");
  b->add(cmd, "--gap", &NutOptions::gap, "smallest distance between two nuts");
  b->add(cmd, "--segments-per-side", &NutOptions::segments_per_side, "segments along a hexagon side");
  b->add(cmd, "--wall-segments", &NutOptions::wall_segments, "segments up the walls");
  b->add(cmd, "--face-segments", &NutOptions::face_segments, "segments across the flat faces");
  cmd->callback([common, b] {
    NutOptions options = b->resolve(common->preset == "small" ? NutOptions::small() : NutOptions{});
    options.seed = common->seed;
    write(make_nuts(options), *common);
  });
}

void add_heightfield(CLI::App* parent, const std::shared_ptr<Common>& common) {
  auto* cmd = parent->add_subcommand(
      "heightfield", "a relief from a grayscale image (PGM/PBM/PPM): closed slab or open sheet");
  add_common(cmd, *common, false);
  auto image = std::make_shared<std::filesystem::path>();
  cmd->add_option("--image", *image, "height image (white high); default: a built-in egg-crate relief");
  auto b = std::make_shared<Binder<HeightfieldOptions>>();
  b->add(cmd, "--resolution", &HeightfieldOptions::builtin_resolution,
         "pixels a side of the built-in relief");
  b->add(cmd, "--max-resolution", &HeightfieldOptions::max_resolution,
         "longer side is box-filtered down to this many pixels");
  b->add(cmd, "--size", &HeightfieldOptions::size, "length of the longer side");
  b->add(cmd, "--height", &HeightfieldOptions::height, "relief height (white minus black)");
  b->add(cmd, "--base", &HeightfieldOptions::base, "slab thickness below black");
  b->add(cmd, "--tiles", &HeightfieldOptions::tiles,
         "N x N separate tiles with a pixel of grout between them (default 1: one piece)");
  auto open = std::make_shared<bool>(false);
  cmd->add_flag("--open", *open, "the top sheet alone instead of a closed slab");
  cmd->callback([common, b, image, open] {
    HeightfieldOptions options =
        b->resolve(common->preset == "small" ? HeightfieldOptions::small() : HeightfieldOptions{});
    options.open = *open;
    if (!image->empty()) options.image = read_netpbm(*image);
    write(make_heightfield(options), *common);
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
  auto* cmd = app.add_subcommand("swatch",
                                 "writes a built-in swatch (chainmail, weave, wire, fruit, vine, nuts, "
                                 "heightfield) or checks one (check)");
  cmd->require_subcommand(1);
  auto common = std::make_shared<Common>();
  add_chainmail(cmd, common);
  add_weave(cmd, common);
  add_wire(cmd, common);
  add_fruit(cmd, common);
  add_vine(cmd, common);
  add_nuts(cmd, common);
  add_heightfield(cmd, common);
  add_check(cmd);
}

}  // namespace meshquilt::cli
