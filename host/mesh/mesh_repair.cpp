#include "mesh/mesh_repair.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <unordered_map>
#include <unordered_set>

#include <glm/geometric.hpp>

#include "core/error.h"
#include "mesh/disjoint_sets.h"
#include "mesh/measures.h"
#include "mesh/topology.h"
#include "mesh/validation.h"

namespace meshquilt {
namespace {

// The mesh being repaired and, per face, the face of the file it came from (for messages).
struct Work {
  TriMesh mesh;
  std::vector<int32_t> face_from;
};

void keep_faces(Work& w, const std::vector<char>& keep) {
  TriMesh& m = w.mesh;
  size_t next = 0;
  const bool with_elements = m.elements.size() == m.triangles.size();
  const bool with_sources = m.sources.size() == m.triangles.size();
  for (size_t f = 0; f < m.triangles.size(); ++f) {
    if (!keep[f]) continue;
    m.triangles[next] = m.triangles[f];
    w.face_from[next] = w.face_from[f];
    if (with_elements) m.elements[next] = m.elements[f];
    if (with_sources) m.sources[next] = m.sources[f];
    ++next;
  }
  m.triangles.resize(next);
  w.face_from.resize(next);
  if (with_elements) m.elements.resize(next);
  if (with_sources) m.sources.resize(next);
}

// Drops the vertices no face uses, keeping the others' order; returns how many.
int64_t drop_unused_vertices(TriMesh& m) {
  std::vector<int32_t> remap(m.positions.size(), -1);
  for (const Tri& t : m.triangles)
    for (int32_t v : t) remap[v] = 0;
  int32_t next = 0;
  const bool with_origins = m.origins.size() == m.positions.size();
  const bool with_colors = m.colors.size() == m.positions.size();
  for (size_t v = 0; v < remap.size(); ++v) {
    if (remap[v] < 0) continue;
    remap[v] = next;
    m.positions[next] = m.positions[v];
    if (with_origins) m.origins[next] = m.origins[v];
    if (with_colors) m.colors[next] = m.colors[v];
    ++next;
  }
  const int64_t dropped = static_cast<int64_t>(m.positions.size()) - next;
  m.positions.resize(next);
  if (with_origins) m.origins.resize(next);
  if (with_colors) m.colors.resize(next);
  for (Tri& t : m.triangles)
    for (int32_t& v : t) v = remap[v];
  return dropped;
}

void add_face(Work& w, const Tri& t, size_t like) {
  TriMesh& m = w.mesh;
  m.triangles.push_back(t);
  w.face_from.push_back(w.face_from[like]);
  if (m.elements.size() + 1 == m.triangles.size()) m.elements.push_back(m.elements[like]);
  if (m.sources.size() + 1 == m.triangles.size()) m.sources.push_back(m.sources[like]);
}

// Largest weld tolerance as a share of the median edge length.
constexpr double kMaxWeldEdgeShare = 1e-3;

// Median length of the edges of faces whose corners differ, 0 when there are none.
double median_edge(const TriMesh& m) {
  std::vector<double> lengths;
  lengths.reserve(3 * m.triangles.size());
  for (const Tri& t : m.triangles)
    for (int k = 0; k < 3; ++k) {
      const double length = glm::length(m.positions[t[(k + 1) % 3]] - m.positions[t[k]]);
      if (length > 0.0) lengths.push_back(length);
    }
  if (lengths.empty()) return 0.0;
  std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 2, lengths.end());
  return lengths[lengths.size() / 2];
}

struct TriKeyHash {
  size_t operator()(const Tri& t) const {
    return std::hash<uint64_t>()(directed_edge_key(t[0], t[1]) * 0x9e3779b97f4a7c15ull ^ static_cast<uint32_t>(t[2]));
  }
};

// Splits each face whose edge is open (used by no other face) at the open vertices that
// lie on that edge within `tolerance`, fanning the face out from its opposite corner.
int64_t close_t_junctions(Work& w, double tolerance) {
  TriMesh& m = w.mesh;
  int64_t splits = 0;
  for (int round = 0; round < 8; ++round) {
    std::unordered_map<uint64_t, int32_t> uses;
    uses.reserve(m.triangles.size() * 2);
    for (const Tri& t : m.triangles)
      for (int k = 0; k < 3; ++k) ++uses[undirected_edge_key(t[k], t[(k + 1) % 3])];
    struct OpenEdge {
      int32_t face, local;
    };
    std::vector<OpenEdge> open;
    std::vector<int32_t> open_vertices;
    std::vector<double> lengths;
    for (size_t f = 0; f < m.triangles.size(); ++f)
      for (int k = 0; k < 3; ++k) {
        const int32_t a = m.triangles[f][k], b = m.triangles[f][(k + 1) % 3];
        if (uses[undirected_edge_key(a, b)] != 1) continue;
        open.push_back({static_cast<int32_t>(f), k});
        open_vertices.push_back(a);
        open_vertices.push_back(b);
        lengths.push_back(glm::length(m.positions[b] - m.positions[a]));
      }
    if (open.empty()) break;
    std::sort(open_vertices.begin(), open_vertices.end());
    open_vertices.erase(std::unique(open_vertices.begin(), open_vertices.end()), open_vertices.end());
    std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 2, lengths.end());
    const double cell = std::max(lengths[lengths.size() / 2], 4.0 * tolerance);
    // Cells counted from the mesh's low corner and clamped, so that a far or huge coordinate
    // cannot overflow a cell index (keys wrap; distances decide).
    const Vec3 origin = bounding_box(m.positions).lo;
    auto cell_of = [cell, origin](const Vec3& p) {
      const Vec3 at = glm::clamp(glm::floor((p - origin) / cell), Vec3(0.0), Vec3(double(int64_t{1} << 40)));
      return glm::i64vec3(at);
    };
    auto key_of = [](const glm::i64vec3& c) {
      return static_cast<uint64_t>(c.x & 0x1fffff) | static_cast<uint64_t>(c.y & 0x1fffff) << 21 |
             static_cast<uint64_t>(c.z & 0x1fffff) << 42;
    };
    std::unordered_map<uint64_t, std::vector<int32_t>> grid;
    for (int32_t v : open_vertices) grid[key_of(cell_of(m.positions[v]))].push_back(v);

    std::vector<char> split(m.triangles.size(), 0);
    int64_t round_splits = 0;
    for (const OpenEdge& e : open) {
      if (split[e.face]) continue;
      const Tri t = m.triangles[e.face];
      const int32_t a = t[e.local], b = t[(e.local + 1) % 3], c = t[(e.local + 2) % 3];
      const Vec3 pa = m.positions[a], ab = m.positions[b] - pa;
      const double length2 = glm::dot(ab, ab);
      if (!(length2 > 0.0)) continue;
      std::vector<std::pair<double, int32_t>> on_edge;
      const glm::i64vec3 lo = cell_of(glm::min(pa, m.positions[b]) - Vec3(tolerance));
      const glm::i64vec3 hi = cell_of(glm::max(pa, m.positions[b]) + Vec3(tolerance));
      const glm::dvec3 span = glm::dvec3(hi - lo) + 1.0;
      if (span.x * span.y * span.z > 4096.0) continue;  // a stray long edge
      for (int64_t x = lo.x; x <= hi.x; ++x)
        for (int64_t y = lo.y; y <= hi.y; ++y)
          for (int64_t z = lo.z; z <= hi.z; ++z) {
            const auto found = grid.find(key_of({x, y, z}));
            if (found == grid.end()) continue;
            for (int32_t v : found->second) {
              if (v == a || v == b || v == c) continue;
              const Vec3 av = m.positions[v] - pa;
              const double s = glm::dot(av, ab) / length2;
              const double along = s * std::sqrt(length2);
              if (along <= tolerance || (1.0 - s) * std::sqrt(length2) <= tolerance) continue;
              if (glm::length(av - s * ab) > tolerance) continue;
              on_edge.emplace_back(s, v);
            }
          }
      if (on_edge.empty()) continue;
      std::sort(on_edge.begin(), on_edge.end());
      on_edge.erase(std::unique(on_edge.begin(), on_edge.end(),
                                [](const auto& p, const auto& q) { return p.second == q.second; }),
                    on_edge.end());
      m.triangles[e.face] = {a, on_edge[0].second, c};
      int32_t from = on_edge[0].second;
      for (size_t i = 1; i < on_edge.size(); ++i) {
        add_face(w, {from, on_edge[i].second, c}, e.face);
        from = on_edge[i].second;
      }
      add_face(w, {from, b, c}, e.face);
      split[e.face] = 1;
      ++round_splits;
    }
    splits += round_splits;
    if (round_splits == 0) break;
  }
  return splits;
}

// Undirected edge -> (face, local edge index) of the faces using it.
using EdgeFaces = std::unordered_map<uint64_t, std::vector<std::pair<int32_t, int>>>;

EdgeFaces edge_faces(const Work& w, const std::string& source, int64_t welded) {
  const TriMesh& m = w.mesh;
  EdgeFaces faces;
  faces.reserve(m.triangles.size() * 2);
  for (size_t f = 0; f < m.triangles.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      auto& list = faces[undirected_edge_key(m.triangles[f][k], m.triangles[f][(k + 1) % 3])];
      list.emplace_back(static_cast<int32_t>(f), k);
    }
  for (const auto& [edge, list] : faces) {
    if (list.size() <= 2) continue;
    std::vector<int32_t> named;
    for (const auto& [f, k] : list) named.push_back(w.face_from[f]);
    std::sort(named.begin(), named.end());
    std::string text;
    for (size_t i = 0; i < std::min<size_t>(named.size(), 4); ++i) text += (i ? ", " : "") + std::to_string(named[i]);
    if (named.size() > 4) text += ", ...";
    // Welding makes such edges where coordinates lost their precision (floats far from the origin).
    const std::string after =
        welded > 0 ? " after welding " + std::to_string(welded) + " coincident vertices" : std::string();
    throw InputError(source + ": non-manifold edge shared by " + std::to_string(list.size()) + " faces (faces " +
                     text + ")" + after + ": no safe repair; separate or delete the extra faces");
  }
  return faces;
}

// Gives each fan of faces around a vertex its own vertex where several fans meet at one.
int64_t split_pinched_vertices(Work& w, const EdgeFaces& faces) {
  TriMesh& m = w.mesh;
  auto corner = [&m](int32_t f, int32_t v) {
    const Tri& t = m.triangles[f];
    return 3 * f + (t[0] == v ? 0 : t[1] == v ? 1 : 2);
  };
  DisjointSets fans(3 * m.triangles.size());
  for (const auto& [edge, list] : faces) {
    if (list.size() != 2) continue;
    const auto [f, k] = list[0];
    const int32_t g = list[1].first;
    for (int32_t v : {m.triangles[f][k], m.triangles[f][(k + 1) % 3]}) fans.unite(corner(f, v), corner(g, v));
  }
  std::vector<char> taken(m.positions.size(), 0);
  std::unordered_map<int32_t, int32_t> vertex_of_fan;
  int64_t copies = 0;
  const bool with_origins = m.origins.size() == m.positions.size();
  const bool with_colors = m.colors.size() == m.positions.size();
  for (size_t f = 0; f < m.triangles.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int32_t v = m.triangles[f][k];
      const int32_t root = static_cast<int32_t>(fans.find(3 * f + k));
      auto [it, inserted] = vertex_of_fan.emplace(root, v);
      if (inserted && std::exchange(taken[v], 1)) {
        it->second = static_cast<int32_t>(m.positions.size());
        m.positions.push_back(m.positions[v]);
        if (with_origins) m.origins.push_back(m.origins[v]);
        if (with_colors) m.colors.push_back(m.colors[v]);
        ++copies;
      }
      m.triangles[f][k] = it->second;
    }
  return copies;
}

// Winds each edge-connected part coherently and outward (see repair_mesh); counts the faces
// turned and the parts holding them.
void orient_parts(Work& w, const EdgeFaces& faces_of_edge, const std::string& source, MeshRepairs& repairs) {
  TriMesh& m = w.mesh;
  const size_t face_count = m.triangles.size();
  std::vector<int8_t> flip(face_count, -1);
  std::vector<int32_t> queue;
  for (size_t start = 0; start < face_count; ++start) {
    if (flip[start] >= 0) continue;
    flip[start] = 0;
    queue.assign(1, static_cast<int32_t>(start));
    bool closed = true;
    for (size_t head = 0; head < queue.size(); ++head) {
      const int32_t f = queue[head];
      const Tri& t = m.triangles[f];
      for (int k = 0; k < 3; ++k) {
        // Direction of the edge as f will finally run it.
        int32_t a = t[k], b = t[(k + 1) % 3];
        if (flip[f]) std::swap(a, b);
        const auto& sharing = faces_of_edge.at(undirected_edge_key(a, b));
        if (sharing.size() < 2) closed = false;
        for (const auto& [g, local] : sharing) {
          if (g == f) continue;
          const int8_t wanted = m.triangles[g][local] == a ? 1 : 0;  // g runs a -> b too
          if (flip[g] < 0) {
            flip[g] = wanted;
            queue.push_back(g);
          } else if (flip[g] != wanted) {
            throw InputError(source + ": non-orientable part (a Moebius-like strip around face " +
                             std::to_string(w.face_from[g]) + "): no consistent winding exists");
          }
        }
      }
    }
    // Outward: closed, a positive signed volume; open (a scan with a hole at the neck), a positive
    // volume of the cone from the part's centroid, i.e. the faces mostly look away from it.
    // A flat or nearly flat open sheet has no outside: it keeps its first face's orientation.
    Vec3 centre(0.0);
    double area = 0.0;
    for (int32_t f : queue) {
      const Tri& t = m.triangles[f];
      const Vec3 &a = m.positions[t[0]], &b = m.positions[t[1]], &c = m.positions[t[2]];
      const double weight = 0.5 * glm::length(glm::cross(b - a, c - a));
      centre += weight * (a + b + c) / 3.0;
      area += weight;
    }
    if (area > 0.0) centre /= area;
    double volume = 0.0, extent = 0.0;
    for (int32_t f : queue) {
      Tri t = m.triangles[f];
      if (flip[f]) std::swap(t[1], t[2]);
      const Vec3 a = m.positions[t[0]] - centre, b = m.positions[t[1]] - centre, c = m.positions[t[2]] - centre;
      volume += glm::dot(a, glm::cross(b, c)) / 6.0;
      extent = std::max({extent, glm::length(a), glm::length(b), glm::length(c)});
    }
    const bool flat_sheet = !closed && std::abs(volume) <= 1e-3 * area * extent;
    if (!flat_sheet && volume < 0.0)
      for (int32_t f : queue) flip[f] = static_cast<int8_t>(1 - flip[f]);
    int64_t turned = 0;
    for (int32_t f : queue) turned += flip[f];
    repairs.rewound_faces += turned;
    repairs.rewound_parts += turned > 0 ? 1 : 0;
  }
  for (size_t f = 0; f < face_count; ++f)
    if (flip[f] > 0) std::swap(m.triangles[f][1], m.triangles[f][2]);
}

}  // namespace

bool MeshRepairs::any() const {
  for (const auto& [name, count] : counts())
    if (count > 0) return true;
  return false;
}

std::vector<std::pair<std::string, int64_t>> MeshRepairs::counts() const {
  return {{"unused_vertices", unused_vertices}, {"welded_vertices", welded_vertices},
          {"collapsed_faces", collapsed_faces}, {"duplicate_faces", duplicate_faces},
          {"zero_area_faces", zero_area_faces}, {"t_junctions", t_junctions},
          {"split_vertices", split_vertices},   {"rewound_faces", rewound_faces},
          {"rewound_parts", rewound_parts}};
}

std::string MeshRepairs::describe(const std::string& part_name) const {
  std::string text;
  auto add = [&text](int64_t n, const std::string& what) {
    if (n > 0) text += (text.empty() ? "" : ", ") + what;
  };
  add(rewound_faces, "rewound " + std::to_string(rewound_faces) + " faces in " + std::to_string(rewound_parts) +
                         " " + part_name);
  add(welded_vertices, "welded " + std::to_string(welded_vertices) + " duplicate vertices");
  add(unused_vertices, "dropped " + std::to_string(unused_vertices) + " unused vertices");
  add(collapsed_faces, "dropped " + std::to_string(collapsed_faces) + " collapsed faces");
  add(duplicate_faces, "dropped " + std::to_string(duplicate_faces) + " duplicate faces");
  add(zero_area_faces, "dropped " + std::to_string(zero_area_faces) + " zero-area faces");
  add(t_junctions, "closed " + std::to_string(t_junctions) + " T-junctions");
  add(split_vertices, "split " + std::to_string(split_vertices) + " pinched vertices");
  return text;
}

RepairedMesh repair_mesh(const TriMesh& input, const std::string& source, double relative_tolerance) {
  validate_mesh(input, source);
  RepairedMesh result;
  MeshRepairs& repairs = result.repairs;
  Work w{input, std::vector<int32_t>(input.triangles.size())};
  std::iota(w.face_from.begin(), w.face_from.end(), 0);
  TriMesh& m = w.mesh;
  if (m.origins.size() != m.positions.size()) {
    m.origins.resize(m.positions.size());
    std::iota(m.origins.begin(), m.origins.end(), 0);
  }
  repairs.unused_vertices = drop_unused_vertices(m);

  // The tolerance follows the bounding box, but never beyond a small share of an edge: a stray
  // face far away would otherwise weld the whole mesh into a few points.
  const double diagonal = glm::length(bounding_box(m.positions).extent());
  const double tolerance = std::min(relative_tolerance * diagonal, kMaxWeldEdgeShare * median_edge(m));
  const std::vector<int32_t> representative =
      weld_representatives(m.positions, diagonal > 0.0 ? tolerance / diagonal : 0.0);
  for (size_t v = 0; v < representative.size(); ++v) repairs.welded_vertices += representative[v] != int32_t(v);
  std::vector<char> keep(m.triangles.size(), 1);
  std::unordered_set<Tri, TriKeyHash> corners;
  corners.reserve(m.triangles.size());
  for (size_t f = 0; f < m.triangles.size(); ++f) {
    Tri& t = m.triangles[f];
    for (int32_t& v : t) v = representative[v];
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) {
      keep[f] = 0;
      ++repairs.collapsed_faces;
      continue;
    }
    Tri sorted = t;
    std::sort(sorted.begin(), sorted.end());
    if (!corners.insert(sorted).second) {
      keep[f] = 0;
      ++repairs.duplicate_faces;
      continue;
    }
    const Vec3 &a = m.positions[t[0]], &b = m.positions[t[1]], &c = m.positions[t[2]];
    const double longest = std::max({glm::length(b - a), glm::length(c - b), glm::length(a - c)});
    if (glm::length(glm::cross(b - a, c - a)) <= tolerance * longest) {  // height below the tolerance
      keep[f] = 0;
      ++repairs.zero_area_faces;
    }
  }
  keep_faces(w, keep);
  if (m.triangles.empty())
    throw InputError(source + ": no face has area (every face has its corners on a line or two of them equal)");
  repairs.t_junctions = close_t_junctions(w, tolerance);
  drop_unused_vertices(m);

  EdgeFaces faces = edge_faces(w, source, repairs.welded_vertices);
  repairs.split_vertices = split_pinched_vertices(w, faces);
  if (repairs.split_vertices > 0) faces = edge_faces(w, source, repairs.welded_vertices);
  orient_parts(w, faces, source, repairs);

  if (!repairs.any()) {
    result.mesh = input;
    return result;
  }
  result.mesh = std::move(m);
  return result;
}

}  // namespace meshquilt
