#include "shell/texture_atlas.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <queue>
#include <unordered_map>

#include "mesh/topology.h"
#include "surface/conformal_patch.h"

namespace meshquilt {
namespace {

double cross2(const glm::dvec2& a, const glm::dvec2& b) { return a.x * b.y - a.y * b.x; }

// A chart being grown: its faces, flattened.
struct Chart {
  std::vector<int32_t> faces;
  std::vector<int32_t> corner_vertex;  // 3 per face, local vertex
  std::vector<int32_t> vertex_base;    // local vertex -> base vertex
  std::vector<glm::dvec2> uv;
};

class AtlasBuilder {
 public:
  AtlasBuilder(const BaseSurface& base, const AtlasOptions& options) : base_(base), options_(options) {
    const TriMesh& mesh = base.mesh;
    const size_t faces = mesh.num_faces();
    across_ = face_neighbors(mesh);  // prepared bases have no non-manifold edges (-2)
    base_boundary_.assign(mesh.num_vertices(), 0);
    for (size_t f = 0; f < faces; ++f)
      for (int k = 0; k < 3; ++k)
        if (across_[f][k] < 0) {
          base_boundary_[mesh.triangles[f][k]] = 1;
          base_boundary_[mesh.triangles[f][(k + 1) % 3]] = 1;
        }
    centroid_.resize(faces);
    for (size_t f = 0; f < faces; ++f) {
      const Tri& t = mesh.triangles[f];
      centroid_[f] = (mesh.positions[t[0]] + mesh.positions[t[1]] + mesh.positions[t[2]]) / 3.0;
    }
    face_stamp_.assign(faces, -1);
    vertex_stamp_.assign(mesh.num_vertices(), -1);
  }

  TextureAtlas build() {
    const size_t faces = base_.mesh.num_faces();
    atlas_.face_chart.assign(faces, -1);
    atlas_.corners.assign(faces, {-1, -1, -1});
    for (size_t seed = 0; seed < faces; ++seed) {
      if (atlas_.face_chart[seed] >= 0) continue;
      double angle = options_.max_normal_angle;
      for (int attempt = 0;; ++attempt) {
        Chart chart = grow(static_cast<int32_t>(seed), angle);
        const bool last = chart.faces.size() == 1 || attempt >= 5;
        if (flatten(chart) || last) {
          commit(chart);
          break;
        }
        angle *= 0.6;
      }
    }
    return std::move(atlas_);
  }

 private:
  Chart grow(int32_t seed, double angle) {
    const TriMesh& mesh = base_.mesh;
    const int stamp = ++stamp_;
    const Vec3 axis = base_.face_normals[seed];
    const double min_cos = std::cos(angle);
    Chart chart;
    using Entry = std::pair<double, int32_t>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
    const auto add = [&](int32_t f) {
      chart.faces.push_back(f);
      face_stamp_[f] = stamp;
      for (int32_t v : mesh.triangles[f]) vertex_stamp_[v] = stamp;
      for (int k = 0; k < 3; ++k) {
        const int32_t g = across_[f][k];
        if (g >= 0 && face_stamp_[g] != stamp && atlas_.face_chart[g] < 0)
          queue.emplace(glm::distance(centroid_[g], centroid_[seed]), g);
      }
    };
    add(seed);
    while (!queue.empty() && static_cast<int32_t>(chart.faces.size()) < options_.max_chart_faces) {
      const int32_t g = queue.top().second;
      queue.pop();
      if (face_stamp_[g] == stamp) continue;
      // Stays a disk: one shared edge and a new third vertex, or two shared edges (a notch).
      int shared = 0, new_vertex = -1;
      for (int k = 0; k < 3; ++k) {
        const int32_t h = across_[g][k];
        if (h >= 0 && face_stamp_[h] == stamp) ++shared;
      }
      for (int32_t v : mesh.triangles[g])
        if (vertex_stamp_[v] != stamp) new_vertex = v;
      if (shared == 1 && new_vertex < 0) continue;
      if (shared != 1 && shared != 2) continue;
      const bool degenerate = base_.face_areas[g] <= 0.0;
      if (degenerate ? shared != 2 : glm::dot(base_.face_normals[g], axis) < min_cos) continue;
      add(g);
    }
    std::unordered_map<int32_t, int32_t> local;
    for (int32_t f : chart.faces)
      for (int32_t v : mesh.triangles[f]) {
        const auto [it, fresh] = local.emplace(v, static_cast<int32_t>(chart.vertex_base.size()));
        if (fresh) chart.vertex_base.push_back(v);
        chart.corner_vertex.push_back(it->second);
      }
    return chart;
  }

  // Flattens and scales the chart; false when it folds or is too distorted.
  bool flatten(Chart& chart) {
    chart.uv = conformal_flattening(base_, chart.faces, chart.corner_vertex, chart.vertex_base);
    double plane_area = 0.0, base_area = 0.0;
    std::vector<double> signed_areas(chart.faces.size());
    for (size_t f = 0; f < chart.faces.size(); ++f) {
      const int32_t* v = &chart.corner_vertex[3 * f];
      signed_areas[f] = 0.5 * cross2(chart.uv[v[1]] - chart.uv[v[0]], chart.uv[v[2]] - chart.uv[v[0]]);
      plane_area += signed_areas[f];
      base_area += base_.face_areas[chart.faces[f]];
    }
    if (!(plane_area > 0.0) || !std::isfinite(plane_area)) return false;
    const double scale = std::sqrt(base_area / plane_area);
    for (glm::dvec2& p : chart.uv) p *= scale;
    double lo = std::numeric_limits<double>::max(), hi = 0.0;
    for (size_t f = 0; f < chart.faces.size(); ++f) {
      const double area = base_.face_areas[chart.faces[f]];
      if (area <= 1e-12 * base_area) continue;
      const double ratio = signed_areas[f] * scale * scale / area;
      if (!(ratio > 0.0)) return false;
      lo = std::min(lo, ratio);
      hi = std::max(hi, ratio);
    }
    return hi <= options_.max_area_distortion * lo;
  }

  void commit(const Chart& chart) {
    const int32_t id = atlas_.charts++;
    const int32_t first = static_cast<int32_t>(atlas_.vertex_base.size());
    for (int32_t f : chart.faces) atlas_.face_chart[f] = id;
    for (size_t k = 0; k < chart.vertex_base.size(); ++k) {
      const int32_t v = chart.vertex_base[k];
      atlas_.vertex_base.push_back(v);
      atlas_.vertex_chart.push_back(id);
      atlas_.uv.push_back(chart.uv[k]);
      bool interior = !base_boundary_[v];
      for (int32_t f : base_.vertex_faces[v]) interior = interior && atlas_.face_chart[f] == id;
      atlas_.on_boundary.push_back(interior ? 0 : 1);
    }
    for (size_t f = 0; f < chart.faces.size(); ++f)
      for (int k = 0; k < 3; ++k) atlas_.corners[chart.faces[f]][k] = first + chart.corner_vertex[3 * f + k];
  }

  const BaseSurface& base_;
  AtlasOptions options_;
  TextureAtlas atlas_;
  std::vector<std::array<int32_t, 3>> across_;  // face across each edge, -1 on the boundary
  std::vector<uint8_t> base_boundary_;
  std::vector<Vec3> centroid_;
  std::vector<int> face_stamp_, vertex_stamp_;
  int stamp_ = 0;
};

}  // namespace

glm::dvec2 TextureAtlas::to_texture(const SurfacePoint& p) const {
  const std::array<int32_t, 3>& c = corners[p.face];
  return (1.0 - p.bary.x - p.bary.y) * uv[c[0]] + p.bary.x * uv[c[1]] + p.bary.y * uv[c[2]];
}

TextureAtlas build_texture_atlas(const BaseSurface& base, const AtlasOptions& options) {
  return AtlasBuilder(base, options).build();
}

}  // namespace meshquilt
