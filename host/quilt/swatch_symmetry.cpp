#include "quilt/swatch_symmetry.h"

#include <Eigen/Dense>

#include "core/constants.h"

namespace meshquilt {
namespace {

ElementShape shape_of(const TriMesh& element, int32_t source) {
  ElementShape shape;
  shape.source = source;
  if (element.positions.empty()) return shape;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const Vec3& p : element.positions) centroid += Eigen::Vector3d(p.x, p.y, p.z);
  centroid /= static_cast<double>(element.positions.size());
  shape.centre = {centroid.x(), centroid.y()};
  Eigen::Matrix3d moments = Eigen::Matrix3d::Zero();
  for (const Vec3& p : element.positions) {
    const Eigen::Vector3d d = Eigen::Vector3d(p.x, p.y, p.z) - centroid;
    moments += d * d.transpose();
  }
  moments /= static_cast<double>(element.positions.size());
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) shape.moments[c][r] = moments(r, c);
  return shape;
}

bool shapes_symmetric_under(const std::vector<ElementShape>& shapes, double angle) {
  for (const ElementShape& shape : shapes) {
    bool found = false;
    for (const ElementShape& other : shapes)
      if (shape.matches_turned(other, angle)) {
        found = true;
        break;
      }
    if (!found) return false;
  }
  return true;
}

}  // namespace

bool ElementShape::matches_turned(const ElementShape& other, double angle) const {
  if (other.source != source) return false;
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  Eigen::Matrix3d mine, theirs;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) {
      mine(r, c) = moments[c][r];
      theirs(r, c) = other.moments[c][r];
    }
  return (theirs - turn * mine * turn.transpose()).norm() <= 0.05 * mine.norm();
}

std::vector<ElementShape> element_shapes(const QuiltSwatch& swatch) {
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
  return shapes;
}

bool symmetric_under(const QuiltSwatch& swatch, double angle) {
  return shapes_symmetric_under(element_shapes(swatch), angle);
}

int rotational_symmetry(const QuiltSwatch& swatch) {
  return symmetric_under(swatch, kPi) ? 2 : 1;
}

}  // namespace meshquilt
