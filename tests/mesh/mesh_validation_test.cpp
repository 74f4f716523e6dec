// validate_mesh: each problem found, with the source named first in the message.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "core/error.h"
#include "mesh/validation.h"

namespace meshquilt {
namespace {

TriMesh triangle() {
  TriMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  m.triangles = {{0, 1, 2}};
  return m;
}

void expect_invalid(const TriMesh& m, const std::string& fragment) {
  try {
    validate_mesh(m, "base.off");
    ADD_FAILURE() << "no error for: " << fragment;
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_EQ(e.kind(), ErrorKind::invalid_mesh);
    EXPECT_EQ(message.rfind("base.off: ", 0), 0u) << message;
    EXPECT_NE(message.find(fragment), std::string::npos) << message;
  }
}

TEST(MeshValidation, AcceptsAValidMesh) {
  TriMesh m = triangle();
  EXPECT_NO_THROW(validate_mesh(m, "base.off"));
  m.elements = {0};
  EXPECT_NO_THROW(validate_mesh(m, "base.off"));
}

TEST(MeshValidation, FindsEachProblem) {
  expect_invalid(TriMesh{}, "no faces");
  TriMesh m = triangle();
  m.triangles[0][2] = 3;
  expect_invalid(m, "index 3");
  m = triangle();
  m.triangles[0][0] = -1;
  expect_invalid(m, "index -1");
  m = triangle();
  m.positions[1].y = std::numeric_limits<double>::quiet_NaN();
  expect_invalid(m, "vertex 1");
  m = triangle();
  m.positions[2].z = -std::numeric_limits<double>::infinity();
  expect_invalid(m, "vertex 2");
  m = triangle();
  m.elements = {0, 1};
  expect_invalid(m, "2 element ids for 1 faces");
  m = triangle();
  m.elements = {-3};
  expect_invalid(m, "negative element id");
}

}  // namespace
}  // namespace meshquilt
