#include "quilt/swatch_symmetry.h"

#include <Eigen/Dense>

namespace meshquilt {
namespace {

struct ElementShape {
  int32_t source = -1;
  Eigen::Matrix3d moments = Eigen::Matrix3d::Zero();
};

ElementShape shape_of(const TriMesh& element, int32_t source) {
  ElementShape shape;
  shape.source = source;
  if (element.positions.empty()) return shape;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const Vec3& p : element.positions) centroid += Eigen::Vector3d(p.x, p.y, p.z);
  centroid /= static_cast<double>(element.positions.size());
  for (const Vec3& p : element.positions) {
    const Eigen::Vector3d d = Eigen::Vector3d(p.x, p.y, p.z) - centroid;
    shape.moments += d * d.transpose();
  }
  shape.moments /= static_cast<double>(element.positions.size());
  return shape;
}

bool shapes_symmetric_under(const std::vector<ElementShape>& shapes, double angle) {
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  for (const ElementShape& shape : shapes) {
    const Eigen::Matrix3d turned = turn * shape.moments * turn.transpose();
    const double tolerance = 0.05 * shape.moments.norm();
    bool found = false;
    for (const ElementShape& other : shapes)
      if (other.source == shape.source && (other.moments - turned).norm() <= tolerance) {
        found = true;
        break;
      }
    if (!found) return false;
  }
  return true;
}

}  // namespace

bool symmetric_under(const QuiltSwatch& swatch, double angle) {
  std::vector<ElementShape> shapes;
  shapes.reserve(swatch.elements.size());
  // Each element's source: that of its first face in the swatch (elements number the faces).
  std::vector<int32_t> source(swatch.elements.size(), -1);
  const TriMesh& mesh = swatch.mesh;
  for (size_t f = mesh.num_faces(); f-- > 0;)
    if (f < mesh.elements.size() && f < mesh.sources.size() && mesh.elements[f] >= 0 &&
        static_cast<size_t>(mesh.elements[f]) < source.size())
      source[mesh.elements[f]] = mesh.sources[f];
  for (size_t k = 0; k < swatch.elements.size(); ++k) shapes.push_back(shape_of(swatch.elements[k], source[k]));
  return shapes_symmetric_under(shapes, angle);
}

int rotational_symmetry(const QuiltSwatch& swatch) {
  constexpr double kPi = 3.14159265358979323846;
  return symmetric_under(swatch, kPi) ? 2 : 1;
}

}  // namespace meshquilt
