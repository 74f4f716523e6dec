#pragma once
//! The built-in swatch kinds, registered once: name, help, options and generator. The CLI's
//! `swatch KIND`, the Python module's `swatch(kind, ...)`, the docs check and the tests all read
//! this table, so a new kind is one entry here plus its generator.

#include <cstdint>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "mesh/tri_mesh.h"

namespace meshquilt {

//! One option of a kind. Its name is snake_case: the CLI spells it --with-dashes, Python as is.
struct SwatchOption {
  enum class Type { integer, real, text, flag };
  std::string name;
  Type type = Type::real;
  std::string help;                  //!< may name other options as {name}
  std::vector<std::string> choices;  //!< a text option's allowed values; empty: any text
};

//! What a caller gave: only the options set (the rest keep the preset's values).
struct SwatchSettings {
  std::string preset = "default";  //!< default (paper-sized) or small (test-sized)
  uint64_t seed = 1;
  std::map<std::string, double> numbers;     //!< integer and real options
  std::map<std::string, std::string> texts;  //!< text options
  std::set<std::string> flags;               //!< flags set
};

struct SwatchKind {
  std::string name;
  std::string help;
  bool random = false;  //!< the seed changes it
  std::vector<SwatchOption> options;
  //! The swatch. \throw InputError(invalid_option) for values its generator refuses.
  std::function<TriMesh(const SwatchSettings&)> make;
  //! The numeric options' values under a preset, for help texts.
  std::function<std::map<std::string, double>(const std::string& preset)> defaults;
  //! An animated kind's frames of one cycle (same vertices and faces in each); empty otherwise.
  std::function<std::vector<TriMesh>(const SwatchSettings&, int count)> frames;
};

//! Every built-in kind, in the order the CLI lists them.
const std::vector<SwatchKind>& swatch_kinds();

//! The kind named `name`. \throw InputError(invalid_option) naming the kinds there are.
const SwatchKind& swatch_kind(const std::string& name);

//! Checks the preset and that every option given is one of the kind's, of its type (a whole
//! number for an integer) and among its choices.
//! \throw InputError(invalid_option) naming the option as {name}, or listing the kind's options.
void check_swatch_settings(const std::string& kind, const SwatchSettings& settings);

//! swatch_kind(kind).make(settings) after check_swatch_settings.
TriMesh make_builtin_swatch(const std::string& kind, const SwatchSettings& settings);

}  // namespace meshquilt
