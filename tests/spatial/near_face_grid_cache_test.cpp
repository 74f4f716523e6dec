// Nearest-face grids in files: a grid read back is the grid built, field for field; a file that
// is damaged anywhere, names another mesh or holds an inconsistent grid is never read; the
// folder keeps only the most recently used files and a folder that cannot be written costs
// only the file.
#include <gtest/gtest.h>

#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include "spatial/near_face_grid_cache.h"

namespace meshquilt {
namespace {

namespace fs = std::filesystem;

TriMesh random_soup(uint32_t seed, int faces) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> x(0.0, 2.0), z(0.0, 0.3), size(-0.2, 0.2);
  TriMesh mesh;
  for (int f = 0; f < faces; ++f) {
    const Vec3 a(x(rng), x(rng), z(rng));
    const auto base = static_cast<int32_t>(mesh.positions.size());
    mesh.positions.insert(mesh.positions.end(), {a, a + Vec3(size(rng), size(rng), size(rng)),
                                                 a + Vec3(size(rng), size(rng), size(rng))});
    mesh.triangles.push_back({base, base + 1, base + 2});
  }
  return mesh;
}

NearFaceGridRequest grouped_request(const TriMesh& mesh, uint32_t labels) {
  NearFaceGridRequest request{0.1, 0.2, 0.1, 0.5, 32, int64_t{1} << 18, {}};
  for (size_t f = 0; f < mesh.num_faces(); ++f) request.face_groups.push_back(static_cast<uint32_t>(f * 7 % labels));
  return request;
}

void expect_same(const NearFaceGrid& a, const NearFaceGrid& b) {
  EXPECT_EQ(a.origin, b.origin);
  EXPECT_EQ(a.voxel, b.voxel);
  EXPECT_EQ(a.size, b.size);
  EXPECT_EQ(a.box_low, b.box_low);
  EXPECT_EQ(a.box_high, b.box_high);
  EXPECT_EQ(a.start, b.start);
  EXPECT_EQ(a.faces, b.faces);
  EXPECT_EQ(a.near, b.near);
  EXPECT_EQ(a.reach, b.reach);
  EXPECT_EQ(a.nearest_face, b.nearest_face);
  EXPECT_EQ(a.group_start, b.group_start);
  ASSERT_EQ(a.groups.size(), b.groups.size());
  for (size_t g = 0; g < a.groups.size(); ++g) {
    EXPECT_EQ(a.groups[g].first, b.groups[g].first);
    EXPECT_EQ(a.groups[g].end, b.groups[g].end);
    EXPECT_EQ(a.groups[g].label, b.groups[g].label);
    EXPECT_EQ(a.groups[g].near, b.groups[g].near);
  }
}

// A fresh folder under the test's temporary directory.
fs::path scratch_folder(const std::string& name) {
  const fs::path folder = fs::temp_directory_path() / ("meshquilt_grid_cache_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(folder);
  return folder;
}

TEST(NearFaceGridCache, BytesReadBackAsTheGridBuilt) {
  const TriMesh mesh = random_soup(1, 300);
  const NearFaceGridRequest request = grouped_request(mesh, 5);
  const NearFaceGrid grid = request.build(mesh);
  ASSERT_GT(grid.faces.size(), 1000u);
  const std::string key = near_face_grid_key(mesh, request);
  const std::optional<NearFaceGrid> read = near_face_grid_from_bytes(near_face_grid_bytes(grid, key), key, 300, 5);
  ASSERT_TRUE(read.has_value());
  expect_same(grid, *read);
}

TEST(NearFaceGridCache, KeysNameTheMeshAndEveryArgument) {
  const TriMesh mesh = random_soup(2, 50);
  const NearFaceGridRequest request = grouped_request(mesh, 3);
  const std::string key = near_face_grid_key(mesh, request);
  EXPECT_EQ(key.size(), 32u);
  EXPECT_EQ(key, near_face_grid_key(mesh, request));
  TriMesh moved = mesh;
  moved.positions[17].z = std::nextafter(moved.positions[17].z, 1.0);
  EXPECT_NE(key, near_face_grid_key(moved, request));
  NearFaceGridRequest other = request;
  other.list_margin *= 1.5;
  EXPECT_NE(key, near_face_grid_key(mesh, other));
  other = request;
  other.max_list += 1;
  EXPECT_NE(key, near_face_grid_key(mesh, other));
  other = request;
  other.face_groups[3] = (other.face_groups[3] + 1) % 3;
  EXPECT_NE(key, near_face_grid_key(mesh, other));
}

TEST(NearFaceGridCache, DamagedOrForeignBytesAreNeverRead) {
  const TriMesh mesh = random_soup(3, 120);
  const NearFaceGridRequest request = grouped_request(mesh, 4);
  const NearFaceGrid grid = request.build(mesh);
  const std::string key = near_face_grid_key(mesh, request);
  const std::string bytes = near_face_grid_bytes(grid, key);
  ASSERT_TRUE(near_face_grid_from_bytes(bytes, key, 120, 4).has_value());
  // Another key, or a mesh with fewer faces or labels than the grid names.
  EXPECT_FALSE(near_face_grid_from_bytes(bytes, near_face_grid_key(random_soup(4, 120), request), 120, 4));
  EXPECT_FALSE(near_face_grid_from_bytes(bytes, key, 60, 4));
  EXPECT_FALSE(near_face_grid_from_bytes(bytes, key, 120, 2));
  // Every truncation, and a byte flipped anywhere (a sample of positions in every part).
  for (size_t length = 0; length < bytes.size(); length += std::max<size_t>(1, bytes.size() / 997))
    EXPECT_FALSE(near_face_grid_from_bytes(std::string_view(bytes).substr(0, length), key, 120, 4)) << length;
  EXPECT_FALSE(near_face_grid_from_bytes(bytes + '\0', key, 120, 4));
  for (size_t at = 0; at < bytes.size(); at += 1 + at / 64) {
    std::string damaged = bytes;
    damaged[at] = static_cast<char>(damaged[at] ^ 0x10);
    EXPECT_FALSE(near_face_grid_from_bytes(damaged, key, 120, 4)) << "byte " << at;
  }
}

TEST(NearFaceGridCache, InconsistentGridsAreRefusedEvenWithAGoodChecksum) {
  const TriMesh mesh = random_soup(5, 150);
  const NearFaceGridRequest request = grouped_request(mesh, 4);
  const NearFaceGrid grid = request.build(mesh);
  const std::string key = near_face_grid_key(mesh, request);
  size_t voxel = 0;  // one with two groups or more
  while (voxel + 1 < grid.group_start.size() && grid.group_start[voxel + 1] - grid.group_start[voxel] < 2) ++voxel;
  ASSERT_LT(voxel + 1, grid.group_start.size());
  const uint32_t g = grid.group_start[voxel];
  const auto refused = [&](const NearFaceGrid& bad) {
    return !near_face_grid_from_bytes(near_face_grid_bytes(bad, key), key, 150, 4).has_value();
  };
  NearFaceGrid bad = grid;
  bad.faces[grid.groups[g].first] = 150;  // no such face
  EXPECT_TRUE(refused(bad));
  bad = grid;
  std::swap(bad.groups[g].label, bad.groups[g + 1].label);  // labels out of order
  EXPECT_TRUE(refused(bad));
  bad = grid;
  bad.groups[g].end += 1;  // groups overlap
  EXPECT_TRUE(refused(bad));
  bad = grid;
  bad.start[voxel + 1] += 1;  // a list the groups do not tile
  EXPECT_TRUE(refused(bad));
  bad = grid;
  bad.near[grid.groups[g].first] = -1.0f;
  EXPECT_TRUE(refused(bad));
  bad = grid;
  bad.reach[voxel] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(refused(bad));
  bad = grid;
  bad.nearest_face[voxel] = -2;
  EXPECT_TRUE(refused(bad));
  bad = grid;
  bad.voxel = 0.0;
  EXPECT_TRUE(refused(bad));
  if (grid.groups[g].end - grid.groups[g].first >= 2) {
    bad = grid;
    std::swap(bad.near[grid.groups[g].first], bad.near[grid.groups[g].first + 1]);  // a group out of order
    bad.groups[g].near = bad.near[grid.groups[g].first];
    if (bad.near[grid.groups[g].first] != bad.near[grid.groups[g].first + 1]) EXPECT_TRUE(refused(bad));
  }
  EXPECT_FALSE(refused(grid));
}

TEST(NearFaceGridCache, AFolderBuildsOnceThenReads) {
  const fs::path folder = scratch_folder("reads");
  const TriMesh mesh = random_soup(6, 200);
  const NearFaceGridRequest request = grouped_request(mesh, 3);
  const NearFaceGrid built = request.build(mesh);
  GridSource source = GridSource::read;
  expect_same(built, cached_near_face_grid({}, mesh, request, &source));
  EXPECT_EQ(source, GridSource::built);
  expect_same(built, cached_near_face_grid(folder, mesh, request, &source));
  EXPECT_EQ(source, GridSource::written);
  const fs::path file = folder / (near_face_grid_key(mesh, request) + ".grid");
  ASSERT_TRUE(fs::is_regular_file(file));
  expect_same(built, cached_near_face_grid(folder, mesh, request, &source));
  EXPECT_EQ(source, GridSource::read);
  // A damaged file is built anew and replaced.
  {
    std::fstream stream(file, std::ios::in | std::ios::out | std::ios::binary);
    stream.seekp(static_cast<std::streamoff>(fs::file_size(file) / 2));
    stream.put('\x7f');
  }
  expect_same(built, cached_near_face_grid(folder, mesh, request, &source));
  EXPECT_EQ(source, GridSource::written);
  expect_same(built, cached_near_face_grid(folder, mesh, request, &source));
  EXPECT_EQ(source, GridSource::read);
  fs::remove_all(folder);
}

TEST(NearFaceGridCache, TheFolderKeepsTheMostRecentlyUsedFiles) {
  const fs::path folder = scratch_folder("keeps");
  std::vector<TriMesh> meshes;
  for (uint32_t k = 0; k < 4; ++k) meshes.push_back(random_soup(10 + k, 40));
  const auto file_of = [&](const TriMesh& mesh) {
    return folder / (near_face_grid_key(mesh, grouped_request(mesh, 2)) + ".grid");
  };
  GridSource source;
  cached_near_face_grid(folder, meshes[0], grouped_request(meshes[0], 2), &source, 2);
  cached_near_face_grid(folder, meshes[1], grouped_request(meshes[1], 2), &source, 2);
  // Mesh 0's file the older of the two, until mesh 0 is used again (a read): then mesh 1's is
  // the least recently used when mesh 2 comes.
  const auto now = fs::file_time_type::clock::now();
  fs::last_write_time(file_of(meshes[0]), now - std::chrono::seconds(20));
  fs::last_write_time(file_of(meshes[1]), now - std::chrono::seconds(10));
  cached_near_face_grid(folder, meshes[0], grouped_request(meshes[0], 2), &source, 2);
  EXPECT_EQ(source, GridSource::read);
  cached_near_face_grid(folder, meshes[2], grouped_request(meshes[2], 2), &source, 2);
  EXPECT_EQ(source, GridSource::written);
  EXPECT_TRUE(fs::exists(file_of(meshes[0])));
  EXPECT_FALSE(fs::exists(file_of(meshes[1])));
  EXPECT_TRUE(fs::exists(file_of(meshes[2])));
  fs::remove_all(folder);
}

TEST(NearFaceGridCache, AFolderThatCannotBeWrittenCostsOnlyTheFile) {
  const fs::path folder = scratch_folder("blocked");
  fs::create_directories(folder);
  std::ofstream(folder / "plain") << "a file, not a folder";
  const TriMesh mesh = random_soup(7, 60);
  const NearFaceGridRequest request = grouped_request(mesh, 2);
  GridSource source;
  expect_same(request.build(mesh), cached_near_face_grid(folder / "plain" / "grids", mesh, request, &source));
  EXPECT_EQ(source, GridSource::unsaved);
  fs::remove_all(folder);
}

}  // namespace
}  // namespace meshquilt
