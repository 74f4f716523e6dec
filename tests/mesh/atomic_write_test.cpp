// Crash-safe writes in-process: the temporary file beside the target, no stray temporaries
// after an error or a cancellation, the old file untouched until the rename.
#include <gtest/gtest.h>

#include <filesystem>

#include "core/error.h"
#include "core/atomic_write.h"
#include "mesh/mesh_io.h"
#include "support/run_cli.h"

namespace meshquilt {
namespace {

using test::read_file;
using test::scratch_dir;
using test::write_file;

size_t count_files(const std::filesystem::path& dir) {
  size_t n = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir)) ++n;
  return n;
}

TriMesh tetrahedron() {
  TriMesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 0.3}};
  mesh.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  return mesh;
}

TEST(AtomicWrite, ReplacesTheFileAndLeavesNothingElse) {
  const auto dir = scratch_dir("atomic_replace");
  write_file(dir / "out.txt", "old");
  write_file_atomic(dir / "out.txt", "new content");
  EXPECT_EQ(read_file(dir / "out.txt"), "new content");
  EXPECT_EQ(count_files(dir), 1u);
}

TEST(AtomicWrite, FailedRenameRemovesTheTemporary) {
  const auto dir = scratch_dir("atomic_failed_rename");
  std::filesystem::create_directories(dir / "target" / "inside");  // a non-empty folder cannot be replaced
  try {
    write_file_atomic(dir / "target", "data");
    FAIL() << "accepted";
  } catch (const IoError& e) {
    EXPECT_EQ(e.kind(), ErrorKind::write_failed);
    EXPECT_NE(std::string(e.what()).find("target"), std::string::npos);
  }
  EXPECT_EQ(count_files(dir), 1u);  // only the folder
}

TEST(AtomicWrite, MissingFolderFailsCleanly) {
  const auto dir = scratch_dir("atomic_missing_folder");
  EXPECT_THROW(write_file_atomic(dir / "no" / "out.txt", "data"), IoError);
  EXPECT_EQ(count_files(dir), 0u);
}

TEST(AtomicWrite, CancelledWriteLeavesTheOldFile) {
  const auto dir = scratch_dir("atomic_cancel");
  write_file(dir / "out.ply", "previous");
  CancelToken token;
  token.cancel();
  WriteOptions options;
  options.cancel = &token;
  EXPECT_THROW(write_mesh(tetrahedron(), dir / "out.ply", options), Cancelled);
  EXPECT_EQ(read_file(dir / "out.ply"), "previous");
  EXPECT_EQ(count_files(dir), 1u);
}

TEST(AtomicWrite, MeshWriterRoundTrips) {
  const auto dir = scratch_dir("atomic_mesh");
  write_mesh(tetrahedron(), dir / "out.off");
  EXPECT_EQ(read_mesh(dir / "out.off").num_faces(), 4u);
  EXPECT_EQ(count_files(dir), 1u);
}

TEST(AtomicWrite, PendingTemporariesAreRemovedOnRequest) {
  // Nothing pending: a no-op that must not touch other files.
  const auto dir = scratch_dir("atomic_pending");
  write_file(dir / "keep.txt", "x");
  remove_pending_temporaries();
  EXPECT_EQ(count_files(dir), 1u);
}

}  // namespace
}  // namespace meshquilt
