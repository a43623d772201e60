// The integrators of an articulation's step (articulation_integrators.h):
// docs/physics.md §11.5.
#include "articulation_integrators.h"

#include <Eigen/Cholesky>
#include <limits>

#include "rigid_body_sim/core/articulations/articulation_dynamics.h"
#include "rigid_body_sim/core/bodies/settings.h"

namespace rigid_body_sim::core::detail {

/// Its constants are in settings.h (SolverSettings: a robot's integrators).
using S = SolverSettings;

bool symplecticPasses(const ArticulationModel& model, double h, ArticulationWorkspace& ws) {
  const int nj = model.jointCount();
  Eigen::VectorXd& u_next = ws.next;
  u_next = ws.predicted;
  Eigen::VectorXd& corrected = ws.corrected;
  Eigen::VectorXd& rhs = ws.rhs;
  int& predict_only = ws.predict_only;
  double last_change = std::numeric_limits<double>::infinity();
  bool converged = false;
  const int passes = predict_only > 0 ? 0 : S::kCorrectorPasses;
  for (int pass = 0; pass < passes && !converged; ++pass) {
    setTwists(model, u_next, ws.kin);
    kineticEnergyGradient(model, ws.kin, ws.dynamics, ws.gradient);
    rhs.tail(nj) = ws.p + h * (ws.force.tail(nj) + ws.gradient.tail(nj));
    corrected = rhs;
    ws.factor.solveInPlace(corrected);
    const double change = (corrected - u_next).cwiseAbs().maxCoeff();
    const double scale = 1.0 + corrected.cwiseAbs().maxCoeff();
    if (!(change <= S::kCorrectorContraction * last_change)) {
      converged = last_change <= S::kCorrectorRounding * scale;
      break;
    }
    u_next.swap(corrected);
    last_change = change;
    converged = change <= S::kCorrectorTolerance * scale;
  }
  if (predict_only > 0) {
    --predict_only;
  } else if (!converged) {
    predict_only = S::kPredictOnlySteps;
  }
  return converged;
}

bool verletPasses(const ArticulationModel& model, const ArticulationLoads& loads, const Vec3& g_W,
                  const std::vector<Vec6>& wrench_L, double h, bool fresh, ArticulationWorkspace& ws) {
  const int nj = model.jointCount();
  Eigen::VectorXd& u_next = ws.next;
  Eigen::VectorXd& before = ws.before;
  Eigen::VectorXd& step = ws.corrected;
  // What the velocity gains over the step: the efforts, the bias (gravity,
  // the wrenches and the Coriolis terms) and the damping at ū.
  const auto gain = [&](const Eigen::VectorXd& bias, Eigen::VectorXd& out) {
    out = h * (ws.force - bias);
    for (int i = 1; i <= nj; ++i) out(model.dofOf(i)) -= h * model.links[i].damping * before(model.dofOf(i));
    ws.factor.solveInPlace(out);
    out += before;
  };
  if (fresh) {
    // ū = u − ½ h A⁻¹ (τ − c(q, u)), the loads without the step's impulses
    // (they act over this step, not the last); c at u is then exact.
    before = ws.u;
    Eigen::VectorXd& half = ws.mid;
    half = 0.5 * h * (ws.force - ws.bias);  // h first: 1e308 N·m over I < 1 would overflow
    if (!loads.impulse_L.empty()) {
      biasForces(model, ws.kin, Vec3::Zero(), loads.impulse_L, false, ws.dynamics, ws.gradient);
      half += 0.5 * ws.gradient;  // the rest forces carry the wrenches' sign flipped
    }
    ws.factor.solveInPlace(half);
    before -= half;
    gain(ws.bias, u_next);
    ws.gain = u_next - before;
    return true;
  }
  before = ws.u;
  u_next = ws.predicted;
  double last_change = std::numeric_limits<double>::infinity();
  for (int pass = 0; pass < S::kVerletPasses; ++pass) {
    ws.mid = 0.5 * (before + u_next);
    biasForcesAt(model, ws.kin, ws.mid, g_W, wrench_L, ws.dynamics, ws.bias);
    gain(ws.bias, step);
    const double change = (step - u_next).cwiseAbs().maxCoeff();
    if (!(change < last_change)) break;  // growing: the passes diverge; the last stands
    u_next.swap(step);
    if (change <= S::kCorrectorTolerance * (1.0 + u_next.cwiseAbs().maxCoeff())) break;
    last_change = change;
  }
  ws.gain = u_next - before;
  return true;
}

void middleMomentum(const ArticulationModel& model, const ArticulationState& state, double h,
                    ArticulationWorkspace& ws) {
  const int nj = model.jointCount();
  Eigen::VectorXd& u_next = ws.next;
  ArticulationState& middle = ws.middle;
  middle = state;
  for (int i = 1; i <= nj; ++i) middle.q(i - 1) = state.q(i - 1) + 0.5 * h * u_next(model.dofOf(i));
  // M in the base's axes depends on the joints alone (§11.3): one M for
  // every round, which only turns the momentum into the base's axes.
  kinematics(model, middle, ws.middle_kin);
  massMatrix(model, ws.middle_kin, ws.dynamics, ws.middle_M);
  const Eigen::LLT<Mat6> base(ws.middle_M.topLeftCorner<6, 6>());
  const Vec6 joints_part = ws.middle_M.bottomLeftCorner(nj, 6).transpose() * u_next.tail(nj);
  double last_change = std::numeric_limits<double>::infinity();
  for (int round = 0; round < S::kMiddleRounds; ++round) {
    const Placement X_WB = Placement::of(advanceBase(state.X_WB, u_next.head<6>(), 0.5 * h));
    const Vec6 twist = base.solve(X_WB.forceToChild(ws.H_W) - joints_part);
    const double change = (twist - u_next.head<6>()).cwiseAbs().maxCoeff();
    u_next.head<6>() = twist;
    // Done at the tolerance, or where the rounds stall at rounding.
    if (change <= S::kMiddleTolerance * (1.0 + twist.cwiseAbs().maxCoeff()) || change >= last_change) break;
    last_change = change;
  }
}

}  // namespace rigid_body_sim::core::detail
