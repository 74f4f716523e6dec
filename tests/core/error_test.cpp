// Error texts name parameters as {name}; what() spells them plainly and a caller may respell them.
#include <gtest/gtest.h>

#include <string>

#include "core/error.h"

namespace meshquilt {
namespace {

std::string as_option(const std::string& text) {
  return Error::render(text, [](std::string name) {
    for (char& c : name)
      if (c == '_') c = '-';
    return "--" + name;
  });
}

TEST(Error, ParametersReadPlainlyInWhat) {
  const OptionError e("chainmail: {pitch_x} and {pitch_y} must be positive");
  EXPECT_EQ(std::string(e.what()), "chainmail: pitch_x and pitch_y must be positive");
  EXPECT_EQ(e.text(), "chainmail: {pitch_x} and {pitch_y} must be positive");
  EXPECT_EQ(e.kind(), ErrorKind::invalid_option);
}

TEST(Error, RenderRespellsOnlyParameterNames) {
  EXPECT_EQ(as_option("{max_memory}: expected a size"), "--max-memory: expected a size");
  EXPECT_EQ(as_option("a {b2} c {d_e}"), "a --b2 c --d-e");
  // Braces around anything else are part of the message (a JSON excerpt, a set, an empty pair).
  for (const char* kept : {"field.json: unexpected '{' at {\"a\": 1}", "{}", "{A}", "{1x}", "{a b}", "{open", "x}"})
    EXPECT_EQ(as_option(kept), kept);
  EXPECT_EQ(as_option("{a}{b}"), "--a--b");
}

}  // namespace
}  // namespace meshquilt
