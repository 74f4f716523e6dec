// Replays every seed-corpus and regression file of tests/fuzz/ through the fuzz targets' bodies
// in the normal (and the sanitizer) build: a crash found by fuzzing stays fixed.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "fuzz/fuzz_bodies.h"

namespace meshquilt::fuzz {
namespace {

using Body = void (*)(const uint8_t*, size_t);

void replay(const std::string& target, Body body) {
  limit_memory();
  size_t files = 0;
  for (const char* kind : {"corpus", "regressions"}) {
    const std::filesystem::path dir = std::filesystem::path(MESHQUILT_FUZZ_DIR) / kind / target;
    if (!std::filesystem::is_directory(dir)) continue;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
      std::ifstream in(entry.path(), std::ios::binary);
      const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
      SCOPED_TRACE(entry.path().string());
      EXPECT_NO_THROW(body(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size()));
      ++files;
    }
  }
  EXPECT_GT(files, 0u) << "no corpus for " << target;
}

TEST(FuzzCorpus, Obj) { replay("obj", obj_body); }
TEST(FuzzCorpus, Ply) { replay("ply", ply_body); }
TEST(FuzzCorpus, Off) { replay("off", off_body); }
TEST(FuzzCorpus, Stl) { replay("stl", stl_body); }
TEST(FuzzCorpus, Swatch) { replay("swatch", swatch_body); }
TEST(FuzzCorpus, Base) { replay("base", base_body); }
TEST(FuzzCorpus, Netpbm) { replay("netpbm", netpbm_body); }
TEST(FuzzCorpus, Field) { replay("field", field_body); }
TEST(FuzzCorpus, Texture) { replay("texture", texture_body); }

// The seeds are valid files: each must parse, not only not crash.
TEST(FuzzCorpus, SeedMeshesParse) {
  for (const char* target : {"obj", "ply", "off", "stl"}) {
    const std::filesystem::path dir = std::filesystem::path(MESHQUILT_FUZZ_DIR) / "corpus" / target;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
      std::ifstream in(entry.path(), std::ios::binary);
      const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
      EXPECT_NO_THROW(parse_mesh(bytes, entry.path().extension().string(), entry.path().string()));
    }
  }
}

// The field seeds not named bad_* are valid field files: each must parse.
TEST(FuzzCorpus, SeedFieldsParse) {
  const std::filesystem::path dir = std::filesystem::path(MESHQUILT_FUZZ_DIR) / "corpus" / "field";
  size_t valid = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().filename().string().rfind("bad_", 0) == 0) continue;
    std::ifstream in(entry.path(), std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_NO_THROW(parse_field(bytes, entry.path().string(), field_base())) << entry.path();
    ++valid;
  }
  EXPECT_GT(valid, 0u);
}

}  // namespace
}  // namespace meshquilt::fuzz
