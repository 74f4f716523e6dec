#include "loom_options.h"

namespace meshquilt::cli {

void add_loom_options(CLI::App* cmd, LoomArgs& args) {
  cmd->add_option("--design", args.design,
                  "the weave design: an image (PNG, PBM, PGM, PPM), a pixel a crossing, dark where the warp "
                  "(column) lies over the weft (row)")
      ->required();
  cmd->add_option("--weaves", args.weaves,
                  "read the design's colours as weaves: RRGGBB=plain,RRGGBB=twill:2/2,RRGGBB=satin:4/1,RRGGBB=FILE.pbm");
  cmd->add_option("--warp-colors", args.warp_colors,
                  "an image whose pixel (c, 0) colours warp c (a row of yarn types; repeats)");
  cmd->add_option("--weft-colors", args.weft_colors,
                  "an image whose pixel (0, r) colours weft r (a column of yarn types; repeats)");
  cmd->add_option("--exemplar", args.exemplars, "a woven swatch mesh (repeat for more)")->required();
  cmd->add_option("-o,--output", args.output, "the fabric mesh, or with --assignment-only a text file")->required();
  cmd->add_option("--method", args.method, "naive, greedy or structured")->capture_default_str();
  cmd->add_option("--seed", args.seed, "seed of the choices among equals and the shifts")->capture_default_str();
  cmd->add_option("--stations", args.stations, "samples along a yarn per crossing (even)")->capture_default_str();
  cmd->add_option("--sides", args.sides, "vertices around each yarn")->capture_default_str();
  cmd->add_option("--base", args.base,
                  "drape the fabric over this base, a disc (one piece, one boundary), laid out in one chart");
  cmd->add_option("--scale", args.scale, "with --base: the fabric's longer side over the base's diagonal")
      ->capture_default_str();
  cmd->add_flag("--periodic", args.periodic,
                "the design is one repeat: its edges wrap round, so the fabric is a swatch for synth over a base");
  cmd->add_flag("--assignment-only", args.assignment_only,
                "write the assignment (rows columns, then per crossing: exemplar warp weft) and no geometry");
  cmd->add_option("--picture", args.picture, "a PNG of which exemplar each crossing copies (a hue each)");
  cmd->add_option("--stats", args.stats, "write the assignment's scores and the crossing grid as JSON");
  cmd->add_option("--progress", args.progress, "auto, bar, json or none")->capture_default_str();
}

std::vector<std::string> loom_input_files(const LoomArgs& args) {
  std::vector<std::string> files{args.design};
  files.insert(files.end(), args.exemplars.begin(), args.exemplars.end());
  for (const std::string* f : {&args.warp_colors, &args.weft_colors, &args.base})
    if (!f->empty()) files.push_back(*f);
  return files;
}

std::vector<std::string> loom_output_files(const LoomArgs& args) {
  std::vector<std::string> files{args.output};
  for (const std::string* f : {&args.stats, &args.picture})
    if (!f->empty()) files.push_back(*f);
  return files;
}

}  // namespace meshquilt::cli
