#include "surface/guidance_field.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "core/error.h"
#include "support/surface_fixtures.h"

namespace meshquilt {
namespace {

namespace fs = std::filesystem;

Vec3 tangent_unit(const Vec3& d, const Vec3& n) { return glm::normalize(d - glm::dot(d, n) * n); }

// Area-weighted unit vertex normals, computed here.
std::vector<Vec3> reference_normals(const TriMesh& m) {
  std::vector<Vec3> n(m.num_vertices(), Vec3(0.0));
  for (const Tri& t : m.triangles) {
    const Vec3 c = glm::cross(m.positions[t[1]] - m.positions[t[0]], m.positions[t[2]] - m.positions[t[0]]);
    for (int v : t) n[v] += c;
  }
  for (Vec3& v : n) v = glm::normalize(v);
  return n;
}

// Principal axis by power iteration on the covariance of the area-weighted vertices.
Vec3 reference_axis(const TriMesh& m) {
  std::vector<double> w(m.num_vertices(), 0.0);
  for (const Tri& t : m.triangles)
    for (int v : t)
      w[v] += test::triangle_area(m.positions[t[0]], m.positions[t[1]], m.positions[t[2]]) / 3.0;
  double total = 0.0;
  Vec3 mean(0.0);
  for (size_t v = 0; v < w.size(); ++v) {
    total += w[v];
    mean += w[v] * m.positions[v];
  }
  mean /= total;
  double c[3][3] = {};
  for (size_t v = 0; v < w.size(); ++v) {
    const Vec3 d = m.positions[v] - mean;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) c[i][j] += w[v] * d[i] * d[j];
  }
  Vec3 x(0.3, 0.5, 0.7);
  for (int it = 0; it < 2000; ++it) {
    Vec3 y(0.0);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) y[i] += c[i][j] * x[j];
    x = glm::normalize(y);
  }
  return x;
}

// Solves a dense system by Gaussian elimination with partial pivoting (columns of b solved together).
std::vector<Vec3> dense_solve(std::vector<std::vector<double>> a, std::vector<Vec3> b) {
  const size_t n = a.size();
  for (size_t col = 0; col < n; ++col) {
    size_t pivot = col;
    for (size_t r = col + 1; r < n; ++r)
      if (std::abs(a[r][col]) > std::abs(a[pivot][col])) pivot = r;
    std::swap(a[col], a[pivot]);
    std::swap(b[col], b[pivot]);
    for (size_t r = col + 1; r < n; ++r) {
      const double f = a[r][col] / a[col][col];
      if (f == 0.0) continue;
      for (size_t k = col; k < n; ++k) a[r][k] -= f * a[col][k];
      b[r] -= f * b[col];
    }
  }
  std::vector<Vec3> x(n);
  for (size_t r = n; r-- > 0;) {
    Vec3 s = b[r];
    for (size_t k = r + 1; k < n; ++k) s -= a[r][k] * x[k];
    x[r] = s / a[r][r];
  }
  return x;
}

TriMesh ellipsoid() {
  TriMesh m = test::uv_sphere(16, 24);
  for (Vec3& p : m.positions) p = test::rigid_motion(Vec3(3.0 * p.x, 1.2 * p.y, 0.8 * p.z));
  return m;
}

TEST(GuidanceField, DefaultFieldFollowsThePrincipalAxis) {
  const TriMesh mesh = ellipsoid();
  const BaseSurface base(mesh);
  const GuidanceField field = interpolate_field(base, {});
  // The long axis of the ellipsoid is the rotated x axis.
  const Vec3 long_axis =
      glm::normalize(test::rigid_motion(Vec3(1.0, 0.0, 0.0)) - test::rigid_motion(Vec3(0.0)));
  EXPECT_NEAR(std::abs(glm::dot(field.axis, long_axis)), 1.0, 1e-9);
  EXPECT_NEAR(glm::length(field.axis), 1.0, 1e-12);
  const std::vector<Vec3> normals = reference_normals(mesh);
  ASSERT_EQ(field.directions.size(), mesh.num_vertices());
  for (size_t v = 0; v < mesh.num_vertices(); ++v) {
    EXPECT_NEAR(glm::length(base.vertex_normals[v] - normals[v]), 0.0, 1e-12);
    if (std::abs(glm::dot(normals[v], field.axis)) > 0.999) continue;  // at the singular ends
    const Vec3 expected = tangent_unit(field.axis, normals[v]);
    EXPECT_NEAR(glm::length(field.directions[v] - expected), 0.0, 1e-9) << v;
  }
}

TEST(GuidanceField, ConstraintsAreKeptAndEverythingIsTangentAndUnit) {
  const TriMesh mesh = test::icosphere(3, 1.5);
  const BaseSurface base(mesh);
  const std::vector<FieldConstraint> constraints{
      {10, Vec3(1.0, 2.0, 0.5)}, {200, Vec3(-3.0, 0.1, 0.2)}, {555, Vec3(0.0, 0.0, 4.0)}};
  const GuidanceField field = interpolate_field(base, constraints);
  for (const FieldConstraint& c : constraints) {
    const Vec3 expected = tangent_unit(c.direction, base.vertex_normals[c.vertex]);
    EXPECT_NEAR(glm::length(field.directions[c.vertex] - expected), 0.0, 1e-12) << c.vertex;
  }
  for (size_t v = 0; v < mesh.num_vertices(); ++v) {
    EXPECT_LT(std::abs(glm::dot(field.directions[v], base.vertex_normals[v])), 1e-9) << v;
    EXPECT_NEAR(glm::length(field.directions[v]), 1.0, 1e-12) << v;
  }
  // GuidanceField::at: tangent to the face, unit.
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int k = 0; k < 500; ++k) {
    double b1 = u(rng), b2 = u(rng);
    if (b1 + b2 > 1.0) b1 = 1.0 - b1, b2 = 1.0 - b2;
    const SurfacePoint p{static_cast<int32_t>(rng() % mesh.num_faces()), glm::dvec2(b1, b2)};
    const Vec3 d = field.at(base, p);
    EXPECT_LT(std::abs(glm::dot(d, base.face_normals[p.face])), 1e-9);
    EXPECT_NEAR(glm::length(d), 1.0, 1e-12);
    // It is the face-plane part of the interpolated vertex directions.
    const Tri& t = mesh.triangles[p.face];
    const Vec3 mix =
        (1.0 - b1 - b2) * field.directions[t[0]] + b1 * field.directions[t[1]] + b2 * field.directions[t[2]];
    EXPECT_NEAR(glm::length(d - tangent_unit(mix, base.face_normals[p.face])), 0.0, 1e-9);
  }
}

TEST(GuidanceField, OnlyTheDirectionOfAConstraintMatters) {
  // A field file gives directions: [0, 0, 10] and [0, 0, 1] must give the same field, and a huge
  // but finite direction must not overflow into zero-length results.
  const TriMesh mesh = test::icosphere(3);
  const BaseSurface base(mesh);
  const std::vector<FieldConstraint> unit{{10, Vec3(1.0, 0.0, 0.0)}, {400, Vec3(0.0, 1.0, 1.0)}};
  std::vector<FieldConstraint> scaled = unit;
  scaled[0].direction *= 1000.0;
  std::vector<FieldConstraint> huge = unit;
  huge[1].direction *= 1e200;
  const GuidanceField a = interpolate_field(base, unit), b = interpolate_field(base, scaled),
                      c = interpolate_field(base, huge);
  for (size_t v = 0; v < mesh.num_vertices(); ++v) {
    EXPECT_NEAR(glm::length(a.directions[v] - b.directions[v]), 0.0, 1e-9) << v;
    EXPECT_NEAR(glm::length(a.directions[v] - c.directions[v]), 0.0, 1e-9) << v;
    EXPECT_NEAR(glm::length(c.directions[v]), 1.0, 1e-12) << v;
  }
}

TEST(GuidanceField, MatchesADenseSolveOfTheDocumentedSystem) {
  // Directions d_v in the vertices' tangent planes minimizing sum over edges |d_v - d_w|^2 plus
  // `regularization` x sum |d_v - default_v|^2, the constrained vertices held (as unit tangents);
  // then normalized. Solved here in a tangent basis of this test's own choosing (the minimizer does
  // not depend on it): setting the gradient to zero gives, per free vertex v and basis vector a,
  // (deg v + eps) x_va - sum over free w, b of (t_va . t_wb) x_wb = eps t_va . default_v + sum over held w of t_va . d_w.
  const TriMesh mesh = ellipsoid();
  const BaseSurface base(mesh);
  const double eps = 0.05;
  const std::vector<FieldConstraint> constraints{
      {5, Vec3(0.0, 1.0, 0.0)}, {100, Vec3(1.0, 1.0, 1.0)}, {300, Vec3(-1.0, 0.0, 2.0)}};
  const GuidanceField field = interpolate_field(base, constraints, eps);
  const Vec3 axis = reference_axis(mesh);
  ASSERT_NEAR(std::abs(glm::dot(axis, field.axis)), 1.0, 1e-9);
  const std::vector<Vec3> normals = reference_normals(mesh);
  const size_t n = mesh.num_vertices();
  std::vector<std::vector<int>> neighbours(n);
  for (const Tri& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      neighbours[t[k]].push_back(t[(k + 1) % 3]);
      neighbours[t[(k + 1) % 3]].push_back(t[k]);
    }
  std::map<int, Vec3> held;  // each constraint held as its unit tangent direction
  for (const auto& c : constraints) held[c.vertex] = tangent_unit(c.direction, normals[c.vertex]);
  std::vector<std::array<Vec3, 2>> basis(n);
  for (size_t v = 0; v < n; ++v) {
    const Vec3 t1 = glm::normalize(glm::cross(normals[v], glm::normalize(Vec3(0.3, -0.5, 0.8))));
    basis[v] = {t1, glm::cross(normals[v], t1)};
  }
  std::vector<int> column(n, -1);
  int unknowns = 0;
  for (size_t v = 0; v < n; ++v)
    if (!held.count(static_cast<int>(v))) column[v] = 2 * unknowns++;
  std::vector<std::vector<double>> a(2 * unknowns, std::vector<double>(2 * unknowns, 0.0));
  std::vector<Vec3> b(2 * unknowns, Vec3(0.0));  // the right-hand side in .x
  for (size_t v = 0; v < n; ++v) {
    if (column[v] < 0) continue;
    std::sort(neighbours[v].begin(), neighbours[v].end());
    neighbours[v].erase(std::unique(neighbours[v].begin(), neighbours[v].end()), neighbours[v].end());
    const Vec3 fallback = field.axis - glm::dot(field.axis, normals[v]) * normals[v];
    for (int i = 0; i < 2; ++i) {
      a[column[v] + i][column[v] + i] = static_cast<double>(neighbours[v].size()) + eps;
      b[column[v] + i].x = eps * glm::dot(basis[v][i], fallback);
      for (int w : neighbours[v]) {
        if (column[w] >= 0) {
          for (int j = 0; j < 2; ++j) a[column[v] + i][column[w] + j] -= glm::dot(basis[v][i], basis[w][j]);
        } else {
          b[column[v] + i].x += glm::dot(basis[v][i], held[w]);
        }
      }
    }
  }
  const std::vector<Vec3> x = dense_solve(a, b);
  for (size_t v = 0; v < n; ++v) {
    const Vec3 raw = column[v] >= 0 ? x[column[v]].x * basis[v][0] + x[column[v] + 1].x * basis[v][1]
                                    : held[static_cast<int>(v)];
    EXPECT_NEAR(glm::length(field.directions[v] - tangent_unit(raw, normals[v])), 0.0, 1e-8) << v;
  }
}

// Two directions on opposite sides of a cylinder, both running around it. Averaged in 3D they are
// opposite, so halfway round a solve in space finds nothing to follow; within the tangent planes
// they agree (running around a cylinder is parallel transport), so the field runs around it
// everywhere.
TEST(GuidanceField, DirectionsSpreadAlongTheSurfaceNotThroughSpace) {
  TriMesh mesh;
  const int around = 24, rings = 6;
  for (int j = 0; j < rings; ++j)
    for (int i = 0; i < around; ++i) {
      const double angle = 2.0 * M_PI * i / around;
      mesh.positions.emplace_back(std::cos(angle), std::sin(angle), 0.5 * j);
    }
  for (int j = 0; j + 1 < rings; ++j)
    for (int i = 0; i < around; ++i) {
      const int p = j * around + i, q = j * around + (i + 1) % around, r = p + around, s = q + around;
      mesh.triangles.push_back({p, q, s});
      mesh.triangles.push_back({p, s, r});
    }
  const BaseSurface base(mesh);
  const std::vector<FieldConstraint> constraints{{2 * around, Vec3(0.0, 1.0, 0.0)},
                                                 {2 * around + around / 2, Vec3(0.0, -1.0, 0.0)}};
  const GuidanceField field = interpolate_field(base, constraints);
  double worst = 1.0;
  for (size_t v = 0; v < mesh.num_vertices(); ++v) {
    const Vec3& p = mesh.positions[v];
    worst = std::min(worst, std::abs(glm::dot(field.directions[v], glm::normalize(Vec3(-p.y, p.x, 0.0)))));
  }
  EXPECT_GT(worst, 0.99);
}

TEST(GuidanceField, DefaultFieldOnASphereIsSmoothAwayFromItsSingularities) {
  const double R = 2.0;
  const TriMesh mesh = test::icosphere(5, R);
  const BaseSurface base(mesh);
  const GuidanceField field = interpolate_field(base, {});
  // Faces across each interior edge.
  std::map<std::pair<int, int>, std::vector<int>> edge_faces;
  for (size_t f = 0; f < mesh.num_faces(); ++f)
    for (int k = 0; k < 3; ++k)
      edge_faces[std::minmax(mesh.triangles[f][k], mesh.triangles[f][(k + 1) % 3])].push_back(
          static_cast<int>(f));
  const auto centre = [&](int f) { return SurfacePoint{f, glm::dvec2(1.0 / 3.0)}; };
  // The default field is the axis projected to the tangent plane: the meridians of `axis`. At polar
  // angle phi from the axis a unit step turns it by 1/R along a meridian and by cot(phi)/R along a
  // parallel, so between centroids h apart it turns by at most h / (R sin phi) to first order.
  // Away from the singularities (sin phi >= 1/2, 30 degrees from either end) that is 2 h / R; the
  // faces' own tilt adds discretisation noise, hence a 25% margin on each pair. The mean stays a
  // few h / R.
  const double min_sin = 0.5;
  double sum = 0.0, mean_h = 0.0, worst_near_ends = 0.0;
  int pairs = 0;
  for (const auto& [edge, faces] : edge_faces) {
    ASSERT_EQ(faces.size(), 2u);
    const int f = faces[0], g = faces[1];
    const double sin_f =
        std::sqrt(std::max(0.0, 1.0 - std::pow(glm::dot(base.face_normals[f], field.axis), 2)));
    const double sin_g =
        std::sqrt(std::max(0.0, 1.0 - std::pow(glm::dot(base.face_normals[g], field.axis), 2)));
    const double change =
        std::acos(std::clamp(glm::dot(field.at(base, centre(f)), field.at(base, centre(g))), -1.0, 1.0));
    if (std::min(sin_f, sin_g) < 0.05) worst_near_ends = std::max(worst_near_ends, change);
    if (std::min(sin_f, sin_g) < min_sin) continue;
    const double h = glm::distance(base.position(centre(f)), base.position(centre(g)));
    EXPECT_LT(change, 1.25 * h / (R * std::min(sin_f, sin_g))) << "faces " << f << " " << g;
    sum += change;
    mean_h += h;
    ++pairs;
  }
  ASSERT_GT(pairs, 10000);
  const double mean = sum / pairs;
  mean_h /= pairs;
  EXPECT_LT(mean, 2.0 * mean_h / R);
  EXPECT_LT(mean, 0.03);  // ~1.7 degrees between neighbouring faces of this sphere
  // The two singularities are where the normal is parallel to the axis: the field turns around them.
  EXPECT_GT(worst_near_ends, 0.5);
}

// --- field files ----------------------------------------------------------------------------

class FieldFile : public ::testing::Test {
 protected:
  FieldFile() : mesh_(test::icosphere(1)) {
    dir_ = fs::path(::testing::TempDir()) / ("guidance_field_test_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  ~FieldFile() override { fs::remove_all(dir_); }

  fs::path write(const std::string& name, const std::string& text) {
    const fs::path file = dir_ / name;
    std::ofstream(file) << text;
    return file;
  }

  void expect_invalid(const std::string& name, const std::string& text, const std::string& mention) {
    const fs::path file = write(name, text);
    try {
      read_field_file(file, mesh_);
      ADD_FAILURE() << "no InputError for " << text;
    } catch (const InputError& e) {
      EXPECT_EQ(e.kind(), ErrorKind::invalid_option) << text;
      const std::string message = e.what();
      EXPECT_EQ(message.rfind(file.string() + ": ", 0), 0u) << message;
      EXPECT_NE(message.find(mention), std::string::npos) << message;
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
  }

  TriMesh mesh_;
  fs::path dir_;
};

TEST_F(FieldFile, ReadsVerticesAndPoints) {
  const Vec3 point(0.31, -0.7, 0.52);
  const fs::path file = write("ok.json", R"({"directions": [
      {"vertex": 4, "direction": [1, 0, 0]},
      {"point": [0.31, -0.7, 0.52], "direction": [0, 2.5, -1]}]})");
  const std::vector<FieldConstraint> c = read_field_file(file, mesh_);
  ASSERT_EQ(c.size(), 2u);
  EXPECT_EQ(c[0].vertex, 4);
  EXPECT_EQ(c[0].direction, Vec3(1.0, 0.0, 0.0));
  int nearest = -1;
  for (size_t v = 0; v < mesh_.num_vertices(); ++v)
    if (nearest < 0 ||
        glm::distance(point, mesh_.positions[v]) < glm::distance(point, mesh_.positions[nearest]))
      nearest = static_cast<int>(v);
  EXPECT_EQ(c[1].vertex, nearest);
  EXPECT_EQ(c[1].direction, Vec3(0.0, 2.5, -1.0));
  EXPECT_TRUE(read_field_file(write("empty.json", R"({"directions": []})"), mesh_).empty());
}

TEST_F(FieldFile, BadContentIsAnInvalidOption) {
  expect_invalid("malformed.json", R"({"directions": [{"vertex": 1, "direction": [1, 0, 0]})", "JSON");
  expect_invalid("noarray.json", R"({"fields": []})", "directions");
  expect_invalid("nodirection.json", R"({"directions": [{"vertex": 1}]})", "direction");
  expect_invalid("zero.json", R"({"directions": [{"vertex": 1, "direction": [0, 0, 0]}]})", "zero");
  expect_invalid("short.json", R"({"directions": [{"vertex": 1, "direction": [1, 0]}]})", "direction");
  expect_invalid("text.json", R"({"directions": [{"vertex": 1, "direction": ["x", 0, 0]}]})", "direction");
  expect_invalid("far.json", R"({"directions": [{"vertex": 42, "direction": [1, 0, 0]}]})", "vertex 42");
  expect_invalid("negative.json", R"({"directions": [{"vertex": -1, "direction": [1, 0, 0]}]})", "vertex -1");
  expect_invalid("where.json", R"({"directions": [{"direction": [1, 0, 0]}]})", "vertex");
  expect_invalid("badpoint.json", R"({"directions": [{"point": [1, 2], "direction": [1, 0, 0]}]})", "point");
}

TEST_F(FieldFile, ParsesTextUnderTheGivenName) {
  const std::string text = R"({"directions": [{"vertex": 2, "direction": [0, 0, 3]},
      {"point": [0.1, 0.2, 0.3], "direction": [1, 1, 0]}]})";
  const std::vector<FieldConstraint> parsed = parse_field(text, "inline field", mesh_);
  const std::vector<FieldConstraint> read = read_field_file(write("same.json", text), mesh_);
  ASSERT_EQ(parsed.size(), read.size());
  for (size_t k = 0; k < parsed.size(); ++k) {
    EXPECT_EQ(parsed[k].vertex, read[k].vertex);
    EXPECT_EQ(parsed[k].direction, read[k].direction);
  }
  // A text that is not NUL-terminated where the view ends: only the view is parsed.
  const std::string padded = std::string(R"({"directions": []})") + "garbage";
  EXPECT_TRUE(parse_field(std::string_view(padded).substr(0, padded.size() - 7), "view", mesh_).empty());
  const std::vector<std::string> bad_texts = {
      R"({"directions": [{"vertex": 18446744073709551615, "direction": [1, 0, 0]}]})", R"({"directions": [)"};
  for (const std::string& bad : bad_texts) {
    try {
      parse_field(bad, "inline field", mesh_);
      ADD_FAILURE() << "no InputError for " << bad;
    } catch (const InputError& e) {
      EXPECT_EQ(e.kind(), ErrorKind::invalid_option);
      EXPECT_EQ(std::string(e.what()).rfind("inline field: ", 0), 0u) << e.what();
    }
  }
}

// Points so far away that squared distances overflow: on a base of that size the nearest vertex
// is still found; from the unit sphere every vertex is equally far (the tie goes to the first).
// Such a point once picked no vertex, and the interpolation wrote before its arrays.
TEST_F(FieldFile, AFarPointPicksTheNearestVertex) {
  TriMesh huge = mesh_;
  for (Vec3& q : huge.positions) q *= 1e200;
  size_t low = 0;
  for (size_t v = 1; v < huge.num_vertices(); ++v)
    if (huge.positions[v].z < huge.positions[low].z) low = v;
  const std::vector<FieldConstraint> below =
      parse_field(R"({"directions": [{"point": [0, 0, -3e200], "direction": [1, 0, 0]}]})", "far", huge);
  ASSERT_EQ(below.size(), 1u);
  EXPECT_EQ(below[0].vertex, static_cast<int32_t>(low));

  const std::vector<FieldConstraint> c = parse_field(
      R"({"directions": [{"point": [1e300, -1e300, 0], "direction": [0, 0, 1]}]})", "far", mesh_);
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0].vertex, 0);
  const BaseSurface base(mesh_);
  const GuidanceField field = interpolate_field(base, c);
  for (const Vec3& d : field.directions) EXPECT_NEAR(glm::length(d), 1.0, 1e-12);
}

TEST_F(FieldFile, MissingFileIsUnreadable) {
  const fs::path file = dir_ / "absent.json";
  try {
    read_field_file(file, mesh_);
    FAIL() << "no IoError";
  } catch (const IoError& e) {
    EXPECT_EQ(e.kind(), ErrorKind::file_unreadable);
    EXPECT_EQ(std::string(e.what()).rfind(file.string() + ": ", 0), 0u) << e.what();
  }
}

TEST_F(FieldFile, WritesOneSegmentPerFaceAlongTheField) {
  const BaseSurface base(mesh_);
  const GuidanceField field = interpolate_field(base, {{3, Vec3(0.0, 1.0, 0.0)}});
  const fs::path file = dir_ / "field.obj";
  const double length = 0.125;
  write_field_obj(base, field, length, file);
  std::ifstream in(file);
  std::vector<Vec3> v;
  std::vector<std::pair<int, int>> lines;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream s(line);
    std::string tag;
    s >> tag;
    if (tag == "v") {
      Vec3 p;
      s >> p.x >> p.y >> p.z;
      v.push_back(p);
    } else if (tag == "l") {
      int a, b;
      s >> a >> b;
      lines.emplace_back(a, b);
    }
  }
  ASSERT_EQ(v.size(), 2 * mesh_.num_faces());
  ASSERT_EQ(lines.size(), mesh_.num_faces());
  for (size_t f = 0; f < mesh_.num_faces(); ++f) {
    const auto [a, b] = lines[f];
    ASSERT_TRUE(a >= 1 && b >= 1 && a <= static_cast<int>(v.size()) && b <= static_cast<int>(v.size()));
    const Tri& t = mesh_.triangles[f];
    const Vec3 centroid = (mesh_.positions[t[0]] + mesh_.positions[t[1]] + mesh_.positions[t[2]]) / 3.0;
    EXPECT_NEAR(glm::distance(v[a - 1], centroid), 0.0, 1e-7);
    const Vec3 expected_end =
        centroid + length * field.at(base, {static_cast<int32_t>(f), glm::dvec2(1.0 / 3.0)});
    EXPECT_NEAR(glm::distance(v[b - 1], expected_end), 0.0, 1e-7);
  }
}

TEST(GuidanceField, DirectionsAtPointsGoToTheNearestVertexAsAFieldFileDoes) {
  const TriMesh mesh = test::icosphere(2);
  const std::vector<Vec3> points{{0.1, 0.05, 0.99}, {-0.7, 0.7, 0.1}};
  const std::vector<Vec3> directions{{1, 0, 0}, {0, 0, 2}};
  const std::vector<FieldConstraint> at = constraints_at_points(points, directions, mesh, "field");
  ASSERT_EQ(at.size(), 2u);
  for (size_t k = 0; k < points.size(); ++k) {
    // Brute force: the vertex nearest the point.
    size_t nearest = 0;
    for (size_t v = 1; v < mesh.num_vertices(); ++v)
      if (glm::distance(mesh.positions[v], points[k]) < glm::distance(mesh.positions[nearest], points[k])) nearest = v;
    EXPECT_EQ(at[k].vertex, static_cast<int32_t>(nearest));
    EXPECT_EQ(at[k].direction, directions[k]);
  }
  // The same as a field file's point entries.
  const std::vector<FieldConstraint> file = parse_field(
      R"({"directions": [{"point": [0.1, 0.05, 0.99], "direction": [1, 0, 0]},
                         {"point": [-0.7, 0.7, 0.1], "direction": [0, 0, 2]}]})",
      "f.json", mesh);
  EXPECT_EQ(file[0].vertex, at[0].vertex);
  EXPECT_EQ(file[1].vertex, at[1].vertex);
  EXPECT_THROW(constraints_at_points(points, {directions[0]}, mesh, "field"), InputError);
  EXPECT_THROW(constraints_at_points({points[0]}, {Vec3(0.0)}, mesh, "field"), InputError);
  EXPECT_THROW(constraints_at_points({Vec3(std::nan(""), 0, 0)}, {directions[0]}, mesh, "field"), InputError);
  EXPECT_THROW(constraints_at_points({points[0]}, {directions[0]}, TriMesh{}, "field"), InputError);
}

}  // namespace
}  // namespace meshquilt
