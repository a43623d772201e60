// An articulation's checks and state helpers (docs/physics.md §11.1).
#include "rigid_body_sim/core/articulations/articulation.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "bodies/validate.h"
#include "rigid_body_sim/core/articulations/articulation_dynamics.h"

namespace rigid_body_sim::core {

namespace {

bool finitePose(const Pose& X) { return X.translation.allFinite() && X.rotation.coeffs().allFinite(); }

void checkJoint(const ArticulationModel& model, int i) {
  const ArticulatedLink& link = model.links[i];
  const std::string field = "joint '" + link.joint + "'";
  if (link.parent < 0 || link.parent >= i) {
    detail::fail(field + " parent", std::to_string(link.parent),
                 "a joint's parent link must come before its child (a tree with one root)");
  }
  if (!finitePose(link.X_PJ) || std::abs(link.X_PJ.rotation.norm() - 1.0) > 1e-9) {
    detail::fail(field + " origin", detail::str(link.X_PJ.translation), "must be finite with a unit rotation");
  }
  if (!link.axis_J.allFinite() || std::abs(link.axis_J.norm() - 1.0) > 1e-9) {
    detail::fail(field + " axis", detail::str(link.axis_J), "must be a finite unit vector");
  }
  const JointLimits& lim = link.limits;
  if (std::isnan(lim.lower) || std::isnan(lim.upper) || lim.lower > lim.upper) {
    detail::fail(field + " limit", "[" + detail::str(lim.lower) + ", " + detail::str(lim.upper) + "]",
                 "lower must not exceed upper");
  }
  if (std::isnan(lim.effort) || lim.effort < 0.0)
    detail::fail(field + " limit effort", detail::str(lim.effort), "must be >= 0");
  if (std::isnan(lim.velocity) || lim.velocity < 0.0) {
    detail::fail(field + " limit velocity", detail::str(lim.velocity), "must be >= 0");
  }
  detail::requireNonNegative(link.damping, field + " dynamics damping", "N*m*s/rad or N*s/m");
  detail::requireNonNegative(link.friction, field + " dynamics friction", "N*m or N");
  const Mimic& mimic = link.mimic;
  if (mimic.joint >= 0) {
    if (mimic.joint == 0 || mimic.joint == i || mimic.joint >= static_cast<int>(model.links.size())) {
      detail::fail(field + " mimic", std::to_string(mimic.joint), "must name another joint");
    }
    if (model.links[mimic.joint].mimic.joint >= 0) {
      detail::fail(field + " mimic", "'" + model.links[mimic.joint].joint + "'",
                   "follows a joint that is itself a mimic");
    }
    if (!std::isfinite(mimic.multiplier) || !std::isfinite(mimic.offset)) {
      detail::fail(field + " mimic", detail::str(mimic.multiplier) + ", " + detail::str(mimic.offset),
                   "multiplier and offset must be finite");
    }
  }
}

}  // namespace

namespace {

/// The first generalized velocity that moves no mass or inertia the earlier
/// ones do not (a pivot of M's Cholesky factor at most 1e-10 of its
/// diagonal), or −1 when M is positive definite.
int singularDof(const Eigen::MatrixXd& M) {
  const int n = static_cast<int>(M.rows());
  Eigen::MatrixXd L = Eigen::MatrixXd::Zero(n, n);
  for (int k = 0; k < n; ++k) {
    const double d = M(k, k) - L.row(k).head(k).squaredNorm();
    if (!(d > 1e-10 * M(k, k))) return k;
    L(k, k) = std::sqrt(d);
    for (int i = k + 1; i < n; ++i) L(i, k) = (M(i, k) - L.row(i).head(k).dot(L.row(k).head(k))) / L(k, k);
  }
  return -1;
}

}  // namespace

void checkArticulation(const ArticulationModel& model) {
  if (model.links.empty()) detail::fail("articulation links", "0", "an articulation needs a base link");
  if (model.links[0].parent != -1) detail::fail("link '" + model.links[0].name + "' parent", "", "the base has none");
  std::vector<std::string> problems;
  const auto check = [&](auto&& what) {
    try {
      what();
    } catch (const std::invalid_argument& e) {
      problems.emplace_back(e.what());
    }
  };
  for (int i = 0; i < static_cast<int>(model.links.size()); ++i) {
    const ArticulatedLink& link = model.links[i];
    if (i > 0) check([&] { checkJoint(model, i); });
    const bool moves = i > 0 || !model.fixed_base;
    const std::string field = "link '" + link.name + "'";
    if (moves) {
      check([&] { detail::requireNonNegative(link.mass.mass, field + " mass", "kg"); });
      check([&] {
        if (link.mass.mass == 0.0 && !link.mass.I_C_F.isZero(0.0))
          detail::fail(field + " mass", "0", "a massless link has no inertia either");
      });
      check([&] { validateInertia(link.mass.I_C_F, field + " inertia", /*allow_zero=*/true); });
    }
    check([&] {
      if (!link.mass.p_FC.allFinite())
        detail::fail(field + " centre of mass", detail::str(link.mass.p_FC), "must be finite");
    });
  }
  if (problems.empty() && model.dofCount() > 0) {
    const int dof = singularDof(massMatrix(model, kinematics(model, restState(model))));
    if (dof >= 0) {
      const bool base = !model.fixed_base && dof < 6;
      const ArticulatedLink& link = model.links[base ? 0 : dof - (model.fixed_base ? 0 : 6) + 1];
      problems.push_back((base ? "the floating base '" + link.name + "'" : "joint '" + link.joint + "'") +
                         " moves no mass or inertia that the joints before it do not (a singular mass matrix): give "
                         "link '" +
                         link.name + "' or a link below it a mass and an inertia");
    }
  }
  if (problems.empty()) return;
  std::string all = problems.front();
  for (std::size_t i = 1; i < problems.size(); ++i) all += "; " + problems[i];
  throw std::invalid_argument(all);
}

int linkOfJoint(const ArticulationModel& model, const std::string& name) {
  for (int j = 1; j <= model.jointCount(); ++j) {
    if (model.links[j].joint == name) return j;
  }
  return -1;
}

std::string heldJointNote(const ArticulationModel& model, const std::string& name) {
  for (const HeldJoint& held : model.held) {
    if (held.name == name) return " (joint '" + name + "' is held: it moves only massless links)";
  }
  return "";
}

LinkState baseLinkState(const ArticulationState& s) {
  const Mat3 R = s.X_WB.rotation.toRotationMatrix();
  return {s.X_WB.translation, s.X_WB.rotation, R * s.V_B.tail<3>(), R * s.V_B.head<3>()};
}

void setBaseLinkState(ArticulationState& s, const LinkState& base) {
  s.X_WB = Pose{base.q_WL.normalized(), base.p_WL};
  const Mat3 R_BW = s.X_WB.rotation.toRotationMatrix().transpose();
  s.V_B.head<3>() = R_BW * base.w_W;  // the base twist, in its own axes
  s.V_B.tail<3>() = R_BW * base.v_WL;
}

double restPosition(const ArticulatedLink& link) {
  const JointLimits& lim = link.limits;
  return lim.lower <= lim.upper ? std::clamp(0.0, lim.lower, lim.upper) : 0.0;
}

ArticulationState restState(const ArticulationModel& model, const Pose& X_WB) {
  ArticulationState state;
  state.X_WB = X_WB;
  state.q = Eigen::VectorXd::Zero(model.jointCount());
  state.v = Eigen::VectorXd::Zero(model.jointCount());
  for (int i = 1; i < static_cast<int>(model.links.size()); ++i) {
    const ArticulatedLink& link = model.links[i];
    const int leader = link.mimic.joint;
    // A leader comes before a mimic only when it is its ancestor: take it from the link itself.
    state.q(i - 1) =
        leader > 0 ? link.mimic.multiplier * restPosition(model.links[leader]) + link.mimic.offset : restPosition(link);
  }
  return state;
}

Eigen::VectorXd generalizedVelocity(const ArticulationModel& model, const ArticulationState& state) {
  Eigen::VectorXd u(model.dofCount());
  const int base = model.fixed_base ? 0 : 6;
  if (base == 6) u.head<6>() = state.V_B;
  u.tail(model.jointCount()) = state.v;
  return u;
}

void setGeneralizedVelocity(const ArticulationModel& model, const Eigen::VectorXd& u, ArticulationState& state) {
  if (!model.fixed_base) state.V_B = u.head<6>();
  state.v = u.tail(model.jointCount());
}

}  // namespace rigid_body_sim::core
