// The registry of built-in swatch kinds: what every front end reads.
#include "swatch/swatch_kinds.h"

#include <gtest/gtest.h>

#include <set>

#include "core/error.h"
#include "mesh/topology.h"

namespace meshquilt {
namespace {

TEST(SwatchKinds, EveryKindIsWellFormedAndBuildsItsSmallPreset) {
  std::set<std::string> names;
  for (const SwatchKind& kind : swatch_kinds()) {
    EXPECT_TRUE(names.insert(kind.name).second) << kind.name;
    EXPECT_FALSE(kind.help.empty()) << kind.name;
    std::set<std::string> options;
    for (const SwatchOption& o : kind.options) {
      EXPECT_TRUE(options.insert(o.name).second) << kind.name << " " << o.name;
      EXPECT_FALSE(o.help.empty()) << kind.name << " " << o.name;
      const bool numeric = o.type == SwatchOption::Type::integer || o.type == SwatchOption::Type::real;
      EXPECT_EQ(kind.defaults("default").count(o.name), numeric ? 1u : 0u) << kind.name << " " << o.name;
    }
    SwatchSettings settings;
    settings.preset = "small";
    const TriMesh mesh = make_builtin_swatch(kind.name, settings);
    EXPECT_GT(mesh.num_faces(), 0u) << kind.name;
    EXPECT_LE(mesh.num_faces(), 20000u) << kind.name << ": the small preset is test-sized";
  }
  EXPECT_EQ(names, (std::set<std::string>{"chainmail", "weave", "wire", "fruit", "vine", "nuts", "heightfield"}));
}

TEST(SwatchKinds, OptionsGivenChangeWhatTheySay) {
  SwatchSettings settings;
  settings.preset = "small";
  const TriMesh two = make_builtin_swatch("fruit", settings);
  settings.numbers["columns"] = 2 * swatch_kind("fruit").defaults("small").at("columns");
  const TriMesh four = make_builtin_swatch("fruit", settings);
  int32_t before = 0, after = 0;
  face_components(two, &before);
  face_components(four, &after);
  EXPECT_EQ(after, 2 * before);
}

TEST(SwatchKinds, BadSettingsAreRefusedByName) {
  auto refusal = [](const std::string& kind, const SwatchSettings& s) {
    try {
      make_builtin_swatch(kind, s);
    } catch (const InputError& e) {
      EXPECT_EQ(e.kind(), ErrorKind::invalid_option);
      return e.text();
    }
    ADD_FAILURE() << kind << ": not refused";
    return std::string();
  };
  SwatchSettings unknown;
  unknown.numbers["colour"] = 3;
  EXPECT_NE(refusal("chainmail", unknown).find("unknown option 'colour' (rows, columns"), std::string::npos);
  SwatchSettings half;
  half.numbers["rows"] = 2.5;
  EXPECT_EQ(refusal("chainmail", half).rfind("{rows}: expected a whole number", 0), 0u);
  SwatchSettings choice;
  choice.texts["only"] = "diagonal";
  EXPECT_EQ(refusal("weave", choice).rfind("{only}: unknown value 'diagonal'", 0), 0u);
  SwatchSettings preset;
  preset.preset = "huge";
  EXPECT_EQ(refusal("nuts", preset).rfind("{preset}", 0), 0u);
  EXPECT_THROW(swatch_kind("teapot"), InputError);
}

}  // namespace
}  // namespace meshquilt
