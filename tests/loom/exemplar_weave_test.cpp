#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "loom/exemplar_weave.h"
#include "swatch/chainmail.h"
#include "swatch/weave.h"

namespace meshquilt {
namespace {

WeaveOptions weave_of(const WeavePattern& pattern) {
  WeaveOptions o = WeaveOptions::small();
  o.pattern = pattern;
  o.warps = 2 * pattern.warps;
  o.wefts = 2 * pattern.wefts;
  return o;
}

void expect_pattern(const ExemplarWeave& found, const WeaveOptions& o) {
  const glm::ivec2 counts = weave_yarn_counts(o);
  ASSERT_EQ(found.pattern.warps, counts.x);
  ASSERT_EQ(found.pattern.wefts, counts.y);
  for (int j = 0; j < counts.y; ++j)
    for (int i = 0; i < counts.x; ++i) EXPECT_EQ(found.pattern.over(i, j), o.pattern.over(i, j)) << i << ", " << j;
}

TEST(ExemplarWeave, ReadsTheGeneratorsPatternAtEveryCrossing) {
  for (const WeavePattern& pattern : {twill_pattern(1, 1), twill_pattern(2, 2), twill_pattern(2, 1), satin_pattern(3, 2)}) {
    const WeaveOptions o = weave_of(pattern);
    const ExemplarWeave found = register_exemplar(make_weave(o), "w.ply");
    expect_pattern(found, o);
    EXPECT_NEAR(found.pitch.x, o.pitch, 1e-9);
    EXPECT_NEAR(found.pitch.y, o.pitch, 1e-9);
    EXPECT_NEAR(found.origin.x, 0.5 * o.pitch, 1e-9);
    EXPECT_NEAR(found.tilt, 0.0, 1e-9);
    EXPECT_NEAR(found.yarn_radius, o.yarn_radius, 0.1 * o.yarn_radius);
  }
}

TEST(ExemplarWeave, RegistersATurnedAndMovedExemplar) {
  const WeaveOptions o = weave_of(twill_pattern(2, 2));
  TriMesh mesh = make_weave(o);
  const double angle = 0.35;  // about 20 degrees
  for (Vec3& p : mesh.positions)
    p = Vec3(std::cos(angle) * p.x - std::sin(angle) * p.y + 7.0, std::sin(angle) * p.x + std::cos(angle) * p.y - 3.0,
             p.z + 1.0);
  const ExemplarWeave found = register_exemplar(mesh, "turned.ply");
  EXPECT_NEAR(found.tilt, angle, 1e-3);
  EXPECT_NEAR(found.pitch.x, o.pitch, 1e-6);
  expect_pattern(found, o);
}

TEST(ExemplarWeave, RefusesWhatIsNotAWeaveByName) {
  ChainmailOptions mail;
  try {
    register_exemplar(make_chainmail(mail), "mail.ply");
    FAIL() << "chain mail registered as a weave";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("mail.ply"), std::string::npos) << e.what();
    EXPECT_EQ(e.kind(), ErrorKind::invalid_mesh);
  }
  // A weave with a warp missing in the middle: the spacing breaks.
  const WeaveOptions o = weave_of(twill_pattern(1, 1));
  TriMesh mesh = make_weave(o);
  TriMesh holed;
  holed.positions = mesh.positions;
  for (size_t f = 0; f < mesh.num_faces(); ++f)
    if (mesh.elements[f] != 2) {
      holed.triangles.push_back(mesh.triangles[f]);
      holed.elements.push_back(mesh.elements[f]);
    }
  EXPECT_THROW(register_exemplar(holed, "holed.ply"), InputError);
}

}  // namespace
}  // namespace meshquilt
