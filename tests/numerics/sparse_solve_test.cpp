// solve_positive_definite and PositiveDefiniteFactor against dense solves written out here, and
// the refusals.
#include <gtest/gtest.h>

#include <random>

#include "core/error.h"
#include "numerics/sparse_solve.h"

namespace meshquilt {
namespace {

// The path graph's Laplacian plus `shift` on the diagonal: tridiagonal, positive definite for
// shift > 0, singular (constants in its null space) for shift = 0.
Eigen::SparseMatrix<double> shifted_path_laplacian(int n, double shift) {
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < n; ++i) {
    const double degree = (i > 0) + (i + 1 < n);
    t.emplace_back(i, i, degree + shift);
    if (i > 0) t.emplace_back(i, i - 1, -1.0);
    if (i + 1 < n) t.emplace_back(i, i + 1, -1.0);
  }
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

// Gaussian elimination on the tridiagonal system (the Thomas algorithm), column by column.
Eigen::MatrixXd thomas(const Eigen::SparseMatrix<double>& A, const Eigen::MatrixXd& B) {
  const int n = static_cast<int>(A.rows());
  Eigen::MatrixXd X(B.rows(), B.cols());
  for (int c = 0; c < B.cols(); ++c) {
    std::vector<double> diag(n), rhs(n);
    for (int i = 0; i < n; ++i) diag[i] = A.coeff(i, i), rhs[i] = B(i, c);
    for (int i = 1; i < n; ++i) {
      const double m = A.coeff(i, i - 1) / diag[i - 1];
      diag[i] -= m * A.coeff(i - 1, i);
      rhs[i] -= m * rhs[i - 1];
    }
    X(n - 1, c) = rhs[n - 1] / diag[n - 1];
    for (int i = n - 2; i >= 0; --i) X(i, c) = (rhs[i] - A.coeff(i, i + 1) * X(i + 1, c)) / diag[i];
  }
  return X;
}

TEST(SparseSolve, AgreesWithEliminationOnAPositiveDefiniteSystem) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  for (const SolveOrdering ordering : {SolveOrdering::amd, SolveOrdering::amd_cached}) {
    for (int n : {1, 2, 17, 200}) {
      const Eigen::SparseMatrix<double> A = shifted_path_laplacian(n, 0.05);
      Eigen::MatrixXd B(n, 3);
      for (int i = 0; i < n; ++i)
        for (int c = 0; c < 3; ++c) B(i, c) = value(rng);
      // Twice, so the cached ordering is also used from its cache.
      for (int round = 0; round < 2; ++round) {
        const Eigen::MatrixXd X = solve_positive_definite(A, B, "path", SolveOptions{ordering, true});
        EXPECT_LT((X - thomas(A, B)).cwiseAbs().maxCoeff(), 1e-9) << n;
      }
    }
  }
}

TEST(SparseSolve, RefusesASingularSystemOnlyWhenAsked) {
  // Singular up to rounding: the factorization succeeds with a vanishing last pivot.
  const Eigen::SparseMatrix<double> A = shifted_path_laplacian(10, 1e-15);
  const Eigen::MatrixXd B = Eigen::MatrixXd::Ones(10, 1);
  try {
    solve_positive_definite(A, B, "the test system", SolveOptions{SolveOrdering::amd, true});
    FAIL() << "a singular system was solved";
  } catch (const SolverError& e) {
    EXPECT_EQ(std::string(e.what()), "the test system is singular");
  }
  EXPECT_TRUE(solve_positive_definite(A, B, "the test system").allFinite());
  // Exactly singular: the factorization itself fails.
  EXPECT_THROW(solve_positive_definite(shifted_path_laplacian(10, 0.0), B, "exact"), SolverError);
}

TEST(SparseSolve, RefusesAnIndefiniteSystemWhenAsked) {
  // A negative pivot: LDL^T factors it without complaint, the pivot check refuses it.
  Eigen::SparseMatrix<double> A = shifted_path_laplacian(4, 0.5);
  A.coeffRef(0, 0) = -3.0;
  EXPECT_THROW(solve_positive_definite(A, Eigen::MatrixXd::Ones(4, 1), "indefinite", SolveOptions{SolveOrdering::amd, true}),
               SolverError);
}

TEST(PositiveDefiniteFactor, OneFactorAnswersEachRightHandSideAsTheDenseSolve) {
  const Eigen::SparseMatrix<double> A = shifted_path_laplacian(40, 0.3);
  const PositiveDefiniteFactor factor(A, "path");
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 3; ++trial) {
    Eigen::MatrixXd B(40, 1);
    for (int i = 0; i < 40; ++i) B(i, 0) = u(rng);
    EXPECT_LT((factor.solve(B) - thomas(A, B)).cwiseAbs().maxCoeff(), 1e-10);
  }
}

}  // namespace
}  // namespace meshquilt
