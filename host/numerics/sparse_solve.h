#pragma once
//! Sparse symmetric positive definite solves (Eigen's simplicial LDL^T), with the factorization,
//! the pivots and the solution checked: the one solver behind the Laplacian deformation, the
//! conformal patch maps and the guidance field.

#include <Eigen/Sparse>
#include <string>

namespace meshquilt {

//! How the unknowns are ordered before factorizing.
enum class SolveOrdering {
  amd,         //!< Eigen's approximate minimum degree ordering
  amd_cached,  //!< the same ordering, remembered per sparsity pattern (a few per thread): for
               //!< many solves of one pattern, such as the copies of one swatch element
};

//! How a solve is made and checked.
struct SolveOptions {
  SolveOrdering ordering = SolveOrdering::amd;
  //! Refuse a vanishing pivot (below 1e-12 of the largest): a semi-definite system factors
  //! without complaint. Off where a rank-deficient system's least-squares answer is wanted.
  bool refuse_singular = false;
};

//! One factorization of A for many right-hand sides, in turn (as a greedy search asks them):
//! made and checked as solve_positive_definite makes and checks it with the default options.
class PositiveDefiniteFactor {
 public:
  //! \throw SolverError "WHAT: factorization failed".
  PositiveDefiniteFactor(const Eigen::SparseMatrix<double>& A, std::string what);
  //! A^-1 B. \throw SolverError "WHAT: solve failed" (a failed or non-finite solve).
  Eigen::MatrixXd solve(const Eigen::MatrixXd& B) const;

 private:
  std::string what_;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> factor_;
};

//! X = A^-1 B, where A (n x n, lower triangle read) is symmetric positive (semi-)definite and B
//! is n x k. `what` names the system in errors ("element deformation: the 120-vertex system").
//! \throw SolverError "WHAT: factorization failed", "WHAT is singular" (with refuse_singular) or
//!        "WHAT: solve failed" (a failed or non-finite solve).
Eigen::MatrixXd solve_positive_definite(const Eigen::SparseMatrix<double>& A, const Eigen::MatrixXd& B,
                                        const std::string& what, const SolveOptions& options = {});

}  // namespace meshquilt
