// The factor of an articulation's A = M + h D that follows its tree
// (docs/physics.md §11.3): A = Lᵀ D L, L unit lower-triangular with entries
// only towards each coordinate's ancestors, as MuJoCo factors M. The tree
// makes no fill-in, so the factor costs Σ depth² and a solve Σ depth, not
// n³/3 and n²; on a serial chain it is the dense factor. Eigen only.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "rigid_body_sim/core/articulations/articulation.h"

namespace rigid_body_sim::core {

/// Each coordinate's parent on its path to the root (−1 at the root): a
/// floating base's six in a row, each joint after its parent link's joint
/// or, on the base, after the base's last coordinate. Into `parent`.
void coordinateParents(const ArticulationModel& model, std::vector<int>& parent);

class TreeFactor {
 public:
  /// Factors A, symmetric positive definite and zero between coordinates
  /// of which neither is the other's ancestor in the model's tree (as M + h D
  /// is). False where a pivot is not positive and finite (A not positive
  /// definite): the solves are then not A⁻¹.
  bool compute(const Eigen::MatrixXd& A, const ArticulationModel& model);

  /// x ← A⁻¹ x, column by column.
  void solveInPlace(Eigen::Ref<Eigen::MatrixXd> x) const;
  template <class Matrix>
  Matrix solve(const Matrix& b) const {
    Matrix x = b;
    solveInPlace(x);
    return x;
  }
  int size() const { return static_cast<int>(parent_.size()); }

 private:
  using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  /// f(first, count) for each run of consecutive coordinates on the path
  /// from k (itself included) to the root, k's own first.
  template <class F>
  void forRuns(int k, F&& f) const {
    while (k >= 0) {
      const int first = run_[k];
      f(first, k - first + 1);
      k = parent_[first];
    }
  }

  RowMajor LD_;  ///< D on the diagonal, L below it (row k: coordinate k's ancestors)
  std::vector<int> parent_;
  std::vector<int> run_;  ///< where the run of consecutive coordinates that ends at k begins
};

}  // namespace rigid_body_sim::core
