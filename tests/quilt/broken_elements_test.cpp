// The clean-up pass on elements built here: open ones, ones passing through others, and ones
// passing through themselves, each removed only where the swatch's own elements are not so.
#include "quilt/broken_elements.h"

#include <gtest/gtest.h>

#include "support/boxes.h"
#include "support/torus.h"

namespace meshquilt {
namespace {

BrokenElements clean(const std::vector<TriMesh>& meshes, bool swatch_closed, bool swatch_unfolded,
                     std::vector<uint8_t>& alive) {
  std::vector<const TriMesh*> pointers;
  for (const TriMesh& m : meshes) pointers.push_back(&m);
  alive.assign(meshes.size(), 1);
  return remove_broken_elements(pointers, swatch_closed, swatch_unfolded, alive);
}

TEST(BrokenElements, WholeSeparateElementsStay) {
  std::vector<uint8_t> alive;
  const BrokenElements removed =
      clean({test::torus(1.0, 0.3), test::box(Vec3(3.0), Vec3(4.0))}, true, true, alive);
  EXPECT_EQ(alive, (std::vector<uint8_t>{1, 1}));
  EXPECT_EQ(removed.open + removed.folded + removed.intersecting, 0);
}

TEST(BrokenElements, AnElementPassingThroughItselfGoesWhereTheSwatchsDoNot) {
  std::vector<uint8_t> alive;
  const BrokenElements removed = clean({test::torus(1.0, 0.3), test::folded_torus()}, true, true, alive);
  EXPECT_EQ(alive, (std::vector<uint8_t>{1, 0}));
  EXPECT_EQ(removed.folded, 1);
  EXPECT_EQ(removed.open, 0);
}

TEST(BrokenElements, ASwatchThatPassesThroughItselfKeepsSuchElements) {
  std::vector<uint8_t> alive;
  const BrokenElements removed = clean({test::folded_torus()}, true, false, alive);
  EXPECT_EQ(alive, (std::vector<uint8_t>{1}));
  EXPECT_EQ(removed.folded, 0);
}

TEST(BrokenElements, OpenElementsGoOnlyWhereTheSwatchIsClosed) {
  std::vector<uint8_t> alive;
  const std::vector<TriMesh> meshes{test::open_box(Vec3(0.0), Vec3(1.0)), test::box(Vec3(2.0), Vec3(3.0))};
  EXPECT_EQ(clean(meshes, true, true, alive).open, 1);
  EXPECT_EQ(alive, (std::vector<uint8_t>{0, 1}));
  EXPECT_EQ(clean(meshes, false, true, alive).open, 0);
  EXPECT_EQ(alive, (std::vector<uint8_t>{1, 1}));
}

TEST(BrokenElements, OfElementsPassingThroughEachOtherTheOneMeetingMostGoes) {
  // The long box crosses both small ones; they do not meet each other.
  std::vector<uint8_t> alive;
  const std::vector<TriMesh> meshes{test::box(Vec3(0.0), Vec3(1.0)),
                                    test::box(Vec3(-0.5, 0.4, 0.4), Vec3(3.5, 0.6, 0.6)),
                                    test::box(Vec3(2.0, 0.0, 0.0), Vec3(3.0, 1.0, 1.0))};
  const BrokenElements removed = clean(meshes, true, true, alive);
  EXPECT_EQ(alive, (std::vector<uint8_t>{1, 0, 1}));
  EXPECT_EQ(removed.intersecting, 1);
  EXPECT_GT(removed.intersecting_face_pairs, 0);
}

}  // namespace
}  // namespace meshquilt
