// An articulation's dynamics against closed forms (Drake's acrobot, the
// rod pendulum's elliptic period, damping's exponential) and against
// themselves (M from inverse dynamics, forward against inverse, energy).
#include "rigid_body_sim/core/articulations/articulation.h"

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <tuple>

#include "articulation_models.h"
#include "lone_robot.h"
#include "rigid_body_sim/core/articulations/articulation_dynamics.h"
#include "rigid_body_sim/core/articulations/articulation_step.h"

namespace rigid_body_sim::core {
namespace {

using test::LoneRobot;
using test::planarChain;
using test::randomTree;
using test::stepAlone;

const Vec3 kGravity(0.0, 0.0, -9.81);

ArticulationState randomState(std::mt19937& rng, const ArticulationModel& model) {
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  ArticulationState state = restState(model, {test::randomRotation(rng), test::randomVec(rng, 1.0)});
  for (int j = 0; j < model.jointCount(); ++j) {
    state.q(j) = u(rng);
    state.v(j) = u(rng);
  }
  if (!model.fixed_base) state.V_B << test::randomVec(rng, 2.0), test::randomVec(rng, 2.0);
  return state;
}

double relativeError(const Eigen::MatrixXd& got, const Eigen::MatrixXd& want) {
  return (got - want).cwiseAbs().maxCoeff() / std::max(1.0, want.cwiseAbs().maxCoeff());
}

// A base placed from its link's pose and twist in the world keeps its twist
// in its own axes: a base turned a quarter about z, spinning about world x at
// 1 rad/s and moving along world y at 2 m/s, spins about its own -y and moves
// along its own -x; baseLinkState gives the world's back.
TEST(ArticulationState, TheBaseIsSetFromItsLinkInTheWorld) {
  LinkState base;
  base.p_WL = Vec3(1.0, 2.0, 3.0);
  base.q_WL = Quat(Eigen::AngleAxisd(M_PI / 2, Vec3::UnitZ()));
  base.q_WL.coeffs() *= 2.0;  // not unit: normalised
  base.w_W = Vec3(1.0, 0.0, 0.0);
  base.v_WL = Vec3(0.0, 2.0, 0.0);
  ArticulationState state;
  setBaseLinkState(state, base);
  EXPECT_NEAR(state.X_WB.rotation.norm(), 1.0, 1e-15);
  EXPECT_LT((state.V_B.head<3>() - Vec3(0.0, -1.0, 0.0)).norm(), 1e-15);
  EXPECT_LT((state.V_B.tail<3>() - Vec3(2.0, 0.0, 0.0)).norm(), 1e-15);
  const LinkState back = baseLinkState(state);
  EXPECT_EQ(back.p_WL, base.p_WL);
  EXPECT_LT((back.w_W - base.w_W).norm(), 1e-15);
  EXPECT_LT((back.v_WL - base.v_WL).norm(), 1e-15);
}

// A spatial inertia carried into the parent's frame equals Xᵀ I X with X
// the parent-to-child transform of twists (the composite-body step, §11.3).
TEST(SpatialInertia, ToParentIsXTransposeIX) {
  std::mt19937 rng(19);
  for (int trial = 0; trial < 20; ++trial) {
    const SpatialInertia I = SpatialInertia::of(test::randomMass(rng));
    const Placement X = Placement::of({test::randomRotation(rng), test::randomVec(rng, 2.0)});
    const Mat6 expected = X.motionToChildMatrix().transpose() * I.matrix() * X.motionToChildMatrix();
    EXPECT_LT((I.toParent(X).matrix() - expected).cwiseAbs().maxCoeff(), 1e-13 * expected.cwiseAbs().maxCoeff());
  }
}

// Each column of M is the generalized force that gives a unit acceleration of
// one coordinate, less the bias: M eᵢ = ID(q, u, eᵢ) − ID(q, u, 0) (the check
// Pinocchio's CRBA test makes). Trees with branches, fixed and floating.
TEST(ArticulationDynamics, MassMatrixColumnsAreInverseDynamicsDifferences) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 40; ++trial) {
    const ArticulationModel model = randomTree(rng, 1 + trial % 8, trial % 2 == 0, trial % 4 < 2);
    checkArticulation(model);
    const ArticulationState state = randomState(rng, model);
    const ArticulationKinematics kin = kinematics(model, state);
    const Eigen::MatrixXd M = massMatrix(model, kin);
    const Eigen::VectorXd bias = biasForces(model, kin, kGravity);
    Eigen::MatrixXd columns(M.rows(), M.cols());
    for (int c = 0; c < M.cols(); ++c) {
      columns.col(c) = inverseDynamics(model, kin, Eigen::VectorXd::Unit(M.cols(), c), kGravity) - bias;
    }
    EXPECT_LT(relativeError(M, columns), 1e-12) << "trial " << trial;
    EXPECT_LT(relativeError(M, M.transpose()), 1e-14);
    EXPECT_EQ(M.llt().info(), Eigen::Success);
    // The kinetic energy summed link by link is ½ uᵀ M u.
    const Eigen::VectorXd u = generalizedVelocity(model, state);
    EXPECT_NEAR(kineticEnergy(model, kin), 0.5 * u.dot(M * u), 1e-12 * (1.0 + kineticEnergy(model, kin)));
  }
}

// The bias in the base's frame (biasForcesAt, the Verlet step's) is the bias
// in each link's own frame, twists, gravity and wrenches alike; the loads'
// whole wrench is the base rows of the rest forces, carried to W.
TEST(ArticulationDynamics, TheBiasInTheBaseFrameIsTheBiasInTheLinksFrames) {
  std::mt19937 rng(23);
  for (int trial = 0; trial < 40; ++trial) {
    const ArticulationModel model = randomTree(rng, 1 + trial % 8, trial % 2 == 0, trial % 4 < 2);
    ArticulationState state = randomState(rng, model);
    std::vector<Vec6> wrench_L(model.links.size());
    for (Vec6& w : wrench_L) w << test::randomVec(rng, 3.0), test::randomVec(rng, 3.0);
    ArticulationKinematics kin = kinematics(model, state);
    const Eigen::VectorXd u = generalizedVelocity(model, state);
    const Eigen::VectorXd want = biasForces(model, kin, kGravity, wrench_L);
    DynamicsScratch scratch;
    Eigen::VectorXd got;
    biasForcesAt(model, kin, u, kGravity, wrench_L, scratch, got);
    EXPECT_LT(relativeError(got, want), 1e-12) << "trial " << trial;
    // At another velocity than the state's: the kinematics' twists unused.
    const Eigen::VectorXd other = Eigen::VectorXd::NullaryExpr(
        model.dofCount(), [&] { return std::uniform_real_distribution<double>(-3.0, 3.0)(rng); });
    biasForcesAt(model, kin, other, kGravity, {}, scratch, got);
    setTwists(model, other, kin);
    EXPECT_LT(relativeError(got, biasForces(model, kin, kGravity)), 1e-12) << "trial " << trial;
    if (!model.fixed_base) {
      const Vec6 rest_B = -restForces(model, kin, kGravity, wrench_L).head<6>();
      const Vec6 want_W = kin.X_WL[0].forceToParent(rest_B);
      EXPECT_LT(relativeError(loadWrench_W(model, kin, kGravity, wrench_L), want_W), 1e-12) << "trial " << trial;
    }
  }
}

// ∂T/∂q at held velocities, against central differences of T = ½ uᵀ M(q) u.
TEST(ArticulationDynamics, KineticEnergyGradientIsTheDerivativeOfT) {
  std::mt19937 rng(13);
  for (int trial = 0; trial < 20; ++trial) {
    const ArticulationModel model = randomTree(rng, 1 + trial % 7, trial % 2 == 1, trial % 3 == 0);
    const ArticulationState state = randomState(rng, model);
    const Eigen::VectorXd gradient = kineticEnergyGradient(model, kinematics(model, state));
    for (int j = 0; j < model.jointCount(); ++j) {
      const double dq = 1e-5;
      ArticulationState plus = state, minus = state;
      plus.q(j) += dq;
      minus.q(j) -= dq;
      const double numeric =
          (kineticEnergy(model, kinematics(model, plus)) - kineticEnergy(model, kinematics(model, minus))) / (2 * dq);
      EXPECT_NEAR(gradient(model.dofOf(j + 1)), numeric, 1e-7 * (1.0 + std::abs(numeric))) << "trial " << trial;
    }
  }
}

TEST(ArticulationDynamics, ForwardAndInverseDynamicsInvertEachOther) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 40; ++trial) {
    const ArticulationModel model = randomTree(rng, 1 + trial % 9, trial % 3 == 0, trial % 2 == 0);
    const ArticulationState state = randomState(rng, model);
    const Eigen::VectorXd tau = Eigen::VectorXd::NullaryExpr(
        model.dofCount(), [&] { return std::uniform_real_distribution<double>(-5.0, 5.0)(rng); });
    const Eigen::VectorXd udot = forwardDynamics(model, state, tau, kGravity);
    const Eigen::VectorXd back = inverseDynamics(model, kinematics(model, state), udot, kGravity);
    EXPECT_LT(relativeError(back, tau), 1e-11) << "trial " << trial;
  }
}

// Drake's acrobot (multibody/benchmarks/acrobot): M(θ₂), the Coriolis
// vector and the gravity vector in closed form, θ from the downward vertical.
TEST(ArticulationDynamics, AcrobotMatchesClosedForm) {
  const double m1 = 1.0, m2 = 1.0, l1 = 1.0, lc1 = 0.5, lc2 = 0.5, Ic1 = 0.083, Ic2 = 0.33, g = 9.81;
  const ArticulationModel model = planarChain({m1, m2}, {l1, 2.0}, {lc1, lc2}, {Ic1, Ic2});
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  for (int trial = 0; trial < 50; ++trial) {
    ArticulationState state = restState(model);
    state.q << u(rng), u(rng);
    state.v << u(rng), u(rng);
    const double s1 = std::sin(state.q(0)), s2 = std::sin(state.q(1)), c2 = std::cos(state.q(1));
    const double s12 = std::sin(state.q(0) + state.q(1));
    const double I1 = Ic1 + m1 * lc1 * lc1, I2 = Ic2 + m2 * lc2 * lc2, k = m2 * l1 * lc2;
    Eigen::Matrix2d M;
    M << I1 + I2 + m2 * l1 * l1 + 2 * k * c2, I2 + k * c2, I2 + k * c2, I2;
    const Eigen::Vector2d coriolis(-2 * k * s2 * state.v(1) * state.v(0) - k * s2 * state.v(1) * state.v(1),
                                   k * s2 * state.v(0) * state.v(0));
    const Eigen::Vector2d gravity(g * m1 * lc1 * s1 + g * m2 * (l1 * s1 + lc2 * s12), g * m2 * lc2 * s12);
    const ArticulationKinematics kin = kinematics(model, state);
    EXPECT_LT(relativeError(massMatrix(model, kin), M), 1e-12);
    EXPECT_LT(relativeError(biasForces(model, kin, Vec3(0, 0, -g)), coriolis + gravity), 1e-12);
    ArticulationState still = state;
    still.v.setZero();
    EXPECT_LT(relativeError(biasForces(model, kinematics(model, still), Vec3(0, 0, -g)), gravity), 1e-12);
  }
}

/// Times at which q crosses 0 going up, linearly interpolated between steps.
std::vector<double> upwardCrossings(const ArticulationModel& model, ArticulationState state, double h, double T) {
  std::vector<double> times;
  const int steps = static_cast<int>(std::lround(T / h));
  LoneRobot alone(model, kGravity, h);
  for (int n = 0; n < steps; ++n) {
    const double before = state.q(0);
    alone.step(state);
    if (before < 0.0 && state.q(0) >= 0.0) times.push_back(h * (n + before / (before - state.q(0))));
  }
  return times;
}

// A rod on a pivot released from horizontal: T = 4 √(I/(m g l)) K(sin(θ₀/2))
// (l the pivot to the centre of mass, I about the pivot); from 0.01 rad the
// small-amplitude 2π √(I/(m g l)).
TEST(ArticulationStep, RodPendulumPeriodIsTheEllipticIntegrals) {
  const double m = 1.3, L = 0.8, Ic = m * L * L / 12.0, I = Ic + m * L * L / 4.0, l = L / 2.0, g = 9.81;
  const ArticulationModel model = planarChain({m}, {L}, {l}, {Ic});
  for (const double theta0 : {M_PI / 2.0, 0.01}) {
    ArticulationState state = restState(model);
    state.q(0) = theta0;
    const std::vector<double> up = upwardCrossings(model, state, 1e-3, 12.0);
    ASSERT_GE(up.size(), 5u);
    const double period = (up.back() - up.front()) / static_cast<double>(up.size() - 1);
    const double expected = 4.0 * std::sqrt(I / (m * g * l)) * std::comp_ellint_1(std::sin(theta0 / 2.0));
    EXPECT_NEAR(period / expected, 1.0, 1e-3) << "θ₀ = " << theta0;
    if (theta0 < 0.1) {
      EXPECT_NEAR(period / (2.0 * M_PI * std::sqrt(I / (m * g * l))), 1.0, 1e-3);
    }
  }
}

// A frictionless, undamped double pendulum, 200 s at 1 ms from a large
// swing: the energy oscillates but does not drift. It is taken where the
// step's velocity is (§11.5): at the middle of the step, the positions
// halfway.
TEST(ArticulationStep, DoublePendulumEnergyDoesNotDrift) {
  const ArticulationModel model = planarChain({1.0, 1.0}, {1.0, 1.0}, {0.5, 0.5}, {1.0 / 12.0, 1.0 / 12.0});
  ArticulationState state = restState(model);
  state.q << 1.5, -0.8;
  const auto energy = [&](const Eigen::VectorXd& q_before) {
    ArticulationState middle = state;
    middle.q = 0.5 * (q_before + state.q);
    const ArticulationKinematics kin = kinematics(model, middle);
    return kineticEnergy(model, kin) + potentialEnergy(model, kin, kGravity);
  };
  const double e0 = energy(state.q);
  const double scale = 2.0 * 9.81 * 1.0;  // m g l: the energies at play
  double first = 0.0, last = 0.0, worst = 0.0, worst_20 = 0.0;
  const int steps = 200000, window = 20000;
  LoneRobot alone(model, kGravity, 1e-3);
  const int every = 10;  // steps between two looks
  Eigen::VectorXd q_before;
  for (int n = 0; n < steps; ++n) {
    if (n % every == 0) q_before = state.q;
    alone.step(state);
    if (n % every != 0) continue;
    const double error = (energy(q_before) - e0) / scale;
    worst = std::max(worst, std::abs(error));
    if (n < window) {
      first += error * every / window;
      worst_20 = worst;
    }
    if (n >= steps - window) last += error * every / window;
  }
  std::printf(
      "double pendulum at 1 ms: worst |ΔE|/(m g l) %.3g over 20 s, %.3g over 200 s; mean of the last 20 s "
      "minus the first %.3g\n",
      worst_20, worst, last - first);
  EXPECT_LT(worst, 1e-3);
  EXPECT_LT(std::abs(last - first), 1e-4);
}

// A disc spinning on a vertical joint with damping b: each step multiplies
// its speed by I/(I + h b) exactly (implicit), close to e^(−b t / I); any b
// is stable and never reverses the spin.
// Verlet carries no joint momenta: a state it stepped, stepped on by
// symplectic Euler (the setting changed between steps), is taken afresh,
// its momenta from its velocities, as a state the caller set.
TEST(ArticulationStep, SymplecticEulerTakesAVerletStateAfresh) {
  std::mt19937 rng(29);
  const ArticulationModel model = randomTree(rng, 4, true, false);
  ModelSpec euler;
  euler.articulation_integrator = ArticulationIntegrator::kSymplecticEuler;
  LoneRobot verlet(model, kGravity, 1e-3), carried(model, kGravity, 1e-3, {}, euler),
      afresh(model, kGravity, 1e-3, {}, euler);
  ArticulationState state = restState(model);
  state.q.setConstant(0.7);
  for (int k = 0; k < 50; ++k) ASSERT_TRUE(verlet.step(state));
  ArticulationState set = state;
  set.carried = {};
  ASSERT_TRUE(carried.step(state));
  ASSERT_TRUE(afresh.step(set));
  EXPECT_EQ(state.q, set.q);
  EXPECT_EQ(state.v, set.v);
}

TEST(ArticulationStep, DampingDecaysAsTheClosedForm) {
  ArticulationModel model = planarChain({2.0}, {1.0}, {0.0}, {0.5});
  model.links[1].axis_J = Vec3::UnitZ();
  model.links[1].mass.I_C_F = Vec3(0.3, 0.3, 0.5).asDiagonal();
  for (const double b : {0.2, 1e6}) {
    model.links[1].damping = b;
    ArticulationState state = restState(model);
    state.v(0) = 3.0;
    const double h = 1e-3, I = 0.5;
    LoneRobot alone(model, kGravity, h);
    for (int n = 1; n <= 1000; ++n) {
      alone.step(state);
      ASSERT_GE(state.v(0), 0.0);
      EXPECT_NEAR(state.v(0), 3.0 * std::pow(I / (I + h * b), n), 1e-12 * 3.0);
    }
    if (b < 1.0) {
      EXPECT_NEAR(state.v(0) / (3.0 * std::exp(-b * 1.0 / I)), 1.0, 1e-3);
    }
  }
}

// A floating tree in zero gravity, 10 s at 1 ms: the momentum the step
// carries stays what it was to rounding, the velocities the step moves by
// give exactly that momentum from where they act (the middle of the
// step's move, §11.5), and the centre of mass moves on its line at P/m.
TEST(ArticulationStep, FloatingTreeKeepsItsMomentumAndItsCentreOfMassLine) {
  // A branched tree, and a long serial chain fast enough that fixed-point
  // passes diverge (§11.5).
  std::mt19937 rng(3);
  for (const auto& [links, serial, speed] : {std::tuple{5, false, 1.0}, std::tuple{20, true, 8.0}}) {
    const ArticulationModel model = randomTree(rng, links, false, serial);
    ArticulationState state = randomState(rng, model);
    state.v *= speed;
    state.V_B *= speed;
    const ArticulationKinematics start = kinematics(model, state);
    const Vec6 H0 = momentum_W(model, start);
    const Vec3 c0 = centreOfMass(model, start);
    const Vec3 velocity = H0.tail<3>() / totalMass(model);
    double worst_carried = 0.0, worst_acting = 0.0, worst_line = 0.0;
    const double h = 1e-3;
    LoneRobot alone(model, Vec3::Zero(), h, SpeedLimits{1e4, 1e4});  // never slowed
    for (int n = 1; n <= 10000; ++n) {
      const ArticulationState before = state;
      alone.step(state);
      ArticulationState acting = before;
      acting.q += 0.5 * h * state.v;
      acting.X_WB = advanceBase(before.X_WB, state.V_B, 0.5 * h);
      acting.v = state.v;
      acting.V_B = state.V_B;
      worst_carried = std::max(worst_carried, (state.carried.H_W - H0).cwiseAbs().maxCoeff());
      worst_acting = std::max(worst_acting, (momentum_W(model, kinematics(model, acting)) - H0).cwiseAbs().maxCoeff());
      worst_line =
          std::max(worst_line, (centreOfMass(model, kinematics(model, state)) - (c0 + n * h * velocity)).norm());
    }
    std::printf(
        "floating %d links, 10 s: |H| %.3g, carried momentum off by %.3g, acting %.3g, centre of mass off its "
        "line %.3g m\n",
        links, H0.norm(), worst_carried, worst_acting, worst_line);
    EXPECT_LT(worst_carried, 1e-9 * std::max(1.0, H0.norm()));
    EXPECT_LT(worst_acting, 1e-9 * std::max(1.0, H0.norm()));
    EXPECT_LT(worst_line, 1e-9);
  }
}

// A floating tree tumbling in zero gravity, 1 s from a random state: the
// joints, the base's place and its turn converge as h² to a run at 50 µs
// (measured order ≥ 1.9 between 2, 1 and 0.5 ms; KDL has no floating
// base, so the fine run is the oracle of the order, not of the dynamics).
TEST(ArticulationStep, AFloatingTreeIsSecondOrderToo) {
  std::mt19937 rng(3);
  const ArticulationModel model = randomTree(rng, 5, false, false);
  const ArticulationState start = randomState(rng, model);
  const auto run = [&](double h) {
    LoneRobot alone(model, Vec3::Zero(), h, SpeedLimits{1e4, 1e4});
    ArticulationState state = start;
    for (long n = std::lround(1.0 / h); n > 0; --n) alone.step(state);
    return state;
  };
  const ArticulationState fine = run(5e-5);
  std::array<double, 3> last{};
  for (const double h : {2e-3, 1e-3, 5e-4}) {
    const ArticulationState s = run(h);
    const std::array<double, 3> e{(s.q - fine.q).cwiseAbs().maxCoeff(),
                                  (s.X_WB.translation - fine.X_WB.translation).norm(),
                                  s.X_WB.rotation.angularDistance(fine.X_WB.rotation)};
    std::printf("floating tree at %g ms: joints %.3g rad, base %.3g m, %.3g rad off the 50 us run\n", h * 1e3, e[0],
                e[1], e[2]);
    for (int k = 0; k < 3 && last[0] > 0.0; ++k) EXPECT_GE(std::log2(last[k] / e[k]), 1.9) << h << " " << k;
    last = e;
  }
}

// An impulse on any link of a floating tree changes its momentum by exactly
// itself (world axes, about W's origin); a rod pendulum struck across at d
// below its pivot turns at ω = P d / I.
TEST(ArticulationStep, AnImpulseOnALinkChangesTheMomentumByItself) {
  std::mt19937 rng(11);
  const ArticulationModel model = randomTree(rng, 6, false, false);
  ArticulationState state = randomState(rng, model);
  const ArticulationKinematics before = kinematics(model, state);
  const Vec6 H0 = momentum_W(model, before);
  ArticulationLoads loads;
  loads.impulse_L.assign(model.links.size(), Vec6::Zero());
  loads.impulse_L[4] << 0.3, -0.2, 0.5, 1.5, 2.0, -1.0;
  ASSERT_TRUE(stepAlone(model, state, loads, Vec3::Zero(), 1e-3, SpeedLimits{1e4, 1e4}));
  const Vec6 expected = H0 + before.X_WL[4].forceToParent(loads.impulse_L[4]);
  EXPECT_LT((state.carried.H_W - expected).cwiseAbs().maxCoeff(), 1e-12 * expected.norm());

  const ArticulationModel rod = planarChain({2.0}, {1.0}, {0.5}, {2.0 / 12.0});
  ArticulationState hanging = restState(rod);
  ArticulationLoads strike;
  strike.impulse_L = {Vec6::Zero(), Vec6::Zero()};
  // 0.6 N·s along x at 0.8 m below the pivot, given at the link's origin
  // (the pivot): the force, and its moment r × P = (0, −0.48, 0).
  strike.impulse_L[1] << 0.0, -0.48, 0.0, 0.6, 0.0, 0.0;
  ASSERT_TRUE(stepAlone(rod, hanging, strike, Vec3::Zero(), 1e-3));
  const double I = 2.0 / 12.0 + 2.0 * 0.25;     // about the pivot
  EXPECT_NEAR(hanging.v(0), -0.48 / I, 1e-12);  // the bottom swings toward +x: about −y
}

// Under gravity alone the centre of mass falls exactly as a free body
// thrown does, c₀ + v₀ t + g t² / 2 at every step (Verlet's start, §11.5),
// whatever the joints do.
TEST(ArticulationStep, CentreOfMassFallsAsAFreeBody) {
  std::mt19937 rng(17);
  const ArticulationModel model = randomTree(rng, 4, false, true);
  ArticulationState state = randomState(rng, model);
  ArticulationKinematics kin = kinematics(model, state);
  const Vec3 c0 = centreOfMass(model, kin);
  const Vec3 v0 = momentum_W(model, kin).tail<3>() / totalMass(model);
  LoneRobot alone(model, kGravity, 1e-3);
  double worst = 0.0;
  for (int n = 1; n <= 2000; ++n) {
    alone.step(state);
    const double t = n * 1e-3;
    worst = std::max(worst,
                     (centreOfMass(model, kinematics(model, state)) - (c0 + v0 * t + 0.5 * kGravity * t * t)).norm());
  }
  EXPECT_LT(worst, 1e-9);
}

TEST(ArticulationStep, CommandedEffortIsClippedToTheLimit) {
  ArticulationModel model = planarChain({2.0}, {1.0}, {0.0}, {0.5});
  model.links[1].axis_J = Vec3::UnitZ();
  model.links[1].mass.I_C_F = Vec3(0.3, 0.3, 0.5).asDiagonal();
  model.links[1].limits.effort = 2.0;
  for (const double effort : {100.0, -100.0, 1.0}) {
    ArticulationState state = restState(model);
    ArticulationLoads loads;
    loads.effort = Eigen::VectorXd::Constant(1, effort);
    stepAlone(model, state, loads, kGravity, 1e-3);
    // From rest, the step's velocity is the one at its middle: a h / 2.
    EXPECT_NEAR(state.v(0), 0.5e-3 * std::clamp(effort, -2.0, 2.0) / 0.5, 1e-15);
  }
}

// A rod released from horizontal swings down onto a lower limit: it never
// goes past it, and it stays there (the limit takes no energy back).
TEST(ArticulationJoints, ALimitHoldsTheJoint) {
  ArticulationModel model = planarChain({1.0}, {1.0}, {0.5}, {1.0 / 12.0});
  model.links[1].limits.lower = 0.3;
  model.links[1].limits.upper = 2.0;
  ArticulationState state = restState(model);
  state.q(0) = M_PI / 2.0;
  double lowest = 10.0;
  LoneRobot alone(model, kGravity, 1e-3);
  for (int n = 0; n < 3000; ++n) {
    alone.step(state);
    lowest = std::min(lowest, state.q(0));
  }
  EXPECT_GE(lowest, 0.3);
  EXPECT_NEAR(state.q(0), 0.3, 1e-12);
  EXPECT_NEAR(state.v(0), 0.0, 1e-9);
  // Pushed hard into the upper limit by its effort: it stays at it.
  ArticulationLoads loads;
  loads.effort = Eigen::VectorXd::Constant(1, 500.0);
  double highest = 0.0;
  for (int n = 0; n < 2000; ++n) {
    alone.step(state, loads);
    highest = std::max(highest, state.q(0));
  }
  EXPECT_LE(highest, 2.0);
  EXPECT_NEAR(state.q(0), 2.0, 1e-12);
}

// Coulomb joint friction F on a joint about the vertical: an effort below F
// leaves it still, exactly; above, it turns at (τ − F)/I.
TEST(ArticulationJoints, FrictionHoldsBelowItsTorqueAndSlipsAbove) {
  ArticulationModel model = planarChain({2.0}, {1.0}, {0.0}, {0.5});
  model.links[1].axis_J = Vec3::UnitZ();
  model.links[1].mass.I_C_F = Vec3(0.3, 0.3, 0.5).asDiagonal();
  model.links[1].friction = 2.0;
  for (const double effort : {1.5, -1.99, 3.0, -5.0}) {
    ArticulationState state = restState(model);
    ArticulationLoads loads;
    loads.effort = Eigen::VectorXd::Constant(1, effort);
    LoneRobot alone(model, kGravity, 1e-3);
    for (int n = 0; n < 999; ++n) alone.step(state, loads);
    const double before = state.v(0);
    alone.step(state, loads);
    const double slip = std::abs(effort) > 2.0 ? (effort - std::copysign(2.0, effort)) / 0.5 : 0.0;
    EXPECT_NEAR((state.v(0) - before) / 1e-3, slip, 1e-9) << "effort " << effort;
    // The first step's start (§11.5) knows no friction: within a step of slip t.
    EXPECT_NEAR(state.v(0), slip * 1.0, 1.001e-3 * std::abs(slip) + 1e-15) << "effort " << effort;
    if (slip == 0.0) {
      EXPECT_NEAR(state.q(0), 0.0, 1e-15);
    }
  }
  // A pendulum at 0.2 rad held by friction above its gravity torque m g l sin θ.
  ArticulationModel pendulum = planarChain({1.0}, {1.0}, {0.5}, {1.0 / 12.0});
  pendulum.links[1].friction = 1.0 * 9.81 * 0.5 * std::sin(0.2) * 1.01;
  ArticulationState held = restState(pendulum);
  held.q(0) = 0.2;
  LoneRobot holding(pendulum, kGravity, 1e-3);
  for (int n = 0; n < 1000; ++n) holding.step(held);
  EXPECT_NEAR(held.q(0), 0.2, 1e-15);
  pendulum.links[1].friction *= 0.9;  // now too weak: it slips
  LoneRobot slipping(pendulum, kGravity, 1e-3);
  for (int n = 0; n < 100; ++n) slipping.step(held);
  EXPECT_LT(held.q(0), 0.2);
}

// A double pendulum whose second joint mimics the first (q₂ = −0.5 q₁ + 0.1):
// the ratio holds within 1e-6 over a 5 s swing.
TEST(ArticulationJoints, MimicJointsKeepTheirRatio) {
  ArticulationModel model = planarChain({1.0, 0.5}, {1.0, 0.6}, {0.5, 0.3}, {1.0 / 12.0, 0.015});
  model.links[2].mimic = {1, -0.5, 0.1};
  checkArticulation(model);
  ArticulationState state = restState(model);
  state.q << 1.2, -0.5;
  double worst = 0.0;
  LoneRobot alone(model, kGravity, 1e-3);
  for (int n = 0; n < 5000; ++n) {
    alone.step(state);
    if (n > 0) worst = std::max(worst, std::abs(state.q(1) - (-0.5 * state.q(0) + 0.1)));
  }
  EXPECT_LT(worst, 1e-6);
  EXPECT_GT(std::abs(state.q(0) - 1.2), 0.1);  // it did swing
}

// The guard: a NaN or infinite effort (no effort limit in the URDF) leaves
// the state where the step began, at rest; a finite but absurd one is slowed
// to the speed limit; loads of the wrong size are refused.
TEST(ArticulationStep, TheGuardKeepsEveryStateFinite) {
  ArticulationModel pendulum = planarChain({1.0}, {1.0}, {0.5}, {1.0 / 12.0});
  {
    ArticulationState state = restState(pendulum);
    ArticulationLoads loads;
    loads.effort = Eigen::VectorXd::Constant(1, 1e308);
    SpeedLimits limits;
    limits.max_angular_speed = 50.0;
    EXPECT_TRUE(stepAlone(pendulum, state, loads, kGravity, 1e-3, limits));
    EXPECT_EQ(state.v(0), 50.0);
    EXPECT_FALSE(state.carried.valid);
  }
  for (const double effort : {std::nan(""), std::numeric_limits<double>::infinity()}) {
    ArticulationState state = restState(pendulum);
    state.q(0) = 0.4;
    state.v(0) = 1.0;
    ArticulationLoads loads;
    loads.effort = Eigen::VectorXd::Constant(1, effort);
    EXPECT_FALSE(stepAlone(pendulum, state, loads, kGravity, 1e-3)) << effort;
    EXPECT_EQ(state.q(0), 0.4);
    EXPECT_EQ(state.v(0), 0.0);
    EXPECT_FALSE(state.carried.valid);
    loads.effort(0) = 0.0;
    EXPECT_TRUE(stepAlone(pendulum, state, loads, kGravity, 1e-3));
    EXPECT_TRUE(state.q.allFinite() && state.v.allFinite());
  }
  // A base on the world with no joint has nothing to move (the fuzzer found
  // its empty vectors read).
  ArticulationModel still;
  still.fixed_base = true;
  still.links.resize(1);
  ArticulationState nothing = restState(still, {Quat::Identity(), Vec3(1, 2, 3)});
  EXPECT_TRUE(stepAlone(still, nothing, {}, kGravity, 1e-3));
  EXPECT_EQ(nothing.X_WB.translation, Vec3(1, 2, 3));
  ArticulationState state = restState(pendulum);
  ArticulationLoads loads;
  loads.effort = Eigen::VectorXd::Zero(2);
  EXPECT_THROW(stepAlone(pendulum, state, loads, kGravity, 1e-3), std::invalid_argument);
  loads.effort.resize(0);
  loads.wrench_L.resize(1);
  EXPECT_THROW(stepAlone(pendulum, state, loads, kGravity, 1e-3), std::invalid_argument);
}

TEST(ArticulationModel, RefusesWhatCannotBeSimulatedNamingIt) {
  std::mt19937 rng(5);
  const ArticulationModel good = randomTree(rng, 3, false, true);
  checkArticulation(good);
  const auto refusal = [&](auto edit) {
    ArticulationModel bad = good;
    edit(bad);
    try {
      checkArticulation(bad);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(refusal([](auto& m) { m.links[2].parent = 2; }).find("joint 'joint2' parent"), std::string::npos);
  EXPECT_NE(refusal([](auto& m) { m.links[3].mass.mass = 0.0; }).find("link 'link3' mass"), std::string::npos);
  EXPECT_NE(refusal([](auto& m) { m.links[1].mass.I_C_F(0, 0) = -1.0; }).find("link 'link1' inertia"),
            std::string::npos);
  EXPECT_NE(refusal([](auto& m) { m.links[1].mass.I_C_F = Vec3(1.0, 1.0, 3.0).asDiagonal(); }).find("triangle"),
            std::string::npos);
  EXPECT_NE(refusal([](auto& m) {
              m.links[2].limits.lower = 1.0;
              m.links[2].limits.upper = 0.5;
            }).find("joint 'joint2' limit"),
            std::string::npos);
  EXPECT_NE(refusal([](auto& m) { m.links[2].axis_J = Vec3::Zero(); }).find("joint 'joint2' axis"), std::string::npos);
  EXPECT_NE(refusal([](auto& m) { m.links[1].damping = NAN; }).find("joint 'joint1' dynamics damping"),
            std::string::npos);
  EXPECT_NE(refusal([](auto& m) {
              m.links[2].mimic.joint = 1;
              m.links[3].mimic.joint = 2;
            }).find("joint 'joint3' mimic"),
            std::string::npos);
  EXPECT_NE(refusal([](auto& m) { m.links[0].mass.mass = 0.0; }).find("link 'base' mass"), std::string::npos);
  // A fixed base needs no mass: it is the world's.
  EXPECT_EQ(refusal([](auto& m) {
              m.fixed_base = true;
              m.links[0].mass = {};
            }),
            "accepted");
}

}  // namespace
}  // namespace rigid_body_sim::core
