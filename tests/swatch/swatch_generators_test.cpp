// Swatch generators: every kind, at its defaults and its small preset, is checked for what the
// quilting needs from a swatch: it loads back (our reader and OpenMesh), has the designed number
// of elements, closed elements are oriented 2-manifolds of the designed genus, no two elements
// intersect (a brute-force exact check written here), z is the thinnest axis; weave over/under is
// read back from the geometry; same seed, same bytes.
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <numbers>
#include <numeric>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <optional>

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include "core/error.h"
#include "mesh/mesh_io.h"
#include "mesh/swatch_frame.h"
#include "swatch/chainmail.h"
#include "swatch/fruit.h"
#include "swatch/heightfield.h"
#include "swatch/nuts.h"
#include "swatch/weave.h"

namespace meshquilt {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("meshquilt_swatch_test_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string file_bytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// ---------------------------------------------------------------------------------------------
// Independent checks.

struct Box {
  Vec3 lo{INFINITY}, hi{-INFINITY};
  void add(const Vec3& p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  Vec3 extent() const { return hi - lo; }
};

Box bounds(const TriMesh& m) {
  Box b;
  for (const Vec3& p : m.positions) b.add(p);
  return b;
}

// Vertex-connected components by union-find.
int count_components(const TriMesh& m) {
  std::vector<int> parent(m.positions.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  std::vector<bool> used(m.positions.size(), false);
  for (const Tri& t : m.triangles) {
    for (int k = 0; k < 3; ++k) {
      used[t[k]] = true;
      parent[find(t[k])] = find(t[(k + 1) % 3]);
    }
  }
  int count = 0;
  for (size_t v = 0; v < parent.size(); ++v) count += used[v] && find(static_cast<int>(v)) == static_cast<int>(v);
  return count;
}

struct ElementTopology {
  int boundary_edges = 0;
  int nonmanifold_edges = 0;
  int misoriented_edges = 0;  // used twice in the same direction
  int euler = 0;              // V - E + F
  double volume = 0.0;        // signed, divergence theorem
};

std::map<int32_t, ElementTopology> element_topology(const TriMesh& m) {
  std::map<int32_t, std::map<std::pair<int32_t, int32_t>, std::pair<int, int>>> edges;  // (forward, backward) uses
  std::map<int32_t, std::vector<bool>> vertices;
  std::map<int32_t, ElementTopology> result;
  for (size_t f = 0; f < m.triangles.size(); ++f) {
    const int32_t e = m.elements[f];
    const Tri& t = m.triangles[f];
    auto& used = vertices[e];
    used.resize(m.positions.size(), false);
    for (int k = 0; k < 3; ++k) {
      used[t[k]] = true;
      const int32_t a = t[k], b = t[(k + 1) % 3];
      auto& uses = edges[e][{std::min(a, b), std::max(a, b)}];
      (a < b ? uses.first : uses.second)++;
    }
    result[e].volume += glm::dot(m.positions[t[0]], glm::cross(m.positions[t[1]], m.positions[t[2]])) / 6.0;
    result[e].euler += 1;
  }
  for (auto& [e, map] : edges) {
    ElementTopology& r = result[e];
    for (const auto& [edge, uses] : map) {
      const int total = uses.first + uses.second;
      r.boundary_edges += total == 1;
      r.nonmanifold_edges += total > 2;
      r.misoriented_edges += uses.first > 1 || uses.second > 1;
    }
    r.euler += static_cast<int>(std::count(vertices[e].begin(), vertices[e].end(), true)) - static_cast<int>(map.size());
  }
  return result;
}

double orient(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return glm::dot(b - a, glm::cross(c - a, d - a));
}

int sign(double x) { return (x > 0.0) - (x < 0.0); }

// Segment pq against triangle abc, closed sets: touching counts as intersecting.
bool segment_hits_triangle(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c) {
  const int sp = sign(orient(a, b, c, p)), sq = sign(orient(a, b, c, q));
  if (sp != 0 && sp == sq) return false;
  if (sp == 0 && sq == 0) {
    // Coplanar: conservatively report contact when the segment meets the triangle's bbox; our
    // swatches never get here unless something is badly wrong.
    return true;
  }
  const int s1 = sign(orient(p, q, a, b)), s2 = sign(orient(p, q, b, c)), s3 = sign(orient(p, q, c, a));
  const bool has_pos = s1 > 0 || s2 > 0 || s3 > 0, has_neg = s1 < 0 || s2 < 0 || s3 < 0;
  return !(has_pos && has_neg);
}

bool triangles_intersect(const TriMesh& m, const Tri& s, const Tri& t) {
  const auto& P = m.positions;
  for (int k = 0; k < 3; ++k) {
    if (segment_hits_triangle(P[s[k]], P[s[(k + 1) % 3]], P[t[0]], P[t[1]], P[t[2]])) return true;
    if (segment_hits_triangle(P[t[k]], P[t[(k + 1) % 3]], P[s[0]], P[s[1]], P[s[2]])) return true;
  }
  return false;
}

// Pairs of faces of different elements that intersect or touch: sweep over x of face bboxes,
// then y/z bbox overlap, then the exact edge-against-triangle test both ways.
int intersecting_pairs(const TriMesh& m) {
  const size_t n = m.triangles.size();
  std::vector<Box> box(n);
  for (size_t f = 0; f < n; ++f) {
    for (int k = 0; k < 3; ++k) box[f].add(m.positions[m.triangles[f][k]]);
  }
  std::vector<size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return box[a].lo.x < box[b].lo.x; });
  int count = 0;
  for (size_t i = 0; i < n; ++i) {
    const Box& a = box[order[i]];
    for (size_t j = i + 1; j < n && box[order[j]].lo.x <= a.hi.x; ++j) {
      const Box& b = box[order[j]];
      if (m.elements[order[i]] == m.elements[order[j]]) continue;
      if (b.lo.y > a.hi.y || a.lo.y > b.hi.y || b.lo.z > a.hi.z || a.lo.z > b.hi.z) continue;
      count += triangles_intersect(m, m.triangles[order[i]], m.triangles[order[j]]);
    }
  }
  return count;
}

double smallest_area(const TriMesh& m) {
  double smallest = INFINITY;
  for (const Tri& t : m.triangles) {
    const auto& P = m.positions;
    smallest = std::min(smallest, 0.5 * glm::length(glm::cross(P[t[1]] - P[t[0]], P[t[2]] - P[t[0]])));
  }
  return smallest;
}

// ---------------------------------------------------------------------------------------------
// The common body: one swatch, what every kind must satisfy.

struct Design {
  int elements;
  bool closed;
  int euler;  // of each element: 0 for a ring or a nut, 2 for a sphere-like element
};

void check_swatch(const TriMesh& m, const Design& design, const std::string& name) {
  SCOPED_TRACE(name);
  ASSERT_EQ(m.elements.size(), m.triangles.size());
  // Elements: as designed, numbered 0..n-1, each exactly one connected component.
  EXPECT_EQ(count_components(m), design.elements);
  std::vector<int32_t> ids(m.elements);
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  ASSERT_EQ(static_cast<int>(ids.size()), design.elements);
  EXPECT_EQ(ids.front(), 0);
  EXPECT_EQ(ids.back(), design.elements - 1);

  const Box box = bounds(m);
  const Vec3 e = box.extent();
  EXPECT_LT(e.z, e.x);
  EXPECT_LT(e.z, e.y);
  EXPECT_GT(smallest_area(m), 1e-8 * glm::dot(e, e)) << "degenerate triangle";

  for (const auto& [element, topo] : element_topology(m)) {
    SCOPED_TRACE("element " + std::to_string(element));
    EXPECT_EQ(topo.nonmanifold_edges, 0);
    EXPECT_EQ(topo.misoriented_edges, 0);
    if (design.closed) {
      EXPECT_EQ(topo.boundary_edges, 0);
      EXPECT_EQ(topo.euler, design.euler);
      EXPECT_GT(topo.volume, 0.0);
    }
  }
  EXPECT_EQ(intersecting_pairs(m), 0);
  // The quilting's swatch loader accepts it as it is: no turn, only a shift to the origin.
  const TriMesh framed = orient_swatch(m, name);
  ASSERT_EQ(framed.positions.size(), m.positions.size());
  for (size_t v = 0; v < m.positions.size(); v += 97) {
    EXPECT_NEAR(glm::length(framed.positions[v] - (m.positions[v] - box.lo)), 0.0, 1e-9 * glm::length(e));
  }
}

// Writes the swatch, reads it back with our reader and with OpenMesh, and compares.
void check_round_trip(const TriMesh& m, const std::string& name) {
  SCOPED_TRACE(name);
  const fs::path dir = scratch(name);
  const fs::path ply = dir / (name + ".ply");
  write_mesh(m, ply);
  const TriMesh back = read_mesh(ply);
  EXPECT_EQ(back.positions, m.positions);
  EXPECT_EQ(back.triangles, m.triangles);
  EXPECT_EQ(back.elements, m.elements);

  const fs::path off = dir / (name + ".off");
  write_mesh(m, off);
  for (const fs::path& file : {ply, off}) {
    OpenMesh::TriMesh_ArrayKernelT<> reference;
    OpenMesh::IO::Options options;
    ASSERT_TRUE(OpenMesh::IO::read_mesh(reference, file.string(), options)) << file;
    // OpenMesh drops any face that would make a vertex or edge non-manifold: all must survive.
    EXPECT_EQ(reference.n_faces(), m.triangles.size()) << file;
    EXPECT_EQ(reference.n_vertices(), m.positions.size()) << file;
    size_t boundary = 0;
    for (auto edge : reference.edges()) boundary += reference.is_boundary(edge);
    if (name.find("open") == std::string::npos) {
      EXPECT_EQ(boundary, 0u) << file;
    }
  }
  fs::remove_all(dir);
}

// ---------------------------------------------------------------------------------------------
// The checker must see an intersection when there is one.

TEST(SwatchChecks, IntersectionCheckFindsOverlappingRings) {
  ChainmailOptions o = ChainmailOptions::small();
  o.rows = 2;
  o.columns = 1;
  TriMesh one = make_chainmail(o);
  TriMesh two = one;
  const auto offset = static_cast<int32_t>(one.positions.size());
  for (const Vec3& p : one.positions) two.positions.push_back(p + Vec3(0.05, 0.0, 0.0));
  for (const Tri& t : one.triangles) two.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  for (int32_t e : one.elements) two.elements.push_back(e + 2);
  EXPECT_GT(intersecting_pairs(two), 0);
  EXPECT_EQ(intersecting_pairs(one), 0);
}

// ---------------------------------------------------------------------------------------------
// Chain mail.

// Does some edge of element b cross the plane of element a inside a's hole? The hole's disk is
// found from a's vertices alone: centroid, normal = axis of least spread, radius = the smallest
// in-plane distance of a vertex from the centroid.
bool threads_hole(const TriMesh& m, int32_t a, int32_t b) {
  Vec3 centroid(0.0);
  int n = 0;
  std::vector<int32_t> verts;
  for (size_t f = 0; f < m.triangles.size(); ++f) {
    if (m.elements[f] != a) continue;
    for (int32_t v : m.triangles[f]) verts.push_back(v);
  }
  std::sort(verts.begin(), verts.end());
  verts.erase(std::unique(verts.begin(), verts.end()), verts.end());
  for (int32_t v : verts) centroid += m.positions[v], ++n;
  centroid /= static_cast<double>(n);
  // Power iteration on (trace I - covariance) finds the covariance's smallest axis.
  double cov[3][3] = {};
  for (int32_t v : verts) {
    const Vec3 d = m.positions[v] - centroid;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) cov[i][j] += d[i] * d[j];
  }
  const double trace = cov[0][0] + cov[1][1] + cov[2][2];
  Vec3 normal(0.3, 0.2, 1.0);
  for (int it = 0; it < 200; ++it) {
    Vec3 next(0.0);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) next[i] += ((i == j ? trace : 0.0) - cov[i][j]) * normal[j];
    normal = glm::normalize(next);
  }
  double hole = INFINITY;
  for (int32_t v : verts) {
    const Vec3 d = m.positions[v] - centroid;
    hole = std::min(hole, glm::length(d - glm::dot(d, normal) * normal));
  }
  for (size_t f = 0; f < m.triangles.size(); ++f) {
    if (m.elements[f] != b) continue;
    for (int k = 0; k < 3; ++k) {
      const Vec3 p = m.positions[m.triangles[f][k]], q = m.positions[m.triangles[f][(k + 1) % 3]];
      const double dp = glm::dot(p - centroid, normal), dq = glm::dot(q - centroid, normal);
      if ((dp < 0.0) == (dq < 0.0)) continue;
      const Vec3 x = p + (dp / (dp - dq)) * (q - p);
      if (glm::length(x - centroid) < hole) return true;
    }
  }
  return false;
}

void check_chainmail_links(const TriMesh& m, const ChainmailOptions& o) {
  // Expected links straight from the 4-in-1 rule: ring (c, r) links the rings of rows r +- 1
  // whose centres lie half a pitch to either side; odd rows are shifted by half a pitch.
  int expected = 0, found = 0;
  for (int r = 0; r < o.rows; ++r) {
    for (int c = 0; c < o.columns; ++c) {
      int degree = 0;
      for (int r2 = 0; r2 < o.rows; ++r2) {
        for (int c2 = 0; c2 < o.columns; ++c2) {
          if (r2 == r && c2 == c) continue;
          const double dx = (c2 + 0.5 * (r2 % 2)) - (c + 0.5 * (r % 2));
          const bool linked = std::abs(r2 - r) == 1 && std::abs(std::abs(dx) - 0.5) < 1e-9;
          const bool threads = threads_hole(m, r * o.columns + c, r2 * o.columns + c2);
          EXPECT_EQ(threads, linked) << "ring (" << c << "," << r << ") and (" << c2 << "," << r2 << ")";
          expected += linked;
          found += threads;
          degree += threads;
        }
      }
      const bool interior = r > 0 && r + 1 < o.rows && c > 0 && c + 1 < o.columns;
      if (interior) {
        EXPECT_EQ(degree, 4) << "interior ring (" << c << "," << r << ")";
      }
    }
  }
  EXPECT_EQ(found, expected);
}

TEST(Chainmail, DefaultsAreClosedDisjointLinkedRings) {
  const ChainmailOptions o;
  const TriMesh m = make_chainmail(o);
  EXPECT_GE(m.num_faces(), 2000u);
  EXPECT_LE(m.num_faces(), 20000u);
  check_swatch(m, {o.rows * o.columns, true, 0}, "chainmail_default");
  check_chainmail_links(m, o);
  check_round_trip(m, "chainmail_default");
  // Centred on z = 0 and periodic: the lattice's period is whole rings.
  const Box b = bounds(m);
  EXPECT_NEAR(b.lo.z, -b.hi.z, 1e-9);
  EXPECT_DOUBLE_EQ(chainmail_period(o).x, o.columns * o.pitch_x);
}

TEST(Chainmail, SmallPreset) {
  const ChainmailOptions o = ChainmailOptions::small();
  const TriMesh m = make_chainmail(o);
  EXPECT_GE(m.num_faces(), 300u);
  EXPECT_LE(m.num_faces(), 2000u);
  check_swatch(m, {o.rows * o.columns, true, 0}, "chainmail_small");
  check_chainmail_links(m, o);
  check_round_trip(m, "chainmail_small");
}

// Periodic: copies shifted by the period neither touch the swatch nor fail to link with it.
TEST(Chainmail, TilesWithItsPeriod) {
  const ChainmailOptions o = ChainmailOptions::small();
  const TriMesh m = make_chainmail(o);
  const glm::dvec2 period = chainmail_period(o);
  const int count = o.rows * o.columns;
  for (const Vec3 shift : {Vec3(period.x, 0, 0), Vec3(0, period.y, 0), Vec3(period.x, period.y, 0)}) {
    TriMesh both = m;
    const auto offset = static_cast<int32_t>(m.positions.size());
    for (const Vec3& p : m.positions) both.positions.push_back(p + shift);
    for (const Tri& t : m.triangles) both.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
    for (int32_t e : m.elements) both.elements.push_back(e + count);
    EXPECT_EQ(intersecting_pairs(both), 0);
  }
  // Shifted up by the period, row 0 of the copy sits where row `rows` would: the last row's
  // ring (c, rows-1) links copy rings (c, 0) and (c+1, 0), rows being odd/even alternately.
  TriMesh both = m;
  const auto offset = static_cast<int32_t>(m.positions.size());
  for (const Vec3& p : m.positions) both.positions.push_back(p + Vec3(0, period.y, 0));
  for (const Tri& t : m.triangles) both.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  for (int32_t e : m.elements) both.elements.push_back(e + count);
  const int last = (o.rows - 1) * o.columns;
  EXPECT_TRUE(threads_hole(both, last + 0, count + 0));
  EXPECT_TRUE(threads_hole(both, last + 0, count + 1));
  EXPECT_FALSE(threads_hole(both, last + 0, count + 2));
}

std::optional<ErrorKind> error_code(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << "one-line message";
    return e.kind();
  }
  return std::nullopt;
}

TEST(Chainmail, RejectsSizesThatWouldTouchOrNotLink) {
  auto with = [](auto change) {
    ChainmailOptions o = ChainmailOptions::small();
    change(o);
    return error_code([&] { make_chainmail(o); });
  };
  EXPECT_EQ(with([](ChainmailOptions& o) { o.wire_radius = 0.3; }), ErrorKind::invalid_option);
  EXPECT_EQ(with([](ChainmailOptions& o) { o.rows = 3; }), ErrorKind::invalid_option);
  EXPECT_EQ(with([](ChainmailOptions& o) { o.columns = 0; }), ErrorKind::invalid_option);
  EXPECT_EQ(with([](ChainmailOptions& o) { o.pitch_y = 2.5; }), ErrorKind::invalid_option);  // rows no longer link
  EXPECT_EQ(with([](ChainmailOptions& o) { o.tilt_degrees = 5.0; }), ErrorKind::invalid_option);
  EXPECT_EQ(with([](ChainmailOptions& o) { o.wire_segments = 2; }), ErrorKind::invalid_option);
  EXPECT_EQ(with([](ChainmailOptions&) {}), std::nullopt);
}

// ---------------------------------------------------------------------------------------------
// Weave.

// Height at which a vertical line through (x, y) meets the faces of one element, averaged over
// the hits (the yarn's top and bottom), or NaN when it misses.
double element_height_at(const TriMesh& m, int32_t element, double x, double y) {
  double sum = 0.0;
  int hits = 0;
  for (size_t f = 0; f < m.triangles.size(); ++f) {
    if (m.elements[f] != element) continue;
    const Vec3 &a = m.positions[m.triangles[f][0]], &b = m.positions[m.triangles[f][1]], &c = m.positions[m.triangles[f][2]];
    const double det = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
    if (std::abs(det) < 1e-15) continue;
    const double u = ((x - a.x) * (c.y - a.y) - (c.x - a.x) * (y - a.y)) / det;
    const double v = ((b.x - a.x) * (y - a.y) - (x - a.x) * (b.y - a.y)) / det;
    if (u < 0.0 || v < 0.0 || u + v > 1.0) continue;
    sum += a.z + u * (b.z - a.z) + v * (c.z - a.z);
    ++hits;
  }
  return hits ? sum / hits : NAN;
}

// Reads the pattern back from the geometry: at each crossing centre, which yarn is higher.
void check_weave_pattern(const TriMesh& m, const WeaveOptions& o, int warps, int wefts,
                         const std::function<bool(int, int)>& expected_warp_over, bool periodic = true) {
  const Box all = bounds(m);
  for (int i = 0; i < warps; ++i) {
    // Every warp spans the swatch along y, staying in its own column.
    Box b;
    for (size_t f = 0; f < m.triangles.size(); ++f)
      if (m.elements[f] == i)
        for (int32_t v : m.triangles[f]) b.add(m.positions[v]);
    EXPECT_NEAR(b.lo.y, all.lo.y, 0.5 * o.pitch) << "warp " << i;
    EXPECT_NEAR(b.hi.y, all.hi.y, 0.5 * o.pitch) << "warp " << i;
    EXPECT_LT(b.extent().x, o.pitch) << "warp " << i;
    EXPECT_GT(b.extent().y, (wefts - 0.5) * o.pitch) << "warp " << i;
  }
  for (int j = 0; j < wefts; ++j) {
    Box b;
    for (size_t f = 0; f < m.triangles.size(); ++f)
      if (m.elements[f] == warps + j)
        for (int32_t v : m.triangles[f]) b.add(m.positions[v]);
    EXPECT_NEAR(b.lo.x, all.lo.x, 0.5 * o.pitch) << "weft " << j;
    EXPECT_NEAR(b.hi.x, all.hi.x, 0.5 * o.pitch) << "weft " << j;
    EXPECT_LT(b.extent().y, o.pitch) << "weft " << j;
    EXPECT_GT(b.extent().x, (warps - 0.5) * o.pitch) << "weft " << j;
  }
  // Periodic: shifted by the period, each yarn's end section lands exactly on its start section
  // (its cap ring and cap centre), so tiled copies continue every yarn seamlessly.
  const double L_x = warps * o.pitch, L_y = wefts * o.pitch;
  for (int e = 0; periodic && e < warps + wefts; ++e) {
    const Vec3 shift = e < warps ? Vec3(0, L_y, 0) : Vec3(L_x, 0, 0);
    std::vector<Vec3> verts;
    for (size_t f = 0; f < m.triangles.size(); ++f)
      if (m.elements[f] == e)
        for (int32_t v : m.triangles[f]) verts.push_back(m.positions[v]);
    std::sort(verts.begin(), verts.end(), [](const Vec3& a, const Vec3& b) { return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z); });
    verts.erase(std::unique(verts.begin(), verts.end()), verts.end());
    int matched = 0;
    for (const Vec3& p : verts) {
      for (const Vec3& q : verts) matched += glm::length(p + shift - q) < 1e-9 * o.pitch;
    }
    EXPECT_GE(matched, o.sides + 1) << "yarn " << e;
  }
  int mismatches = 0;
  for (int j = 0; j < wefts; ++j) {
    for (int i = 0; i < warps; ++i) {
      const double x = (i + 0.5) * o.pitch, y = (j + 0.5) * o.pitch;
      const double warp_z = element_height_at(m, i, x, y), weft_z = element_height_at(m, warps + j, x, y);
      ASSERT_FALSE(std::isnan(warp_z) || std::isnan(weft_z)) << "crossing " << i << "," << j;
      mismatches += (warp_z > weft_z) != expected_warp_over(i, j);
    }
  }
  EXPECT_EQ(mismatches, 0);
}

int mod(int a, int n) { return ((a % n) + n) % n; }

TEST(Weave, DefaultsArePlainClosedDisjointYarns) {
  const WeaveOptions o;
  const TriMesh m = make_weave(o);
  EXPECT_GE(m.num_faces(), 2000u);
  EXPECT_LE(m.num_faces(), 20000u);
  check_swatch(m, {20, true, 2}, "weave_default");
  check_weave_pattern(m, o, 10, 10, [](int i, int j) { return mod(i - j, 2) == 0; });
  check_round_trip(m, "weave_default");
  const Box b = bounds(m);
  EXPECT_NEAR(b.lo.z, -b.hi.z, 1e-9);
  // Yarns end on the period's borders; a cap, perpendicular to its sloping yarn, may lean out by
  // less than the yarn radius.
  EXPECT_NEAR(b.lo.x, 0.0, o.yarn_radius);
  EXPECT_NEAR(b.hi.x, weave_period(o).x, o.yarn_radius);
  EXPECT_NEAR(b.lo.y, 0.0, o.yarn_radius);
  EXPECT_NEAR(b.hi.y, weave_period(o).y, o.yarn_radius);
}

TEST(Weave, SmallPreset) {
  const WeaveOptions o = WeaveOptions::small();
  const TriMesh m = make_weave(o);
  EXPECT_GE(m.num_faces(), 300u);
  EXPECT_LE(m.num_faces(), 2000u);
  check_swatch(m, {8, true, 2}, "weave_small");
  check_weave_pattern(m, o, 4, 4, [](int i, int j) { return mod(i - j, 2) == 0; });
  check_round_trip(m, "weave_small");
}

TEST(Weave, Twill23OnTenByTen) {
  WeaveOptions o = WeaveOptions::small();
  o.pattern = twill_pattern(2, 3);
  o.warps = o.wefts = 10;
  const TriMesh m = make_weave(o);
  check_swatch(m, {20, true, 2}, "weave_twill23");
  // Warp over two wefts, under three, each row shifted by one.
  check_weave_pattern(m, o, 10, 10, [](int i, int j) { return mod(i - j, 5) < 2; });
}

TEST(Weave, Satin41OnTenByTen) {
  WeaveOptions o = WeaveOptions::small();
  o.pattern = satin_pattern(4, 1);
  o.warps = o.wefts = 10;
  const TriMesh m = make_weave(o);
  check_swatch(m, {20, true, 2}, "weave_satin41");
  // 5-end satin: step 2 (1 < 2 < 4, coprime to 5); warp over four, under one.
  check_weave_pattern(m, o, 10, 10, [](int i, int j) { return mod(i - 2 * j, 5) < 4; });
  // Interlacings (the one "under" per row) of neighbouring rows are never adjacent.
  for (int j = 0; j < 5; ++j) {
    int under = -1, next = -1;
    for (int i = 0; i < 5; ++i) {
      if (!o.pattern.over(i, j)) under = i;
      if (!o.pattern.over(i, j + 1)) next = i;
    }
    EXPECT_NE(mod(next - under, 5), 1);
    EXPECT_NE(mod(under - next, 5), 1);
  }
}

TEST(Weave, RandomJacquardDesignFromAnImage) {
  // Every local over/under configuration turns up in a random design; the generator's clearance
  // analysis must hold for all of them, which the exact intersection check confirms.
  const fs::path dir = scratch("jacquard");
  const int n = 12;
  std::string pbm = "P1\n" + std::to_string(n) + " " + std::to_string(n) + "\n";
  uint64_t state = 12345;
  std::vector<std::vector<int>> black(n, std::vector<int>(n));
  for (int r = 0; r < n; ++r) {
    for (int c = 0; c < n; ++c) {
      state = state * 6364136223846793005ull + 1442695040888963407ull;
      black[r][c] = (state >> 33) & 1;
      pbm += black[r][c] ? "1 " : "0 ";
    }
    pbm += "\n";
  }
  std::ofstream(dir / "design.pbm") << pbm;
  WeaveOptions o = WeaveOptions::small();
  o.pattern = parse_weave_pattern((dir / "design.pbm").string());
  const TriMesh m = make_weave(o);
  check_swatch(m, {2 * n, true, 2}, "weave_jacquard");
  // Image row 0 is the top (largest y, the last weft); black puts the warp over.
  check_weave_pattern(m, o, n, n, [&](int i, int j) { return black[n - 1 - j][i] == 1; });
  fs::remove_all(dir);
}

TEST(Weave, RejectsBadCountsAndTouchingYarns) {
  auto with = [](auto change) {
    WeaveOptions o = WeaveOptions::small();
    change(o);
    return error_code([&] { make_weave(o); });
  };
  EXPECT_EQ(with([](WeaveOptions& o) { o.pattern = twill_pattern(2, 3), o.warps = 7; }), ErrorKind::invalid_option);
  EXPECT_EQ(with([](WeaveOptions& o) { o.yarn_radius = 0.45; }), ErrorKind::invalid_option);
  EXPECT_EQ(with([](WeaveOptions& o) { o.amplitude = 0.15; }), ErrorKind::invalid_option);  // crossings touch
  EXPECT_EQ(with([](WeaveOptions& o) { o.amplitude = 1.5; }), ErrorKind::invalid_option);   // yarn folds
  EXPECT_EQ(with([](WeaveOptions& o) { o.sides = 2; }), ErrorKind::invalid_option);
  EXPECT_EQ(with([](WeaveOptions&) {}), std::nullopt);
}

// Sparse crimped wire.

// Bounding box of one element's vertices.
Box element_bounds(const TriMesh& m, int32_t element) {
  Box b;
  for (size_t f = 0; f < m.triangles.size(); ++f)
    if (m.elements[f] == element)
      for (int32_t v : m.triangles[f]) b.add(m.positions[v]);
  return b;
}

// Each wire: centred on its own line at (n + 1/2) pitch, one radius to either side of it,
// the swatch's full length along it, and crimped: its z span is 2 (crimp + radius) within the
// facets' sag.
void check_wires(const TriMesh& m, const WeaveOptions& o, int first_element, int count, bool warp, int length) {
  for (int n = 0; n < count; ++n) {
    SCOPED_TRACE((warp ? "warp " : "weft ") + std::to_string(n));
    const Box b = element_bounds(m, first_element + n);
    const double across_lo = warp ? b.lo.x : b.lo.y, across_hi = warp ? b.hi.x : b.hi.y;
    const double along_lo = warp ? b.lo.y : b.lo.x, along_hi = warp ? b.hi.y : b.hi.x;
    // Section vertices sit at angles 2 pi k / sides from the across direction.
    double lowest_cos = 1.0;
    for (int k = 0; k < o.sides; ++k) lowest_cos = std::min(lowest_cos, std::cos(2.0 * std::numbers::pi * k / o.sides));
    EXPECT_NEAR(across_hi, (n + 0.5) * o.pitch + o.yarn_radius, 1e-9);
    EXPECT_NEAR(across_lo, (n + 0.5) * o.pitch + lowest_cos * o.yarn_radius, 1e-9);
    // Caps lean out by less than a radius past the swatch's borders.
    EXPECT_NEAR(along_lo, 0.0, o.yarn_radius);
    EXPECT_NEAR(along_hi, length * o.pitch, o.yarn_radius);
    EXPECT_GT(b.extent().z, 2.0 * (o.amplitude + o.yarn_radius) * 0.95);
    EXPECT_LE(b.extent().z, 2.0 * (o.amplitude + o.yarn_radius) + 1e-9);
  }
}

TEST(Wire, DefaultIsNineByNineSparseCrimpedPlainWeave) {
  const WeaveOptions o = WeaveOptions::wire();
  const TriMesh m = make_weave(o);
  EXPECT_EQ(m.num_faces(), 21024u);
  check_swatch(m, {18, true, 2}, "wire_default");  // closed tubes, no two touching (brute force)
  check_weave_pattern(m, o, 9, 9, [](int i, int j) { return mod(i - j, 2) == 0; }, false);
  check_round_trip(m, "wire_default");
  // Thin wires several diameters apart: the gap between parallel wires is at least 5 diameters.
  EXPECT_GE(o.pitch - 2.0 * o.yarn_radius, 5.0 * 2.0 * o.yarn_radius);
  check_wires(m, o, 0, 9, true, 9);
  check_wires(m, o, 9, 9, false, 9);
}

TEST(Wire, SmallPresetAndChosenSpacing) {
  const WeaveOptions small = WeaveOptions::small_wire();
  const TriMesh m = make_weave(small);
  EXPECT_LE(m.num_faces(), 2100u);
  check_swatch(m, {10, true, 2}, "wire_small");
  check_wires(m, small, 0, 5, true, 5);
  check_wires(m, small, 5, 5, false, 5);

  // Radius and pitch are independent: a wider spacing and a thinner wire, 7 x 4 wires.
  WeaveOptions o = small;
  o.pitch = 2.5;
  o.yarn_radius = 0.05;
  o.amplitude = 0.2;
  o.warps = 7;
  o.wefts = 4;
  const TriMesh wide = make_weave(o);
  check_swatch(wide, {11, true, 2}, "wire_wide");
  check_weave_pattern(wide, o, 7, 4, [](int i, int j) { return mod(i - j, 2) == 0; }, false);
  check_wires(wide, o, 0, 7, true, 4);
  check_wires(wide, o, 7, 4, false, 7);
}

TEST(Wire, OneDirectionBuildsOnlyThoseWires) {
  for (const WeaveYarns yarns : {WeaveYarns::warps, WeaveYarns::wefts}) {
    const bool warp = yarns == WeaveYarns::warps;
    SCOPED_TRACE(warp ? "warps" : "wefts");
    WeaveOptions o = WeaveOptions::small_wire();
    o.warps = 5;
    o.wefts = 3;
    o.yarns = yarns;
    const TriMesh m = make_weave(o);
    const int count = warp ? 5 : 3;
    check_swatch(m, {count, true, 2}, warp ? "wire_warps" : "wire_wefts");
    // Every element runs in the one direction, across the other direction's full length.
    check_wires(m, o, 0, count, warp, warp ? 3 : 5);
    // Exactly the faces of those wires in the two-direction swatch, in the same order.
    WeaveOptions both = o;
    both.yarns = WeaveYarns::both;
    const TriMesh full = make_weave(both);
    const int32_t first = warp ? 0 : 5;
    std::vector<Vec3> expected, got;
    for (size_t f = 0; f < full.triangles.size(); ++f)
      if (full.elements[f] >= first && full.elements[f] < first + count)
        for (int32_t v : full.triangles[f]) expected.push_back(full.positions[v]);
    for (const Tri& t : m.triangles)
      for (int32_t v : t) got.push_back(m.positions[v]);
    EXPECT_EQ(got, expected);
  }
  // Without crossings the crimp need not clear the other direction: an amplitude the two-way
  // swatch refuses is accepted for one direction.
  WeaveOptions flat = WeaveOptions::small_wire();
  flat.amplitude = 0.05;
  EXPECT_EQ(error_code([&] { make_weave(flat); }), ErrorKind::invalid_option);
  flat.yarns = WeaveYarns::wefts;
  EXPECT_EQ(error_code([&] { make_weave(flat); }), std::nullopt);
}

TEST(Wire, AnyCountOnlyWithoutWholeRepeats) {
  WeaveOptions o = WeaveOptions::small();  // whole repeats required, as before
  o.warps = 5;
  EXPECT_EQ(error_code([&] { make_weave(o); }), ErrorKind::invalid_option);
  o.whole_repeats = false;
  EXPECT_EQ(error_code([&] { make_weave(o); }), std::nullopt);
}

// The size checks are sound: swatches at the edge of what they accept still do not intersect.
template <class Options, class Make>
Options at_acceptance_limit(Options o, double Options::*field, double accepted, double rejected, Make make) {
  for (int it = 0; it < 20; ++it) {
    const double mid = 0.5 * (accepted + rejected);
    o.*field = mid;
    bool ok = true;
    try {
      make(o);
    } catch (const InputError&) {
      ok = false;
    }
    (ok ? accepted : rejected) = mid;
  }
  o.*field = accepted;
  return o;
}

TEST(SizeChecks, WeaveAtTheLimitDoesNotIntersect) {
  for (int segments : {3, 4, 6}) {
    WeaveOptions o = WeaveOptions::small();
    o.segments_per_pitch = segments;
    o.pattern = twill_pattern(1, 2);
    o.warps = o.wefts = 6;
    const WeaveOptions limit = at_acceptance_limit(o, &WeaveOptions::amplitude, 0.3, 0.05, make_weave);
    EXPECT_LT(limit.amplitude, 0.3);
    const TriMesh m = make_weave(limit);
    EXPECT_EQ(intersecting_pairs(m), 0) << "segments " << segments << " amplitude " << limit.amplitude;
  }
}

TEST(SizeChecks, ChainmailAtTheLimitDoesNotIntersect) {
  for (int segments : {8, 12, 24}) {
    ChainmailOptions o = ChainmailOptions::small();
    o.ring_segments = segments;
    const ChainmailOptions limit = at_acceptance_limit(o, &ChainmailOptions::wire_radius, 0.1, 0.4, make_chainmail);
    EXPECT_GT(limit.wire_radius, 0.15) << "segments " << segments;
    const TriMesh m = make_chainmail(limit);
    EXPECT_EQ(intersecting_pairs(m), 0) << "segments " << segments << " wire " << limit.wire_radius;
  }
}

// ---------------------------------------------------------------------------------------------
// Fruit and nuts.

TEST(Fruit, DefaultsAreClosedDisjointBlobs) {
  const FruitOptions o;
  const TriMesh m = make_fruit(o);
  EXPECT_GE(m.num_faces(), 2000u);
  EXPECT_LE(m.num_faces(), 21000u);
  check_swatch(m, {o.rows * o.columns, true, 2}, "fruit_default");
  check_round_trip(m, "fruit_default");
  EXPECT_NEAR(bounds(m).lo.z, 0.0, 1e-12);
}

TEST(Fruit, SmallPresetAndShapesVary) {
  const FruitOptions o = FruitOptions::small();
  const TriMesh m = make_fruit(o);
  EXPECT_GE(m.num_faces(), 300u);
  EXPECT_LE(m.num_faces(), 2000u);
  check_swatch(m, {4, true, 2}, "fruit_small");
  check_round_trip(m, "fruit_small");
  // Sizes vary: the elements' heights are not all equal.
  std::map<int32_t, Box> boxes;
  for (size_t f = 0; f < m.triangles.size(); ++f)
    for (int32_t v : m.triangles[f]) boxes[m.elements[f]].add(m.positions[v]);
  EXPECT_GT(std::abs(boxes[0].extent().z - boxes[1].extent().z), 1e-3);
}

TEST(Fruit, HasAStemPit) {
  // The highest points form a rim around the stem pit: near the rim's centre (the fruit's axis)
  // the surface stays well below the rim.
  FruitOptions o = FruitOptions::small();
  o.columns = o.rows = 1;
  o.subdivisions = 4;
  for (uint64_t seed : {1, 2, 3}) {
    o.seed = seed;
    const TriMesh m = make_fruit(o);
    std::vector<Vec3> by_height(m.positions);
    std::sort(by_height.begin(), by_height.end(), [](const Vec3& a, const Vec3& b) { return a.z > b.z; });
    const size_t rim = by_height.size() / 10;
    Vec3 axis(0.0);
    for (size_t k = 0; k < rim; ++k) axis += by_height[k] / static_cast<double>(rim);
    double top_at_axis = -INFINITY;
    for (const Vec3& p : m.positions)
      if (std::hypot(p.x - axis.x, p.y - axis.y) < 0.1 * o.radius) top_at_axis = std::max(top_at_axis, p.z);
    EXPECT_LT(top_at_axis, by_height.front().z - 0.05 * o.radius) << "seed " << seed;
  }
}

TEST(Nuts, DefaultsAreClosedGenusOneDisjoint) {
  const NutOptions o;
  const TriMesh m = make_nuts(o);
  EXPECT_GE(m.num_faces(), 2000u);
  EXPECT_LE(m.num_faces(), 20000u);
  check_swatch(m, {o.rows * o.columns, true, 0}, "nuts_default");
  check_round_trip(m, "nuts_default");
}

TEST(Nuts, SmallPresetHasHoleAndVariedRotation) {
  const NutOptions o = NutOptions::small();
  const TriMesh m = make_nuts(o);
  EXPECT_GE(m.num_faces(), 300u);
  EXPECT_LE(m.num_faces(), 2000u);
  check_swatch(m, {4, true, 0}, "nuts_small");
  check_round_trip(m, "nuts_small");
  // Per nut: no vertex closer to the axis than the hole; the direction of the farthest vertex
  // (a hexagon corner) differs between nuts modulo 60 degrees.
  std::map<int32_t, Box> boxes;
  for (size_t f = 0; f < m.triangles.size(); ++f)
    for (int32_t v : m.triangles[f]) boxes[m.elements[f]].add(m.positions[v]);
  std::vector<double> corner_angles;
  for (const auto& [e, box] : boxes) {
    const Vec3 c = 0.5 * (box.lo + box.hi);
    double nearest = INFINITY, farthest = 0.0, angle = 0.0;
    for (size_t f = 0; f < m.triangles.size(); ++f) {
      if (m.elements[f] != e) continue;
      for (int32_t v : m.triangles[f]) {
        const double r = std::hypot(m.positions[v].x - c.x, m.positions[v].y - c.y);
        nearest = std::min(nearest, r);
        if (r > farthest) farthest = r, angle = std::atan2(m.positions[v].y - c.y, m.positions[v].x - c.x);
      }
    }
    EXPECT_GT(nearest, 0.4 * o.hole_radius);
    corner_angles.push_back(std::fmod(angle + 6.0 * M_PI, M_PI / 3.0));
  }
  std::sort(corner_angles.begin(), corner_angles.end());
  EXPECT_GT(corner_angles.back() - corner_angles.front(), 0.05);
}

TEST(RandomKinds, SameSeedSameBytesOtherSeedOtherBytes) {
  const fs::path dir = scratch("determinism");
  auto bytes_of = [&](const TriMesh& m, const std::string& name) {
    write_mesh(m, dir / name);
    return file_bytes(dir / name);
  };
  FruitOptions f = FruitOptions::small();
  const std::string f1 = bytes_of(make_fruit(f), "f1.ply"), f2 = bytes_of(make_fruit(f), "f2.ply");
  f.seed = 2;
  const std::string f3 = bytes_of(make_fruit(f), "f3.ply");
  EXPECT_EQ(f1, f2);
  EXPECT_NE(f1, f3);
  NutOptions n = NutOptions::small();
  const std::string n1 = bytes_of(make_nuts(n), "n1.ply"), n2 = bytes_of(make_nuts(n), "n2.ply");
  n.seed = 2;
  const std::string n3 = bytes_of(make_nuts(n), "n3.ply");
  EXPECT_EQ(n1, n2);
  EXPECT_NE(n1, n3);
  fs::remove_all(dir);
}

// ---------------------------------------------------------------------------------------------
// Height field.

TEST(Heightfield, DefaultsAreAClosedSlab) {
  const HeightfieldOptions o;
  const TriMesh m = make_heightfield(o);
  EXPECT_GE(m.num_faces(), 2000u);
  EXPECT_LE(m.num_faces(), 20000u);
  check_swatch(m, {1, true, 2}, "heightfield_default");
  check_round_trip(m, "heightfield_default");
}

TEST(Heightfield, SmallPresetClosedAndOpen) {
  HeightfieldOptions o = HeightfieldOptions::small();
  const TriMesh closed = make_heightfield(o);
  EXPECT_LE(closed.num_faces(), 2000u);
  check_swatch(closed, {1, true, 2}, "heightfield_small");
  check_round_trip(closed, "heightfield_small");
  o.open = true;
  const TriMesh open = make_heightfield(o);
  EXPECT_EQ(open.num_faces(), 2u * 15 * 15);
  check_swatch(open, {1, false, 0}, "heightfield_small_open");
  check_round_trip(open, "heightfield_small_open");
  // The open sheet's boundary is the rim of the pixel grid.
  EXPECT_EQ(element_topology(open)[0].boundary_edges, 4 * 15);
  EXPECT_EQ(element_topology(open)[0].euler, 1);
}

TEST(Heightfield, TilesAreSeparateSlabsWithGrout) {
  HeightfieldOptions o = HeightfieldOptions::small();  // 16 x 16 pixels
  o.tiles = 4;                                         // 4 pixels a tile: 3 x 3 quads, one spacing apart
  const TriMesh tiles = make_heightfield(o);
  check_swatch(tiles, {16, true, 2}, "heightfield_tiles");
  check_round_trip(tiles, "heightfield_tiles");
  EXPECT_EQ(tiles.num_faces(), 16u * (4 * 3 * 3 + 4 * (3 + 3)));
  // Each tile's top is the one-piece slab's top over the same pixels: every tile vertex is a
  // vertex of the one-piece slab, and no two tiles come closer than one pixel spacing.
  const TriMesh whole = make_heightfield(HeightfieldOptions::small());
  std::set<std::tuple<double, double, double>> slab;
  for (const Vec3& p : whole.positions) slab.insert({p.x, p.y, p.z});
  for (const Vec3& p : tiles.positions) EXPECT_TRUE(slab.count({p.x, p.y, p.z})) << p.x << " " << p.y << " " << p.z;
  const double spacing = o.size / 15.0;
  std::map<int32_t, std::pair<glm::dvec2, glm::dvec2>> box;
  for (size_t f = 0; f < tiles.num_faces(); ++f)
    for (int32_t v : tiles.triangles[f]) {
      auto [it, fresh] = box.try_emplace(tiles.elements[f], glm::dvec2(1e300), glm::dvec2(-1e300));
      it->second.first = glm::min(it->second.first, glm::dvec2(tiles.positions[v]));
      it->second.second = glm::max(it->second.second, glm::dvec2(tiles.positions[v]));
    }
  for (const auto& [e, b] : box) EXPECT_NEAR(b.second.x - b.first.x, 3 * spacing, 1e-9) << e;
  for (const auto& [a, ba] : box)
    for (const auto& [b, bb] : box) {
      if (a >= b) continue;
      const double gap = std::max({bb.first.x - ba.second.x, ba.first.x - bb.second.x, bb.first.y - ba.second.y,
                                   ba.first.y - bb.second.y});
      EXPECT_GE(gap, spacing - 1e-9) << a << " " << b;
    }
  o.tiles = 6;  // 2 pixels a tile
  EXPECT_EQ(error_code([&] { make_heightfield(o); }), ErrorKind::invalid_option);
  o.tiles = 0;
  EXPECT_EQ(error_code([&] { make_heightfield(o); }), ErrorKind::invalid_option);
}

TEST(Heightfield, HeightsFollowTheImageUpright) {
  HeightfieldOptions o;
  o.image.width = 3;
  o.image.height = 2;
  o.image.values = {0.0, 0.25, 0.5,   // top row: largest y
                    0.75, 1.0, 0.1};  // bottom row: y = 0
  o.size = 4.0;  // spacing 2
  o.height = 1.0;
  o.base = 0.2;
  const TriMesh m = make_heightfield(o);
  check_swatch(m, {1, true, 2}, "heightfield_tiny");
  auto z_at = [&](double x, double y) {
    double best = -INFINITY;
    for (const Vec3& p : m.positions)
      if (std::abs(p.x - x) < 1e-12 && std::abs(p.y - y) < 1e-12) best = std::max(best, p.z);
    return best;
  };
  EXPECT_DOUBLE_EQ(z_at(0, 2), 0.0);
  EXPECT_DOUBLE_EQ(z_at(2, 2), 0.25);
  EXPECT_DOUBLE_EQ(z_at(4, 2), 0.5);
  EXPECT_DOUBLE_EQ(z_at(0, 0), 0.75);
  EXPECT_DOUBLE_EQ(z_at(2, 0), 1.0);
  EXPECT_DOUBLE_EQ(z_at(4, 0), 0.1);
  EXPECT_DOUBLE_EQ(bounds(m).lo.z, -0.2);
}

TEST(Heightfield, RejectsReliefThickerThanWide) {
  HeightfieldOptions o = HeightfieldOptions::small();
  o.height = 20.0;
  EXPECT_EQ(error_code([&] { make_heightfield(o); }), ErrorKind::invalid_option);
  o = HeightfieldOptions::small();
  o.image.width = 1;
  o.image.height = 5;
  o.image.values.assign(5, 0.5);
  EXPECT_EQ(error_code([&] { make_heightfield(o); }), ErrorKind::invalid_option);
}

TEST(Heightfield, LargeImagesAreBoxFiltered) {
  GrayImage image;
  image.width = 8;
  image.height = 4;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 8; ++c) image.values.push_back(c < 4 ? 0.0 : 1.0);
  const GrayImage small = downsample_image(image, 4);
  ASSERT_EQ(small.width, 4);
  ASSERT_EQ(small.height, 2);
  EXPECT_DOUBLE_EQ(small.at(0, 0), 0.0);
  EXPECT_DOUBLE_EQ(small.at(1, 1), 0.0);
  EXPECT_DOUBLE_EQ(small.at(2, 0), 1.0);
  EXPECT_DOUBLE_EQ(small.at(3, 1), 1.0);
}

}  // namespace
}  // namespace meshquilt
