// The tree's factor of A = M + h D against Eigen's dense Cholesky, on
// random trees with branches, fixed and floating (physics §11.3).
#include "rigid_body_sim/core/articulations/tree_factor.h"

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <random>
#include <vector>

#include "articulation_models.h"
#include "rigid_body_sim/core/articulations/articulation_dynamics.h"

namespace rigid_body_sim::core {
namespace {

// A floating base's six coordinates are one path; a joint follows its
// parent link's joint, or the base's last coordinate.
TEST(TreeFactor, CoordinatesFollowTheTree) {
  ArticulationModel model;
  model.fixed_base = false;
  model.links.resize(5);
  model.links[1].parent = 0;
  model.links[2].parent = 1;
  model.links[3].parent = 0;
  model.links[4].parent = 3;
  std::vector<int> parent;
  coordinateParents(model, parent);
  EXPECT_EQ(parent, (std::vector<int>{-1, 0, 1, 2, 3, 4, 5, 6, 5, 8}));
  model.fixed_base = true;
  coordinateParents(model, parent);
  EXPECT_EQ(parent, (std::vector<int>{-1, 0, -1, 2}));
}

// A⁻¹ b for one column and for three, at M + h D of random states of
// random trees, as Eigen's dense Cholesky gives it.
TEST(TreeFactor, SolvesAsTheDenseCholesky) {
  std::mt19937 rng(31);
  std::uniform_real_distribution<double> uniform(-2.0, 2.0);
  for (int trial = 0; trial < 60; ++trial) {
    const ArticulationModel model = test::randomTree(rng, 1 + trial % 12, trial % 2 == 0, trial % 5 == 0);
    ArticulationState state = restState(model, {test::randomRotation(rng), test::randomVec(rng, 1.0)});
    for (int j = 0; j < model.jointCount(); ++j) state.q(j) = uniform(rng);
    Eigen::MatrixXd A = massMatrix(model, kinematics(model, state));
    for (int i = 1; i <= model.jointCount(); ++i) A(model.dofOf(i), model.dofOf(i)) += 1e-3 * (1.0 + trial % 3);
    TreeFactor factor;
    ASSERT_TRUE(factor.compute(A, model));
    const Eigen::LLT<Eigen::MatrixXd> llt(A);
    const Eigen::VectorXd b = Eigen::VectorXd::NullaryExpr(A.rows(), [&] { return uniform(rng); });
    const Eigen::VectorXd want = llt.solve(b);
    EXPECT_LT((factor.solve(b) - want).cwiseAbs().maxCoeff(), 1e-11 * (1.0 + want.cwiseAbs().maxCoeff()))
        << "trial " << trial;
    const Eigen::Matrix<double, Eigen::Dynamic, 3> B =
        Eigen::Matrix<double, Eigen::Dynamic, 3>::NullaryExpr(A.rows(), 3, [&] { return uniform(rng); });
    const Eigen::Matrix<double, Eigen::Dynamic, 3> x = factor.solve(B);
    EXPECT_LT((A * x - B).cwiseAbs().maxCoeff(), 1e-10 * (1.0 + A.cwiseAbs().maxCoeff() * x.cwiseAbs().maxCoeff()))
        << "trial " << trial;
  }
}

// A matrix that is not positive definite is refused by its pivots.
TEST(TreeFactor, SaysWhenAPivotIsNotPositive) {
  ArticulationModel model;
  model.fixed_base = true;
  model.links.resize(3);
  model.links[1].parent = 0;
  model.links[2].parent = 1;
  Eigen::Matrix2d A;
  A << 1.0, 2.0, 2.0, 1.0;  // eigenvalues 3 and −1
  TreeFactor factor;
  EXPECT_FALSE(factor.compute(A, model));
  A << 2.0, 1.0, 1.0, 2.0;
  EXPECT_TRUE(factor.compute(A, model));
}

}  // namespace
}  // namespace rigid_body_sim::core
