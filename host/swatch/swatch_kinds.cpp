#include "swatch/swatch_kinds.h"

#include <algorithm>
#include <cmath>
#include <variant>

#include "core/error.h"
#include "swatch/chainmail.h"
#include "swatch/fruit.h"
#include "swatch/heightfield.h"
#include "swatch/netpbm.h"
#include "swatch/nuts.h"
#include "swatch/vine.h"
#include "swatch/weave.h"
#include "swatch/weave_pattern.h"

namespace meshquilt {
namespace {

using Type = SwatchOption::Type;

// A numeric option and the field of the kind's options struct it sets.
template <class O>
struct Field {
  const char* name;
  std::variant<int O::*, double O::*> member;
  const char* help;
};

template <class O>
std::vector<SwatchOption> options_of(const std::vector<Field<O>>& fields) {
  std::vector<SwatchOption> options;
  for (const Field<O>& f : fields)
    options.push_back({f.name, std::holds_alternative<int O::*>(f.member) ? Type::integer : Type::real, f.help, {}});
  return options;
}

// `preset` with the numbers given set.
template <class O>
O with_numbers(O o, const std::vector<Field<O>>& fields, const SwatchSettings& s) {
  for (const Field<O>& f : fields) {
    const auto given = s.numbers.find(f.name);
    if (given == s.numbers.end()) continue;
    if (const auto* integer = std::get_if<int O::*>(&f.member))
      o.**integer = static_cast<int>(given->second);
    else
      o.*std::get<double O::*>(f.member) = given->second;
  }
  return o;
}

template <class O>
std::map<std::string, double> numbers_of(const O& o, const std::vector<Field<O>>& fields) {
  std::map<std::string, double> values;
  for (const Field<O>& f : fields) {
    const auto* integer = std::get_if<int O::*>(&f.member);
    values[f.name] = integer ? static_cast<double>(o.**integer) : o.*std::get<double O::*>(f.member);
  }
  return values;
}

std::string text_or(const SwatchSettings& s, const std::string& name, const std::string& fallback) {
  const auto given = s.texts.find(name);
  return given == s.texts.end() ? fallback : given->second;
}

WeaveYarns yarns_named(const std::string& name) {
  return name == "warps" ? WeaveYarns::warps : name == "wefts" ? WeaveYarns::wefts : WeaveYarns::both;
}

const SwatchOption kOnly{"only", Type::text, "build one direction alone: warps (along y) or wefts (along x)",
                         {"both", "warps", "wefts"}};

// Every kind with its options struct: the table from which the registry is made.
template <class O>
SwatchKind kind(const char* name, const char* help, bool random, std::vector<Field<O>> fields,
                std::vector<SwatchOption> extra, std::function<O(const std::string& preset)> preset,
                std::function<TriMesh(O, const SwatchSettings&)> make,
                std::function<std::vector<TriMesh>(O, const SwatchSettings&, int)> frames = {}) {
  SwatchKind k;
  k.name = name;
  k.help = help;
  k.random = random;
  k.options = options_of(fields);
  k.options.insert(k.options.end(), extra.begin(), extra.end());
  k.make = [fields, preset, make](const SwatchSettings& s) { return make(with_numbers(preset(s.preset), fields, s), s); };
  k.defaults = [fields, preset](const std::string& p) { return numbers_of(preset(p), fields); };
  if (frames)
    k.frames = [fields, preset, frames](const SwatchSettings& s, int count) {
      return frames(with_numbers(preset(s.preset), fields, s), s, count);
    };
  return k;
}

std::vector<SwatchKind> make_kinds() {
  std::vector<SwatchKind> kinds;
  kinds.push_back(kind<ChainmailOptions>(
      "chainmail", "European 4-in-1 chain mail: tilted rings, each linked through four neighbours", false,
      {{"rows", &ChainmailOptions::rows, "ring rows along y (even)"},
       {"columns", &ChainmailOptions::columns, "rings per row along x"},
       {"ring_radius", &ChainmailOptions::ring_radius, "radius of a ring's centreline"},
       {"wire_radius", &ChainmailOptions::wire_radius, "radius of the wire"},
       {"pitch_x", &ChainmailOptions::pitch_x, "ring spacing along a row"},
       {"pitch_y", &ChainmailOptions::pitch_y, "row spacing"},
       {"tilt", &ChainmailOptions::tilt_degrees, "ring tilt out of the x-y plane, degrees"},
       {"ring_segments", &ChainmailOptions::ring_segments, "segments around a ring"},
       {"wire_segments", &ChainmailOptions::wire_segments, "segments around the wire"}},
      {}, [](const std::string& p) { return p == "small" ? ChainmailOptions::small() : ChainmailOptions{}; },
      [](ChainmailOptions o, const SwatchSettings&) { return make_chainmail(o); }));
  kinds.push_back(kind<WeaveOptions>(
      "weave", "woven yarns: warps along y and wefts along x, over and under by a weave pattern", false,
      {{"warps", &WeaveOptions::warps, "warps (a multiple of the pattern's ends; 0: about 10)"},
       {"wefts", &WeaveOptions::wefts, "wefts (a multiple of the pattern's picks; 0: about 10)"},
       {"pitch", &WeaveOptions::pitch, "distance between neighbouring yarns"},
       {"yarn_radius", &WeaveOptions::yarn_radius, "yarn radius"},
       {"amplitude", &WeaveOptions::amplitude, "height of a yarn above or below z = 0 at a crossing"},
       {"segments", &WeaveOptions::segments_per_pitch, "segments per pitch along a yarn"},
       {"sides", &WeaveOptions::sides, "vertices around a yarn"}},
      {{"pattern", Type::text, "plain, twill:M/N, satin:M/N, or a PBM/PGM image (dark: warp over)", {}}, kOnly},
      [](const std::string& p) { return p == "small" ? WeaveOptions::small() : WeaveOptions{}; },
      [](WeaveOptions o, const SwatchSettings& s) {
        o.pattern = parse_weave_pattern(text_or(s, "pattern", "plain"));
        o.yarns = yarns_named(text_or(s, "only", "both"));
        return make_weave(o);
      }));
  kinds.push_back(kind<WeaveOptions>(
      "wire", "a sparse square mesh of thin crimped wires: a plain weave, any wire count", false,
      {{"wires", &WeaveOptions::yarns_hint, "wires each way (default 9; small preset 5)"},
       {"warps", &WeaveOptions::warps, "wires along y (overrides {wires})"},
       {"wefts", &WeaveOptions::wefts, "wires along x (overrides {wires})"},
       {"radius", &WeaveOptions::yarn_radius, "wire radius"},
       {"pitch", &WeaveOptions::pitch, "distance between neighbouring parallel wires"},
       {"crimp", &WeaveOptions::amplitude, "height of a wire above or below z = 0 at a crossing"},
       {"segments", &WeaveOptions::segments_per_pitch, "segments per pitch along a wire"},
       {"sides", &WeaveOptions::sides, "vertices around a wire"}},
      {kOnly},
      [](const std::string& p) {
        WeaveOptions o = p == "small" ? WeaveOptions::small_wire() : WeaveOptions::wire();
        o.yarns_hint = o.warps;  // --wires shows the preset's count
        return o;
      },
      [](WeaveOptions o, const SwatchSettings& s) {
        // wires sets both counts; warps and wefts, given, override it.
        if (s.numbers.count("wires")) {
          if (o.yarns_hint < 1)
            throw InputError("{wires}: expected 1 or more, got " + std::to_string(o.yarns_hint),
                             ErrorKind::invalid_option);
          if (!s.numbers.count("warps")) o.warps = o.yarns_hint;
          if (!s.numbers.count("wefts")) o.wefts = o.yarns_hint;
        }
        o.yarns_hint = WeaveOptions{}.yarns_hint;
        o.yarns = yarns_named(text_or(s, "only", "both"));
        return make_weave(o);
      }));
  kinds.push_back(kind<FruitOptions>(
      "fruit", "apple-like blobs of varied size and shape in one layer, not touching", true,
      {{"columns", &FruitOptions::columns, "fruit per row"},
       {"rows", &FruitOptions::rows, "rows"},
       {"radius", &FruitOptions::radius, "mean radius"},
       {"size_variation", &FruitOptions::size_variation, "relative spread of sizes, 0..0.5"},
       {"gap", &FruitOptions::gap, "smallest distance between two fruit"},
       {"subdivisions", &FruitOptions::subdivisions, "icosahedron subdivisions (20*4^n faces each)"}},
      {}, [](const std::string& p) { return p == "small" ? FruitOptions::small() : FruitOptions{}; },
      [](FruitOptions o, const SwatchSettings& s) {
        o.seed = s.seed;
        return make_fruit(o);
      }));
  kinds.push_back(kind<VineOptions>(
      "vine", "swaying stalks, closed tubes in one layer; with {frames}, its animation", true,
      {{"columns", &VineOptions::columns, "stalks per row"},
       {"rows", &VineOptions::rows, "rows"},
       {"spacing", &VineOptions::spacing, "distance between roots"},
       {"height", &VineOptions::height, "stalk height"},
       {"radius", &VineOptions::radius, "tube radius"},
       {"curl", &VineOptions::curl, "rest lean of the tips along x, in heights"},
       {"sway", &VineOptions::sway, "largest tip displacement of the animation, in heights (0..0.5)"},
       {"segments", &VineOptions::segments, "centreline points per stalk"},
       {"sides", &VineOptions::sides, "tube sides"}},
      {}, [](const std::string& p) { return p == "small" ? VineOptions::small() : VineOptions{}; },
      [](VineOptions o, const SwatchSettings& s) {
        o.seed = s.seed;
        return make_vine(o);
      },
      [](VineOptions o, const SwatchSettings& s, int count) {
        o.seed = s.seed;
        return make_vine_frames(o, count);
      }));
  kinds.push_back(kind<NutOptions>(
      "nuts", "hex nuts (genus 1) at varied rotations in one layer, not touching", true,
      {{"columns", &NutOptions::columns, "nuts per row"},
       {"rows", &NutOptions::rows, "rows"},
       {"across_flats", &NutOptions::across_flats, "hexagon width across flats"},
       {"hole_radius", &NutOptions::hole_radius, "hole radius"},
       {"thickness", &NutOptions::thickness, "nut height"},
       {"size_variation", &NutOptions::size_variation, "relative spread of sizes, 0..0.5"},
       {"gap", &NutOptions::gap, "smallest distance between two nuts"},
       {"segments_per_side", &NutOptions::segments_per_side, "segments along a hexagon side"},
       {"wall_segments", &NutOptions::wall_segments, "segments up the walls"},
       {"face_segments", &NutOptions::face_segments, "segments across the flat faces"}},
      {}, [](const std::string& p) { return p == "small" ? NutOptions::small() : NutOptions{}; },
      [](NutOptions o, const SwatchSettings& s) {
        o.seed = s.seed;
        return make_nuts(o);
      }));
  kinds.push_back(kind<HeightfieldOptions>(
      "heightfield", "a relief from a grayscale image (PGM/PBM/PPM): closed slab or open sheet", false,
      {{"resolution", &HeightfieldOptions::builtin_resolution, "pixels a side of the built-in relief"},
       {"max_resolution", &HeightfieldOptions::max_resolution, "longer side is box-filtered down to this many pixels"},
       {"size", &HeightfieldOptions::size, "length of the longer side"},
       {"height", &HeightfieldOptions::height, "relief height (white minus black)"},
       {"base", &HeightfieldOptions::base, "slab thickness below black"},
       {"tiles", &HeightfieldOptions::tiles,
        "N x N separate tiles with a pixel of grout between them (default 1: one piece)"}},
      {{"image", Type::text, "height image (white high); default: a built-in egg-crate relief", {}},
       {"open", Type::flag, "the top sheet alone instead of a closed slab", {}}},
      [](const std::string& p) { return p == "small" ? HeightfieldOptions::small() : HeightfieldOptions{}; },
      [](HeightfieldOptions o, const SwatchSettings& s) {
        o.open = s.flags.count("open") > 0;
        if (const std::string image = text_or(s, "image", ""); !image.empty()) o.image = read_netpbm(image);
        return make_heightfield(o);
      }));
  return kinds;
}

}  // namespace

const std::vector<SwatchKind>& swatch_kinds() {
  static const std::vector<SwatchKind> kinds = make_kinds();
  return kinds;
}

const SwatchKind& swatch_kind(const std::string& name) {
  std::string names;
  for (const SwatchKind& k : swatch_kinds()) {
    if (k.name == name) return k;
    names += (names.empty() ? "" : ", ") + k.name;
  }
  throw InputError("swatch: unknown kind '" + name + "' (" + names + ")", ErrorKind::invalid_option);
}

TriMesh make_builtin_swatch(const std::string& kind_name, const SwatchSettings& settings) {
  check_swatch_settings(kind_name, settings);
  return swatch_kind(kind_name).make(settings);
}

void check_swatch_settings(const std::string& kind_name, const SwatchSettings& settings) {
  const SwatchKind& k = swatch_kind(kind_name);
  if (settings.preset != "default" && settings.preset != "small")
    throw InputError("{preset}: expected default or small, got '" + settings.preset + "'", ErrorKind::invalid_option);
  auto option = [&](const std::string& name) -> const SwatchOption& {
    for (const SwatchOption& o : k.options)
      if (o.name == name) return o;
    std::string names;
    for (const SwatchOption& o : k.options) names += (names.empty() ? "" : ", ") + o.name;
    throw InputError("swatch " + k.name + ": unknown option '" + name + "' (" + names + ")",
                     ErrorKind::invalid_option);
  };
  for (const auto& [name, value] : settings.numbers) {
    const SwatchOption& o = option(name);
    if (o.type != Type::integer && o.type != Type::real)
      throw InputError("{" + name + "}: expected text, not a number", ErrorKind::invalid_option);
    if (o.type == Type::integer && !(std::isfinite(value) && value == std::round(value) && std::abs(value) < 1e9))
      throw InputError("{" + name + "}: expected a whole number, got " + std::to_string(value),
                       ErrorKind::invalid_option);
  }
  for (const auto& [name, text] : settings.texts) {
    const SwatchOption& o = option(name);
    if (o.type != Type::text) throw InputError("{" + name + "}: expected a number", ErrorKind::invalid_option);
    if (!o.choices.empty() && std::find(o.choices.begin(), o.choices.end(), text) == o.choices.end())
      throw InputError("{" + name + "}: unknown value '" + text + "'", ErrorKind::invalid_option);
  }
  for (const std::string& name : settings.flags)
    if (option(name).type != Type::flag) throw InputError("{" + name + "}: not a flag", ErrorKind::invalid_option);
}

}  // namespace meshquilt
