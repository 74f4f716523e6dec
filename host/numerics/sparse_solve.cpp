#include "numerics/sparse_solve.h"

#include <algorithm>
#include <utility>
#include <vector>

#include "core/error.h"

namespace meshquilt {
namespace {

// Eigen's AMD ordering, remembered per sparsity pattern: the ordering is a function of the
// pattern alone and a large share of one small solve, so factorizations are the very ones AMD
// gives.
struct CachedAmdOrdering {
  using PermutationType = Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int>;

  template <typename MatrixType>
  void operator()(const MatrixType& mat, PermutationType& perm) {
    if (!mat.isCompressed()) {
      Eigen::AMDOrdering<int>()(mat, perm);
      return;
    }
    struct Entry {
      std::vector<int> outer, inner;
      PermutationType perm;
    };
    constexpr size_t kEntries = 8;
    thread_local std::vector<Entry> cache;
    thread_local size_t next = 0;
    const int* outer = mat.outerIndexPtr();
    const int* inner = mat.innerIndexPtr();
    const auto n = static_cast<size_t>(mat.outerSize());
    const auto nnz = static_cast<size_t>(outer[n]);
    for (const Entry& e : cache)
      if (e.outer.size() == n + 1 && e.inner.size() == nnz && std::equal(e.outer.begin(), e.outer.end(), outer) &&
          std::equal(e.inner.begin(), e.inner.end(), inner)) {
        perm = e.perm;
        return;
      }
    Eigen::AMDOrdering<int>()(mat, perm);
    Entry entry{std::vector<int>(outer, outer + n + 1), std::vector<int>(inner, inner + nnz), perm};
    if (cache.size() < kEntries) {
      cache.push_back(std::move(entry));
    } else {
      cache[next] = std::move(entry);
      next = (next + 1) % kEntries;
    }
  }
};

// Relative size below which a pivot counts as vanishing.
constexpr double kSingularPivot = 1e-12;

template <typename Ordering>
Eigen::MatrixXd solve_with(const Eigen::SparseMatrix<double>& A, const Eigen::MatrixXd& B, const std::string& what,
                           bool refuse_singular) {
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Ordering> solver;
  solver.compute(A);
  if (solver.info() != Eigen::Success) throw SolverError(what + ": factorization failed");
  const Eigen::VectorXd& D = solver.vectorD();
  if (refuse_singular && D.size() > 0 && !(D.minCoeff() > kSingularPivot * D.cwiseAbs().maxCoeff()))
    throw SolverError(what + " is singular");
  Eigen::MatrixXd X = solver.solve(B);
  if (solver.info() != Eigen::Success || !X.allFinite()) throw SolverError(what + ": solve failed");
  return X;
}

}  // namespace

PositiveDefiniteFactor::PositiveDefiniteFactor(const Eigen::SparseMatrix<double>& A, std::string what)
    : what_(std::move(what)) {
  factor_.compute(A);
  if (factor_.info() != Eigen::Success) throw SolverError(what_ + ": factorization failed");
}

Eigen::MatrixXd PositiveDefiniteFactor::solve(const Eigen::MatrixXd& B) const {
  Eigen::MatrixXd X = factor_.solve(B);
  if (factor_.info() != Eigen::Success || !X.allFinite()) throw SolverError(what_ + ": solve failed");
  return X;
}

Eigen::MatrixXd solve_positive_definite(const Eigen::SparseMatrix<double>& A, const Eigen::MatrixXd& B,
                                        const std::string& what, const SolveOptions& options) {
  if (options.ordering == SolveOrdering::amd_cached)
    return solve_with<CachedAmdOrdering>(A, B, what, options.refuse_singular);
  return solve_with<Eigen::AMDOrdering<int>>(A, B, what, options.refuse_singular);
}

}  // namespace meshquilt
