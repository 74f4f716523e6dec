#include "surface/guidance_field.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "numerics/sparse_solve.h"
#include "numerics/symmetric_eigen.h"
#include "core/atomic_write.h"

namespace meshquilt {
namespace {

// The base vertex nearest p; ties (and a difference that overflows) go to the first; -1 without
// vertices. hypot, not glm::distance: the squares overflow for a point beyond about 1e154, every
// distance would be infinite and no vertex chosen.
int32_t nearest_vertex(const TriMesh& base, const Vec3& p) {
  int32_t nearest = -1;
  double best = std::numeric_limits<double>::infinity();
  for (size_t v = 0; v < base.num_vertices(); ++v) {
    const Vec3 d = p - base.positions[v];
    const double distance = std::hypot(d.x, d.y, d.z);
    if (nearest < 0 || distance < best) {
      best = distance;
      nearest = static_cast<int32_t>(v);
    }
  }
  return nearest;
}

Vec3 tangent_part(const Vec3& d, const Vec3& n) { return d - glm::dot(d, n) * n; }

// Any unit vector perpendicular to n.
Vec3 any_tangent(const Vec3& n) {
  const Vec3 helper = std::abs(n.x) < 0.9 ? Vec3(1.0, 0.0, 0.0) : Vec3(0.0, 1.0, 0.0);
  return glm::normalize(glm::cross(n, helper));
}

Vec3 parse_vector(const nlohmann::json& value, const std::string& what, const std::string& where) {
  if (!value.is_array() || value.size() != 3)
    throw InputError(where + ": '" + what + "' must be an array of three numbers", ErrorKind::invalid_option);
  Vec3 v;
  for (int k = 0; k < 3; ++k) {
    if (!value[k].is_number())
      throw InputError(where + ": '" + what + "' must be an array of three numbers", ErrorKind::invalid_option);
    v[k] = value[k].get<double>();
  }
  if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
    throw InputError(where + ": '" + what + "' is not finite", ErrorKind::invalid_option);
  return v;
}

// Principal axis of the area-weighted vertices (largest eigenvalue of their covariance).
Vec3 principal_axis(const BaseSurface& base) {
  const TriMesh& mesh = base.mesh;
  std::vector<double> weight(mesh.num_vertices(), 0.0);
  for (size_t f = 0; f < mesh.num_faces(); ++f)
    for (int32_t v : mesh.triangles[f]) weight[v] += base.face_areas[f] / 3.0;
  double total = 0.0;
  Vec3 mean(0.0);
  for (size_t v = 0; v < mesh.num_vertices(); ++v) {
    total += weight[v];
    mean += weight[v] * mesh.positions[v];
  }
  if (total <= 0.0) return Vec3(1.0, 0.0, 0.0);
  mean /= total;
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (size_t v = 0; v < mesh.num_vertices(); ++v) {
    const Vec3 d = mesh.positions[v] - mean;
    const Eigen::Vector3d e(d.x, d.y, d.z);
    covariance += weight[v] * e * e.transpose();
  }
  Symmetric3 matrix;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) matrix[i][j] = covariance(i, j);
  Vec3 a = symmetric_eigenvectors(matrix)[2];
  // A deterministic sign: the largest component positive.
  int largest = 0;
  for (int k = 1; k < 3; ++k)
    if (std::abs(a[k]) > std::abs(a[largest])) largest = k;
  return a[largest] < 0.0 ? -a : a;
}

}  // namespace

std::vector<FieldConstraint> parse_field(std::string_view text, const std::string& name,
                                         const TriMesh& base) {
  nlohmann::json document;
  try {
    document = nlohmann::json::parse(text.begin(), text.end());
  } catch (const nlohmann::json::exception& e) {
    throw InputError(name + ": not valid JSON (" + std::string(e.what()) + ")", ErrorKind::invalid_option);
  }
  if (!document.is_object() || !document.contains("directions") || !document["directions"].is_array())
    throw InputError(name + ": expected an object with a 'directions' array", ErrorKind::invalid_option);
  std::vector<FieldConstraint> constraints;
  size_t index = 0;
  for (const nlohmann::json& entry : document["directions"]) {
    const std::string where = name + ": directions[" + std::to_string(index++) + "]";
    if (!entry.is_object() || !entry.contains("direction"))
      throw InputError(where + ": needs a 'direction'", ErrorKind::invalid_option);
    FieldConstraint c;
    c.direction = parse_vector(entry["direction"], "direction", where);
    if (glm::length(c.direction) == 0.0)
      throw InputError(where + ": the direction is zero", ErrorKind::invalid_option);
    if (entry.contains("vertex")) {
      if (!entry["vertex"].is_number_integer())
        throw InputError(where + ": 'vertex' must be an integer", ErrorKind::invalid_option);
      const int64_t v = entry["vertex"].get<int64_t>();
      if (v < 0 || v >= static_cast<int64_t>(base.num_vertices()))
        throw InputError(where + ": vertex " + std::to_string(v) + " does not exist (the base has " +
                             std::to_string(base.num_vertices()) + " vertices after welding)",
                         ErrorKind::invalid_option);
      c.vertex = static_cast<int32_t>(v);
    } else if (entry.contains("point")) {
      c.vertex = nearest_vertex(base, parse_vector(entry["point"], "point", where));
      if (c.vertex < 0) throw InputError(where + ": the base has no vertices", ErrorKind::invalid_option);
    } else {
      throw InputError(where + ": needs a 'vertex' or a 'point'", ErrorKind::invalid_option);
    }
    constraints.push_back(c);
  }
  return constraints;
}

std::vector<FieldConstraint> constraints_at_points(const std::vector<Vec3>& points, const std::vector<Vec3>& directions,
                                                  const TriMesh& base, const std::string& name) {
  if (points.size() != directions.size())
    throw InputError(name + ": " + std::to_string(points.size()) + " points but " + std::to_string(directions.size()) +
                         " directions",
                     ErrorKind::invalid_option);
  std::vector<FieldConstraint> constraints;
  for (size_t k = 0; k < points.size(); ++k) {
    const std::string where = name + ": direction " + std::to_string(k);
    const Vec3& p = points[k];
    const Vec3& d = directions[k];
    if (!std::isfinite(p.x + p.y + p.z) || !std::isfinite(d.x + d.y + d.z))
      throw InputError(where + ": not finite", ErrorKind::invalid_option);
    if (glm::length(d) == 0.0) throw InputError(where + ": the direction is zero", ErrorKind::invalid_option);
    FieldConstraint c;
    c.direction = d;
    c.vertex = nearest_vertex(base, p);
    if (c.vertex < 0) throw InputError(where + ": the base has no vertices", ErrorKind::invalid_option);
    constraints.push_back(c);
  }
  return constraints;
}

std::vector<FieldConstraint> read_field_file(const std::filesystem::path& file, const TriMesh& base) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw IoError(ErrorKind::file_unreadable, file.string() + ": cannot read the field file");
  std::stringstream text;
  text << in.rdbuf();
  return parse_field(text.str(), file.string(), base);
}

Vec3 GuidanceField::at(const BaseSurface& base, const SurfacePoint& p) const {
  const Tri& t = base.mesh.triangles[p.face];
  const Vec3 d = (1.0 - p.bary.x - p.bary.y) * directions[t[0]] + p.bary.x * directions[t[1]] +
                 p.bary.y * directions[t[2]];
  const Vec3 n = base.face_normals[p.face];
  if (glm::length(n) == 0.0) return glm::length(d) > 0.0 ? glm::normalize(d) : Vec3(1.0, 0.0, 0.0);
  const Vec3 tangent = tangent_part(d, n);
  const double len = glm::length(tangent);
  return len > 1e-9 ? tangent / len : any_tangent(n);
}

GuidanceField interpolate_field(const BaseSurface& base, const std::vector<FieldConstraint>& constraints,
                                double regularization) {
  const TriMesh& mesh = base.mesh;
  const size_t n = mesh.num_vertices();
  GuidanceField field;
  field.axis = principal_axis(base);
  std::vector<Vec3> fallback(n);
  for (size_t v = 0; v < n; ++v) fallback[v] = tangent_part(field.axis, base.vertex_normals[v]);

  std::vector<Vec3> raw = fallback;
  if (!constraints.empty()) {
    std::vector<int32_t> fixed(n, -1);
    for (size_t k = 0; k < constraints.size(); ++k) fixed[constraints[k].vertex] = static_cast<int32_t>(k);
    // Held values are unit tangents: a constraint gives a direction, so its length must not weigh
    // it against the others (and a huge one must not overflow the solve).
    std::vector<Vec3> held(constraints.size());
    for (size_t k = 0; k < constraints.size(); ++k) {
      const Vec3& given = constraints[k].direction;
      const double largest = std::max({std::abs(given.x), std::abs(given.y), std::abs(given.z)});
      const Vec3 d = largest > 0.0 ? given / largest : Vec3(0.0);
      const Vec3 n = base.vertex_normals[constraints[k].vertex];
      const Vec3 t = tangent_part(d, n);
      held[k] = glm::length(t) > 1e-12 ? glm::normalize(t) : any_tangent(n);
    }
    // Two unknowns per free vertex: its direction in a basis (t1, t2) of its tangent plane. A
    // neighbour's direction enters projected to this plane, t_i^T t_j (symmetric, so the system
    // is too, and positive definite with a vertex held).
    std::vector<std::array<Vec3, 2>> basis(n);
    for (size_t v = 0; v < n; ++v) {
      const Vec3 t1 = any_tangent(base.vertex_normals[v]);
      basis[v] = {t1, glm::cross(base.vertex_normals[v], t1)};
    }
    std::vector<int32_t> column(n, -1);
    int32_t unknowns = 0;
    for (size_t v = 0; v < n; ++v)
      if (fixed[v] < 0) column[v] = 2 * unknowns++;
    // (L_tangent + eps I) x = eps x_default, with held vertices moved to the right-hand side.
    std::vector<Eigen::Triplet<double>> triplets;
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(2 * unknowns);
    for (size_t v = 0; v < n; ++v) {
      if (column[v] < 0) continue;
      std::vector<int32_t> neighbours;
      for (const auto& [w, length] : base.edges[v]) neighbours.push_back(w);
      std::sort(neighbours.begin(), neighbours.end());
      neighbours.erase(std::unique(neighbours.begin(), neighbours.end()), neighbours.end());
      for (int a = 0; a < 2; ++a) {
        triplets.emplace_back(column[v] + a, column[v] + a, static_cast<double>(neighbours.size()) + regularization);
        rhs(column[v] + a) += regularization * glm::dot(basis[v][a], fallback[v]);
        for (int32_t w : neighbours) {
          if (column[w] >= 0) {
            for (int b = 0; b < 2; ++b)
              triplets.emplace_back(column[v] + a, column[w] + b, -glm::dot(basis[v][a], basis[w][b]));
          } else {
            rhs(column[v] + a) += glm::dot(basis[v][a], held[fixed[w]]);
          }
        }
      }
    }
    if (unknowns > 0) {
      Eigen::SparseMatrix<double> A(2 * unknowns, 2 * unknowns);
      A.setFromTriplets(triplets.begin(), triplets.end());
      const Eigen::MatrixXd x = solve_positive_definite(A, rhs, "guidance field");
      for (size_t v = 0; v < n; ++v)
        if (column[v] >= 0) raw[v] = x(column[v], 0) * basis[v][0] + x(column[v] + 1, 0) * basis[v][1];
    }
    for (size_t v = 0; v < n; ++v)
      if (fixed[v] >= 0) {
        raw[v] = held[fixed[v]];
        field.held_vertices.push_back(static_cast<int32_t>(v));
      }
  }
  field.directions.resize(n);
  for (size_t v = 0; v < n; ++v) {
    const Vec3 t = tangent_part(raw[v], base.vertex_normals[v]);
    const double len = glm::length(t);
    field.directions[v] = len > 1e-12 ? t / len : any_tangent(base.vertex_normals[v]);
  }
  return field;
}

void write_field_obj(const BaseSurface& base, const GuidanceField& field, double length,
                     const std::filesystem::path& file) {
  std::ostringstream out;
  out << "# meshquilt guidance field: one segment per face, from its centroid along the field\n";
  out.precision(9);
  for (size_t f = 0; f < base.mesh.num_faces(); ++f) {
    const SurfacePoint centre{static_cast<int32_t>(f), glm::dvec2(1.0 / 3.0)};
    const Vec3 p = base.position(centre);
    const Vec3 q = p + length * field.at(base, centre);
    out << "v " << p.x << ' ' << p.y << ' ' << p.z << "\nv " << q.x << ' ' << q.y << ' ' << q.z << '\n';
  }
  for (size_t f = 0; f < base.mesh.num_faces(); ++f) out << "l " << 2 * f + 1 << ' ' << 2 * f + 2 << '\n';
  write_file_atomic(file, out.str());
}

}  // namespace meshquilt
