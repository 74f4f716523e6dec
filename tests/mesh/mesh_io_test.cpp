// Mesh I/O: round trips for every format, hand-written files for each parser rule, OpenMesh as an
// independent reference reader, and garbage / truncated input that must fail cleanly.

#include <gtest/gtest.h>

#include <optional>
#include <glm/common.hpp>
#include <unistd.h>

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <bit>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <string>

#include "core/error.h"
#include "mesh/mesh_io.h"
#include "mesh/validation.h"

namespace meshquilt {
namespace {

namespace fs = std::filesystem;

class MeshIoTest : public ::testing::Test {
 protected:
  void SetUp() override {
    // tmpfs when there is one: these tests write many small files.
    const fs::path base = fs::is_directory("/dev/shm") ? fs::path("/dev/shm") : fs::temp_directory_path();
    dir_ = base /
           ("meshquilt_mesh_io_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path path(const std::string& name) const { return dir_ / name; }
  fs::path write_text(const std::string& name, const std::string& content) const {
    const fs::path p = path(name);
    std::ofstream(p, std::ios::binary) << content;
    return p;
  }
  size_t files_in_dir() const {
    return static_cast<size_t>(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()));
  }

  fs::path dir_;
};

// Two tetrahedra with coordinates that do not print exactly in few digits, elements 3 and 7.
TriMesh two_tetrahedra() {
  TriMesh m;
  m.positions = {{0.1, 1.0 / 3.0, -2.5e-7}, {1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, 1.0},
                 {5.0, 5.0, 5.0},           {6.0, 5.0, 5.0}, {5.0, 6.0, 5.0}, {5.0, 5.0, 6.123456789012345}};
  m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}, {4, 6, 5}, {4, 5, 7}, {4, 7, 6}, {5, 6, 7}};
  m.elements = {3, 3, 3, 3, 7, 7, 7, 7};
  return m;
}

void expect_same_mesh(const TriMesh& a, const TriMesh& b, bool with_elements) {
  ASSERT_EQ(a.positions.size(), b.positions.size());
  ASSERT_EQ(a.triangles.size(), b.triangles.size());
  for (size_t v = 0; v < a.positions.size(); ++v) EXPECT_EQ(a.positions[v], b.positions[v]) << "vertex " << v;
  for (size_t f = 0; f < a.triangles.size(); ++f) EXPECT_EQ(a.triangles[f], b.triangles[f]) << "face " << f;
  if (with_elements) {
    EXPECT_EQ(a.elements, b.elements);
  } else {
    EXPECT_TRUE(b.elements.empty());
  }
}

template <typename F>
std::optional<ErrorKind> code_of(F&& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.kind();
  }
  return std::nullopt;
}

TEST_F(MeshIoTest, RoundTripsExactlyWithElements) {
  const TriMesh mesh = two_tetrahedra();
  for (bool binary : {true, false}) {
    const fs::path p = path(binary ? "b.ply" : "a.ply");
    write_mesh(mesh, p, WriteOptions{binary});
    expect_same_mesh(mesh, read_mesh(p), true);
  }
  write_mesh(mesh, path("m.obj"));
  expect_same_mesh(mesh, read_mesh(path("m.obj")), true);
  write_mesh(mesh, path("m.off"));
  expect_same_mesh(mesh, read_mesh(path("m.off")), false);
}

TEST_F(MeshIoTest, PlyKeepsVertexColoursAndReadsFloatOnes) {
  TriMesh mesh = two_tetrahedra();
  for (size_t v = 0; v < mesh.num_vertices(); ++v)
    mesh.colors.push_back({static_cast<uint8_t>(30 * v), static_cast<uint8_t>(255 - v), 7});
  for (bool binary : {true, false}) {
    const fs::path p = path(binary ? "cb.ply" : "ca.ply");
    write_mesh(mesh, p, WriteOptions{binary});
    const TriMesh back = read_mesh(p);
    expect_same_mesh(mesh, back, true);
    EXPECT_EQ(back.colors, mesh.colors);
  }
  const std::string floats =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "property float r\nproperty float g\nproperty float b\nelement face 1\nproperty list uchar int vertex_indices\n"
      "end_header\n0 0 0 1 0.5 0\n1 0 0 0 0 0\n0 1 0 0.2 0.2 1\n3 0 1 2\n";
  const TriMesh m = parse_mesh(floats, ".ply", "floats.ply");
  ASSERT_EQ(m.colors.size(), 3u);
  EXPECT_EQ(m.colors[0], (std::array<uint8_t, 3>{255, 128, 0}));
  EXPECT_EQ(m.colors[2], (std::array<uint8_t, 3>{51, 51, 255}));
}

TEST_F(MeshIoTest, StlRoundTripKeepsFloatPositionsAndSharesVertices) {
  const TriMesh mesh = two_tetrahedra();
  for (bool binary : {true, false}) {
    const fs::path p = path(binary ? "b.stl" : "a.stl");
    write_mesh(mesh, p, WriteOptions{binary});
    const TriMesh back = read_mesh(p);
    ASSERT_EQ(back.triangles.size(), mesh.triangles.size());
    EXPECT_EQ(back.positions.size(), mesh.positions.size());  // identical corners are shared again
    EXPECT_TRUE(back.elements.empty());
    for (size_t f = 0; f < mesh.triangles.size(); ++f) {
      for (int c = 0; c < 3; ++c) {
        const Vec3 expected = mesh.positions[mesh.triangles[f][c]];
        const Vec3 got = back.positions[back.triangles[f][c]];
        const double tolerance = binary ? 1e-6 : 0.0;  // binary STL stores floats
        EXPECT_NEAR(got.x, expected.x, tolerance * std::abs(expected.x) + 1e-12);
        EXPECT_NEAR(got.y, expected.y, tolerance * std::abs(expected.y) + 1e-12);
        EXPECT_NEAR(got.z, expected.z, tolerance * std::abs(expected.z) + 1e-12);
      }
    }
  }
}

TEST_F(MeshIoTest, WriteLeavesNoTemporaryAndOverwrites) {
  TriMesh mesh = two_tetrahedra();
  write_mesh(mesh, path("out.ply"));
  mesh.positions[0].x = 42.0;
  write_mesh(mesh, path("out.ply"));
  EXPECT_EQ(read_mesh(path("out.ply")).positions[0].x, 42.0);
  EXPECT_EQ(files_in_dir(), 1u);
}

TEST_F(MeshIoTest, WriteFailuresAreTypedAndClean) {
  const TriMesh mesh = two_tetrahedra();
  EXPECT_EQ(code_of([&] { write_mesh(mesh, path("missing_dir") / "out.ply"); }), ErrorKind::write_failed);
  EXPECT_EQ(code_of([&] { write_mesh(mesh, path("out.xyz")); }), ErrorKind::unknown_format);
  // The target is a non-empty directory: the rename fails, the directory survives, no temp is left.
  fs::create_directories(path("taken.obj") / "inside");
  EXPECT_EQ(code_of([&] { write_mesh(mesh, path("taken.obj")); }), ErrorKind::write_failed);
  EXPECT_TRUE(fs::is_directory(path("taken.obj") / "inside"));
  EXPECT_EQ(files_in_dir(), 1u);
  TriMesh bad = mesh;
  bad.elements.pop_back();
  EXPECT_EQ(code_of([&] { write_mesh(bad, path("bad.ply")); }), ErrorKind::write_failed);
  EXPECT_FALSE(fs::exists(path("bad.ply")));
}

TEST_F(MeshIoTest, ObjIndexFormsNegativeIndicesAndPolygons) {
  const fs::path p = write_text("forms.obj",
                                "# comment\n"
                                "mtllib x.mtl\n"
                                "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                "vt 0 0\nvt 1 0\nvn 0 0 1\n"
                                "\n"
                                "g some_part\n"
                                "usemtl red\n"
                                "f 1/1/1 2/2/1 3//1 4/1\n"  // quad: fanned from its first vertex
                                "v 2 0 0  \r\n"
                                "f -4 -1 -3\n"  // vertices 2 5 3 after resolving against 5 vertices
                                "s off\n"
                                "l 1 2\n");
  const TriMesh m = read_mesh(p);
  ASSERT_EQ(m.positions.size(), 5u);
  EXPECT_EQ(m.positions[4], Vec3(2, 0, 0));
  const std::vector<Tri> expected = {{0, 1, 2}, {0, 2, 3}, {1, 4, 2}};
  EXPECT_EQ(m.triangles, expected);
  EXPECT_TRUE(m.elements.empty());  // groups not named element_N carry no element ids
}

TEST_F(MeshIoTest, ObjElementGroupsOnlyWhenEveryFaceIsInOne) {
  const std::string vertices = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n";
  const TriMesh all = read_mesh(write_text("all.obj", vertices + "g element_4\nf 1 2 3\ng element_1\nf 1 2 4\nf 2 3 4\n"));
  EXPECT_EQ(all.elements, (std::vector<int32_t>{4, 1, 1}));
  const TriMesh some = read_mesh(write_text("some.obj", vertices + "f 1 2 3\ng element_1\nf 1 2 4\n"));
  EXPECT_TRUE(some.elements.empty());
  const TriMesh other = read_mesh(write_text("other.obj", vertices + "g element_1\nf 1 2 3\ng lid\nf 1 2 4\n"));
  EXPECT_TRUE(other.elements.empty());
}

TEST_F(MeshIoTest, OffVariants) {
  // Counts on the keyword line, comments, blank lines, double spaces, a quad, face colours.
  const TriMesh a = read_mesh(write_text("a.off",
                                         "OFF 5 2 0 # counts here\n"
                                         "# a comment\n\n"
                                         "0  0 0\n1 0  0\n\n1 1 0\n0 1 0\n0.5 0.5 1e-1\n"
                                         "4  0 1 2 3  255 0 0\n"
                                         "3 0 1 4\n"));
  ASSERT_EQ(a.positions.size(), 5u);
  EXPECT_EQ(a.positions[4], Vec3(0.5, 0.5, 0.1));
  EXPECT_EQ(a.triangles, (std::vector<Tri>{{0, 1, 2}, {0, 2, 3}, {0, 1, 4}}));

  // COFF as CGAL writes it: RGBA after each vertex.
  const TriMesh c = read_mesh(write_text("c.off",
                                         "COFF\n3 1 0\n"
                                         "-0.25 0 -0.5 192 192 192 255 \n"
                                         "0.25 0 -0.5 192 192 192 255 \n"
                                         "0 0 0.5 192 192 192 255 \n"
                                         "3  0 1 2\n"));
  EXPECT_EQ(c.positions, (std::vector<Vec3>{{-0.25, 0, -0.5}, {0.25, 0, -0.5}, {0, 0, 0.5}}));
  EXPECT_EQ(c.triangles, (std::vector<Tri>{{0, 1, 2}}));

  // NOFF (normals) and CNOFF (normals, then colours), counts on their own line after a comment.
  const TriMesh n = read_mesh(write_text("n.off", "NOFF\n# c\n3 1 3\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n3 2 1 0\n"));
  EXPECT_EQ(n.positions[1], Vec3(1, 0, 0));
  EXPECT_EQ(n.triangles, (std::vector<Tri>{{2, 1, 0}}));
  const TriMesh cn =
      read_mesh(write_text("cn.off", "CNOFF 3 1 0\n0 0 7 0 0 1 1 0 0 1\n1 0 7 0 0 1 1 0 0 1\n0 1 7 0 0 1 1 0 0 1\n3 0 1 2\n"));
  EXPECT_EQ(cn.positions[2], Vec3(0, 1, 7));
}

// Big- or little-endian PLY bytes written here, independently of the writer under test.
struct PlyBytes {
  bool big = true;
  std::string data;
  template <typename T>
  void put(T value) {
    char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    if (big == (std::endian::native == std::endian::little)) std::reverse(bytes, bytes + sizeof(T));
    data.append(bytes, sizeof(T));
  }
};

std::string binary_ply(bool big) {
  PlyBytes b;
  b.big = big;
  b.data =
      std::string("ply\r\nformat ") + (big ? "binary_big_endian" : "binary_little_endian") +
      " 1.0\ncomment mixed types\nobj_info x\n"
      "element vertex 4\nproperty float x\nproperty uchar red\nproperty double y\nproperty list uchar float extra\n"
      "property float z\n"
      "element edge 1\nproperty int vertex1\nproperty int vertex2\n"
      "element face 2\nproperty list uchar float texcoord\nproperty list uint8 uint32 vertex_indices\n"
      "property short element\n"
      "end_header\n";
  const double ys[4] = {0.0, 0.0, 1.0, 1.0};
  const float xs[4] = {0.f, 1.f, 1.f, 0.f};
  for (int v = 0; v < 4; ++v) {
    b.put(xs[v]);
    b.put(uint8_t(200));
    b.put(ys[v]);
    b.put(uint8_t(v % 3));  // variable-length list to skip
    for (int k = 0; k < v % 3; ++k) b.put(float(k));
    b.put(float(v) * 0.5f);
  }
  b.put(int32_t(0));
  b.put(int32_t(1));
  // Face 0: a quad; face 1: a triangle.
  b.put(uint8_t(2));
  b.put(0.5f);
  b.put(0.25f);
  b.put(uint8_t(4));
  for (uint32_t i : {0u, 1u, 2u, 3u}) b.put(i);
  b.put(int16_t(9));
  b.put(uint8_t(0));
  b.put(uint8_t(3));
  for (uint32_t i : {3u, 2u, 1u}) b.put(i);
  b.put(int16_t(2));
  return b.data;
}

void expect_binary_ply_content(const TriMesh& m) {
  ASSERT_EQ(m.positions.size(), 4u);
  EXPECT_EQ(m.positions[1], Vec3(1, 0, 0.5));
  EXPECT_EQ(m.positions[3], Vec3(0, 1, 1.5));
  EXPECT_EQ(m.triangles, (std::vector<Tri>{{0, 1, 2}, {0, 2, 3}, {3, 2, 1}}));
  EXPECT_EQ(m.elements, (std::vector<int32_t>{9, 9, 2}));
}

TEST_F(MeshIoTest, BinaryPlyBothEndiansSkipsUnknownProperties) {
  expect_binary_ply_content(read_mesh(write_text("big.ply", binary_ply(true))));
  expect_binary_ply_content(read_mesh(write_text("little.ply", binary_ply(false))));
}

TEST_F(MeshIoTest, AsciiPlyWithExtraElementsAndProperties) {
  const TriMesh m = read_mesh(write_text("a.ply",
                                         "ply\nformat ascii 1.0\ncomment x\n"
                                         "element vertex 3\nproperty double x\nproperty double y\nproperty double z\n"
                                         "property list uchar int friends\nproperty uchar red\n"
                                         "element material 1\nproperty float shine\n"
                                         "element face 1\nproperty list uchar int vertex_index\nproperty uint element\n"
                                         "end_header\n"
                                         "0 0 0 2 1 2 255\n1 0 0 0 255\n0 1 0 1 0 255\n"
                                         "0.5\n"
                                         "3 0 1 2 12\n"));
  EXPECT_EQ(m.positions[2], Vec3(0, 1, 0));
  EXPECT_EQ(m.triangles, (std::vector<Tri>{{0, 1, 2}}));
  EXPECT_EQ(m.elements, (std::vector<int32_t>{12}));
}

TEST_F(MeshIoTest, StlAsciiAndBinaryShareCorners) {
  const TriMesh a = read_mesh(write_text("a.stl",
                                         "solid square\n"
                                         "  facet normal 0 0 1\n    outer loop\n"
                                         "      vertex 0 0 0\n      vertex 1 0 0\n      vertex 1 1 0\n"
                                         "    endloop\n  endfacet\n"
                                         "  facet normal 0 0 1\n    outer loop\n"
                                         "      vertex 0 0 0\n      vertex 1 1 0\n      vertex 0 1 0\n"
                                         "    endloop\n  endfacet\n"
                                         "endsolid square\n"));
  ASSERT_EQ(a.positions.size(), 4u);
  EXPECT_EQ(a.triangles, (std::vector<Tri>{{0, 1, 2}, {0, 2, 3}}));

  // Binary STL whose header starts with "solid" (some exporters do this): the size decides.
  PlyBytes b;
  b.big = false;
  b.data = "solid but binary";
  b.data.resize(80, '\0');
  b.put(uint32_t(2));
  const float corners[2][3][3] = {{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}, {{0, 0, 0}, {1, 1, 0}, {0, 1, 0}}};
  for (const auto& face : corners) {
    for (int k = 0; k < 3; ++k) b.put(0.f);
    for (const auto& c : face) {
      for (float x : c) b.put(x);
    }
    b.put(uint16_t(0));
  }
  const TriMesh m = read_mesh(write_text("b.stl", b.data));
  ASSERT_EQ(m.positions.size(), 4u);
  EXPECT_EQ(m.triangles, a.triangles);
  EXPECT_EQ(m.positions, a.positions);
  // Trailing bytes are tolerated when the header cannot be ASCII; with "solid" they are an error.
  std::string other = b.data + "trailing";
  other.replace(0, 5, "xxxxx");
  EXPECT_EQ(read_mesh(write_text("c.stl", other)).triangles, a.triangles);
  EXPECT_THROW(read_mesh(write_text("d.stl", b.data + "trailing")), InputError);
}

TEST_F(MeshIoTest, OpenErrorsAndFormatErrors) {
  EXPECT_EQ(code_of([&] { read_mesh(path("nothing.obj")); }), ErrorKind::file_unreadable);
  fs::create_directories(path("dir.obj"));
  EXPECT_EQ(code_of([&] { read_mesh(path("dir.obj")); }), ErrorKind::file_unreadable);
  EXPECT_EQ(code_of([&] { read_mesh(write_text("x.3ds", "v 0 0 0")); }), ErrorKind::unknown_format);
  EXPECT_EQ(code_of([&] { read_mesh(write_text("upper.OBJ", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")); }), std::nullopt);
  try {
    read_mesh(path("nothing.obj"));
  } catch (const IoError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(path("nothing.obj").string() + ": cannot open: ", 0), 0u) << e.what();
  }
}

TEST_F(MeshIoTest, InvalidContentIsInputError) {
  const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"empty.obj", ""},
      {"empty.ply", ""},
      {"empty.off", ""},
      {"empty.stl", ""},
      {"nofaces.obj", tri},
      {"index.obj", tri + "f 1 2 4\n"},
      {"zero.obj", tri + "f 0 1 2\n"},
      {"negative.obj", tri + "f -1 -2 -4\n"},
      {"two.obj", tri + "f 1 2\n"},
      {"token.obj", tri + "f 1 2 x\n"},
      {"coord.obj", "v 0 0 zz\n"},
      {"nan.obj", "v 0 0 nan\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"},
      {"inf.off", "OFF\n3 1 0\n0 0 inf\n1 0 0\n0 1 0\n3 0 1 2\n"},
      {"short.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n"},
      {"range.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n"},
      {"two.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n"},
      {"huge.off", "OFF\n2000000000 2000000000 0\n0 0 0\n"},
      {"binary.off", "OFF BINARY\n"},
      {"noend.ply", "ply\nformat ascii 1.0\nelement vertex 3\n"},
      {"noformat.ply", "ply\nelement vertex 0\nend_header\n"},
      {"huge.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\nproperty float x\n"
                   "property float y\nproperty float z\nelement face 4000000000\n"
                   "property list uchar int vertex_indices\nend_header\n\x01\x02"},
      {"asciirange.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                         "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                         "0 0 0\n1 0 0\n0 1 0\n3 0 1 -1\n"},
      {"text.stl", "hello world"},
      {"open.stl", "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"},
  };
  for (const auto& [name, content] : cases) {
    const fs::path p = write_text(name, content);
    try {
      read_mesh(p);
      ADD_FAILURE() << name << ": no error";
    } catch (const InputError& e) {
      EXPECT_EQ(e.kind(), ErrorKind::invalid_mesh) << name;
      EXPECT_EQ(std::string(e.what()).rfind(p.string() + ": ", 0), 0u) << name << ": " << e.what();
    } catch (const std::exception& e) {
      ADD_FAILURE() << name << ": wrong exception type: " << e.what();
    }
  }
}

// Every strict prefix of a binary file has too few bytes for its header counts.
TEST_F(MeshIoTest, TruncatedBinaryFilesFailCleanly) {
  const TriMesh mesh = two_tetrahedra();
  for (const std::string name : {"t.ply", "t.stl"}) {
    write_mesh(mesh, path(name));
    std::ifstream in(path(name), std::ios::binary);
    const std::string full((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    // Every cut through the header, then a sample of cuts through the data.
    for (size_t length = 0; length < full.size(); length += length < 300 ? 1 : 7) {
      const fs::path p = write_text("cut_" + name, full.substr(0, length));
      try {
        read_mesh(p);
        ADD_FAILURE() << name << " cut at " << length << ": no error";
      } catch (const InputError&) {
      } catch (const std::exception& e) {
        ADD_FAILURE() << name << " cut at " << length << ": " << e.what();
      }
    }
  }
}

// Text prefixes may happen to be valid meshes; they must never crash or throw anything else.
TEST_F(MeshIoTest, TruncatedTextAndRandomBytesNeverCrash) {
  const TriMesh mesh = two_tetrahedra();
  std::mt19937 random(12345);
  auto check = [&](const std::string& name, const std::string& content) {
    const fs::path p = write_text(name, content);
    try {
      const TriMesh m = read_mesh(p);
      validate_mesh(m, name);
    } catch (const InputError&) {
    } catch (const std::exception& e) {
      ADD_FAILURE() << name << " (" << content.size() << " bytes): " << e.what();
    }
  };
  for (const std::string name : {"t.obj", "t.off", "a.ply", "a.stl"}) {
    write_mesh(mesh, path(name), WriteOptions{false});
    std::ifstream in(path(name), std::ios::binary);
    const std::string full((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    for (size_t length = 0; length < full.size(); length += 3) check("cut_" + name, full.substr(0, length));
  }
  const std::vector<std::string> prefixes = {"", "ply\nformat binary_little_endian 1.0\nelement vertex 3\n",
                                             "ply\nformat ascii 1.0\nelement face 2\n", "OFF\n", "solid ", "v "};
  for (int trial = 0; trial < 120; ++trial) {
    std::string bytes(random() % 600, '\0');
    for (char& c : bytes) c = static_cast<char>(random() % 256);
    const std::string content = prefixes[trial % prefixes.size()] + bytes;
    for (const std::string ext : {".obj", ".off", ".ply", ".stl"}) check("random" + ext, content);
  }
}

// ---------------------------------------------------------------------------------------------
// OpenMesh as the independent reference reader.

using ReferenceMesh = OpenMesh::TriMesh_ArrayKernelT<>;

struct Expected {
  const char* file;
  size_t vertices;
  size_t faces;
};

// Counts as listed in the data folder's SOURCES.md.
const Expected kSharedMeshes[] = {
    {"bunny.off", 3485, 6966},      {"spot_triangulated.obj", 2930, 5856}, {"teapot.obj", 3644, 6320},
    {"decimated-max.obj", 5272, 10540}, {"head.off", 1487, 2918},          {"mannequin-devil.off", 12977, 25888},
    {"armadillo.off", 26002, 52000}, {"bull.off", 6200, 12396},            {"fertility.off", 4494, 9000},
    {"knot.off", 2080, 4160},       {"knot2.off", 5760, 11520},            {"plane.off", 841, 1600},
    {"cylinder.off", 1200, 2262},   {"sphere.off", 162, 320},
};

fs::path shared_meshes() { return fs::path(MESHQUILT_SHARED_DIR) / "data" / "meshes"; }

// Compares positions (OpenMesh stores floats) and faces up to a rotation of their corners.
void expect_matches_reference(const TriMesh& ours, const fs::path& file) {
  ReferenceMesh reference;
  OpenMesh::IO::Options options;
  ASSERT_TRUE(OpenMesh::IO::read_mesh(reference, file.string(), options)) << file;
  ASSERT_EQ(reference.n_vertices(), ours.positions.size()) << file;
  double scale = 0.0;
  for (const Vec3& p : ours.positions) scale = std::max({scale, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  for (size_t v = 0; v < ours.positions.size(); ++v) {
    const auto q = reference.point(ReferenceMesh::VertexHandle(static_cast<int>(v)));
    for (int k = 0; k < 3; ++k) {
      ASSERT_NEAR(ours.positions[v][k], q[k], 1e-6 * scale) << file << " vertex " << v;
    }
  }
  ASSERT_EQ(reference.n_faces(), ours.triangles.size()) << file;
  for (size_t f = 0; f < ours.triangles.size(); ++f) {
    std::vector<int> corners;
    for (auto v : reference.fv_range(ReferenceMesh::FaceHandle(static_cast<int>(f)))) corners.push_back(v.idx());
    ASSERT_EQ(corners.size(), 3u);
    const Tri& t = ours.triangles[f];
    bool same = false;
    for (int r = 0; r < 3; ++r) {
      same |= corners[r] == t[0] && corners[(r + 1) % 3] == t[1] && corners[(r + 2) % 3] == t[2];
    }
    ASSERT_TRUE(same) << file << " face " << f;
  }
}

TEST(MeshIoShared, ReadsEveryDataMeshLikeOpenMesh) {
  if (!fs::is_directory(shared_meshes())) GTEST_SKIP() << "no shared mesh folder";
  for (const Expected& e : kSharedMeshes) {
    const fs::path file = shared_meshes() / e.file;
    if (!fs::exists(file)) continue;
    const TriMesh ours = read_mesh(file);
    EXPECT_EQ(ours.positions.size(), e.vertices) << e.file;
    EXPECT_EQ(ours.triangles.size(), e.faces) << e.file;
    expect_matches_reference(ours, file);
  }
}

// plane.off is COFF: a flat grid in y = 0 over [-0.625, 0.625]^2 (SOURCES.md).
TEST(MeshIoShared, ReadsCgalCoffPlane) {
  const fs::path file = shared_meshes() / "plane.off";
  if (!fs::exists(file)) GTEST_SKIP() << "no shared mesh folder";
  const TriMesh m = read_mesh(file);
  Vec3 low(1e9), high(-1e9);
  for (const Vec3& p : m.positions) {
    EXPECT_EQ(p.y, 0.0);
    low = glm::min(low, p);
    high = glm::max(high, p);
  }
  EXPECT_DOUBLE_EQ(low.x, -0.625);
  EXPECT_DOUBLE_EQ(high.x, 0.625);
  EXPECT_DOUBLE_EQ(low.z, -0.625);
  EXPECT_DOUBLE_EQ(high.z, 0.625);
}

// What we write, OpenMesh reads back the same: every format, binary and ASCII.
TEST_F(MeshIoTest, OpenMeshReadsWhatWeWrite) {
  const fs::path source = shared_meshes() / "sphere.off";
  if (!fs::exists(source)) GTEST_SKIP() << "no shared mesh folder";
  const TriMesh mesh = read_mesh(source);
  for (const std::string name : {"b.ply", "a.ply", "m.obj", "m.off"}) {
    write_mesh(mesh, path(name), WriteOptions{name != "a.ply"});
    expect_matches_reference(mesh, path(name));
  }
  for (const std::string name : {"b.stl", "a.stl"}) {
    write_mesh(mesh, path(name), WriteOptions{name == "b.stl"});
    ReferenceMesh reference;
    ASSERT_TRUE(OpenMesh::IO::read_mesh(reference, path(name).string()));
    EXPECT_EQ(reference.n_faces(), mesh.triangles.size()) << name;
    EXPECT_EQ(reference.n_vertices(), read_mesh(path(name)).positions.size()) << name;
  }
}

}  // namespace
}  // namespace meshquilt
