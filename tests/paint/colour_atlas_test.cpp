// paint --atlas: colours of a refined base baked into a texture over the base's charts, read
// back through the written .glb (its JSON, its TEXCOORD_0 and its PNG, parsed here) at random
// points of the surface, where a colour linear in space must come back.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "mesh/mesh_io.h"
#include "paint/colour_atlas.h"
#include "paint/colour_image.h"
#include "render/png_encoding.h"
#include "support/surface_fixtures.h"
#include "surface/base_layout.h"

namespace meshquilt {
namespace {

glm::dvec3 colour_at(const Vec3& p) { return glm::clamp(0.5 + 0.45 * glm::dvec3(p.x, p.y, -p.z), 0.0, 1.0); }

TEST(ColourAtlas, AColourLinearInSpaceComesBackThroughTheWrittenGlb) {
  const TriMesh base = test::icosphere(2);
  const int levels = 3;
  TriMesh refined = split_faces(base, levels);
  for (const Vec3& p : refined.positions) {
    const glm::dvec3 c = 255.0 * colour_at(p);
    refined.colors.push_back({static_cast<uint8_t>(std::lround(c.x)), static_cast<uint8_t>(std::lround(c.y)),
                              static_cast<uint8_t>(std::lround(c.z))});
  }
  const ColourAtlas atlas = bake_colour_atlas(base, refined, levels, 512);
  ASSERT_GT(atlas.charts, 0);
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "mq_colour_atlas";
  std::filesystem::create_directories(dir);
  write_textured_glb(base, {atlas.face_uv, encode_png(atlas.image)}, dir / "atlas.glb");

  // The .glb as any viewer reads it: corners, their texture coordinates, the embedded PNG.
  std::ifstream in(dir / "atlas.glb", std::ios::binary);
  const std::string glb((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  uint32_t json_length = 0;
  std::memcpy(&json_length, glb.data() + 12, 4);
  const nlohmann::json gltf = nlohmann::json::parse(glb.substr(20, json_length));
  const char* bin = glb.data() + 20 + json_length + 8;
  const nlohmann::json& primitive = gltf["meshes"][0]["primitives"][0];
  ASSERT_EQ(gltf["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["index"], 0);
  const auto view_of = [&](int accessor) { return gltf["bufferViews"][gltf["accessors"][accessor]["bufferView"].get<int>()]; };
  const auto floats = [&](int accessor, int k) {
    const nlohmann::json view = view_of(accessor);
    std::vector<float> out(gltf["accessors"][accessor]["count"].get<size_t>() * k);
    std::memcpy(out.data(), bin + view["byteOffset"].get<size_t>(), out.size() * 4);
    return out;
  };
  const std::vector<float> position = floats(primitive["attributes"]["POSITION"], 3);
  const std::vector<float> uv = floats(primitive["attributes"]["TEXCOORD_0"], 2);
  const nlohmann::json index_view = view_of(primitive["indices"]);
  std::vector<uint32_t> index(gltf["accessors"][primitive["indices"].get<int>()]["count"].get<size_t>());
  std::memcpy(index.data(), bin + index_view["byteOffset"].get<size_t>(), index.size() * 4);
  ASSERT_EQ(index.size(), 3 * base.num_faces());
  const nlohmann::json image_view = gltf["bufferViews"][gltf["images"][0]["bufferView"].get<int>()];
  {
    std::ofstream png(dir / "atlas.png", std::ios::binary);
    png.write(bin + image_view["byteOffset"].get<size_t>(), image_view["byteLength"].get<std::streamsize>());
  }
  const ColourImage texture = read_colour_image(dir / "atlas.png");
  ASSERT_EQ(texture.width, 512);

  // Random points of random faces: the texture there (bilinear, as a viewer filters it) against
  // the colour of the point in space.
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int close = 0, far = 0;
  const int samples = 4000;
  for (int n = 0; n < samples; ++n) {
    const size_t f = rng() % base.num_faces();
    double a = unit(rng), b = unit(rng);
    if (a + b > 1.0) a = 1.0 - a, b = 1.0 - b;
    Vec3 p(0.0);
    glm::dvec2 t(0.0);
    const double w[3] = {1.0 - a - b, a, b};
    for (int k = 0; k < 3; ++k) {
      const uint32_t c = index[3 * f + k];
      p += w[k] * Vec3(position[3 * c], position[3 * c + 1], position[3 * c + 2]);
      t += w[k] * glm::dvec2(uv[2 * c], uv[2 * c + 1]);
    }
    const double error = glm::length(texture.sample(t * 512.0) - colour_at(p));
    close += error < 4.0 / 255.0;
    far += error > 0.1;
  }
  // Points within a texel of a chart's border read its gutter too; no point reads another chart.
  EXPECT_GT(close, samples * 95 / 100);
  EXPECT_EQ(far, 0);
}

TEST(ColourAtlas, RefusesWhatItCannotBake) {
  const TriMesh base = test::icosphere(1);
  TriMesh refined = split_faces(base, 1);
  refined.colors.assign(refined.num_vertices(), {1, 2, 3});
  EXPECT_THROW(bake_colour_atlas(base, refined, 2, 256), InputError);
  EXPECT_THROW(bake_colour_atlas(base, refined, 1, 8), InputError);
  EXPECT_NO_THROW(bake_colour_atlas(base, refined, 1, 64));
  EXPECT_THROW(write_textured_glb(base, {{}, "not a png"}, std::filesystem::temp_directory_path() / "mq_atlas.glb"), IoError);
}

}  // namespace
}  // namespace meshquilt
