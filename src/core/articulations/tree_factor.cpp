// A = Lᵀ D L along an articulation's tree (tree_factor.h): docs/physics.md §11.3.
#include "rigid_body_sim/core/articulations/tree_factor.h"

#include <cmath>

namespace rigid_body_sim::core {

void coordinateParents(const ArticulationModel& model, std::vector<int>& parent) {
  parent.assign(static_cast<std::size_t>(model.dofCount()), -1);
  const int base = model.fixed_base ? 0 : 6;
  for (int k = 1; k < base; ++k) parent[k] = k - 1;
  for (int i = 1; i <= model.jointCount(); ++i) {
    const int p = model.links[i].parent;
    parent[model.dofOf(i)] = p > 0 ? model.dofOf(p) : base - 1;
  }
}

bool TreeFactor::compute(const Eigen::MatrixXd& A, const ArticulationModel& model) {
  coordinateParents(model, parent_);
  const int n = size();
  // Paths to the root as runs of consecutive coordinates (a serial chain is
  // one run), so that the sums over ancestors are contiguous rows.
  run_.resize(n);
  for (int k = 0; k < n; ++k) run_[k] = k > 0 && parent_[k] == k - 1 ? run_[k - 1] : k;
  LD_ = A;
  bool positive = true;
  // From the leaves in: eliminating coordinate k changes only the entries
  // between its ancestors, which are on one path (no fill-in).
  for (int k = n - 1; k >= 0; --k) {
    const double d = LD_(k, k);
    if (!(d > 0.0 && std::isfinite(d))) positive = false;
    for (int i = parent_[k]; i >= 0; i = parent_[i]) {
      const double l = LD_(k, i) / d;
      double* row_i = LD_.row(i).data();
      const double* row_k = LD_.row(k).data();
      forRuns(i, [&](int first, int count) {
        for (int j = first; j < first + count; ++j) row_i[j] -= l * row_k[j];
      });
    }
    double* row_k = LD_.row(k).data();
    forRuns(parent_[k], [&](int first, int count) {
      for (int j = first; j < first + count; ++j) row_k[j] /= d;
    });
  }
  return positive;
}

void TreeFactor::solveInPlace(Eigen::Ref<Eigen::MatrixXd> x) const {
  const int n = size();
  for (Eigen::Index c = 0; c < x.cols(); ++c) {
    double* v = x.col(c).data();
    for (int i = n - 1; i >= 0; --i) {  // Lᵀ: descendants before their ancestors
      const double vi = v[i];
      const double* row = LD_.row(i).data();
      forRuns(parent_[i], [&](int first, int count) {
        for (int j = first; j < first + count; ++j) v[j] -= vi * row[j];
      });
    }
    for (int i = 0; i < n; ++i) v[i] /= LD_(i, i);
    for (int i = 0; i < n; ++i) {  // L: ancestors before their descendants
      const double* row = LD_.row(i).data();
      double sum = 0.0;
      forRuns(parent_[i], [&](int first, int count) {
        for (int j = first; j < first + count; ++j) sum += row[j] * v[j];
      });
      v[i] -= sum;
    }
  }
}

}  // namespace rigid_body_sim::core
