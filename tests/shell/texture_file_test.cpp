// The texture-space file: version 2 keeps each vertex's swatch vertex; version 1 files, written
// before it, are still read (without origins). The version 1 bytes are built here by hand.
#include "shell/texture_file.h"

#include <gtest/gtest.h>

#include <cstring>

#include "core/error.h"
#include "support/run_cli.h"

namespace meshquilt {
namespace {

QuiltTexture one_triangle() {
  QuiltTexture t;
  t.base_vertices = 3;
  t.base_faces = 1;
  t.base_connectivity = 42;
  for (int k = 0; k < 3; ++k)
    t.vertices.push_back(LocalVertex{SurfacePoint{0, glm::dvec2(0.25 * k, 0.125)}, 0.5 * k});
  t.triangles = {{0, 1, 2}};
  t.elements = {7};
  t.sources = {3};
  t.origins = {11, -1, 5};
  return t;
}

uint64_t fnv1a(const std::string& bytes) {
  uint64_t hash = 0xcbf29ce484222325ull;
  for (unsigned char c : bytes) hash = (hash ^ c) * 0x100000001b3ull;
  return hash;
}

TEST(TextureFile, Version2KeepsOrigins) {
  const auto dir = test::scratch_dir("texture_file");
  write_texture_file(dir / "t.mqt", one_triangle());
  const std::string bytes = test::read_file(dir / "t.mqt");
  EXPECT_EQ(bytes.substr(0, 11), "MQTEXTURE2\n");
  const QuiltTexture back = parse_texture(bytes, "t.mqt");
  EXPECT_EQ(back.origins, (std::vector<int32_t>{11, -1, 5}));
  EXPECT_EQ(back.elements, std::vector<int32_t>{7});
  EXPECT_EQ(back.vertices[2].height, 1.0);
}

TEST(TextureFile, Version1IsStillReadWithoutOrigins) {
  const auto dir = test::scratch_dir("texture_file_v1");
  write_texture_file(dir / "t.mqt", one_triangle());
  std::string bytes = test::read_file(dir / "t.mqt");
  // Version 1: the other magic, no origins (3 x i32 before the checksum), its own checksum.
  bytes = "MQTEXTURE1\n" + bytes.substr(11, bytes.size() - 11 - 8 - 12);
  const uint64_t sum = fnv1a(bytes);
  bytes.append(reinterpret_cast<const char*>(&sum), 8);
  const QuiltTexture v1 = parse_texture(bytes, "v1.mqt");
  EXPECT_TRUE(v1.origins.empty());
  EXPECT_EQ(v1.sources, std::vector<int32_t>{3});
  EXPECT_EQ(v1.triangles, (std::vector<Tri>{{0, 1, 2}}));
  // A version 2 header over version 1 bytes is refused, not misread.
  std::string mislabelled = bytes;
  mislabelled[9] = '2';
  EXPECT_THROW(parse_texture(mislabelled, "mislabelled.mqt"), InputError);
}

}  // namespace
}  // namespace meshquilt
