// An articulation's joint constraints: docs/physics.md §11.6.
#include "joint_rows.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rigid_body_sim::core::detail {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

double rowVelocity(const JointRow& row, const Eigen::VectorXd& u) {
  double w = row.sign * u(row.offset + row.dof);
  if (row.other >= 0) w += row.coefficient * u(row.offset + row.other);
  return w;
}

JointRow makeRow(int offset, int dof, double sign, double target, double lower, double upper) {
  JointRow row;
  row.offset = offset;
  row.dof = dof;
  row.sign = sign;
  row.target = target;
  row.lower = lower;
  row.upper = upper;
  return row;
}

}  // namespace

void buildJointRows(const ArticulationModel& model, const ArticulationState& state, const Eigen::VectorXd& u_free,
                    double h, int offset, std::vector<JointRow>& rows) {
  for (int i = 1; i <= model.jointCount(); ++i) {
    const ArticulatedLink& link = model.links[i];
    const int d = model.dofOf(i);
    const double q = state.q(i - 1);
    // A limit the joint could reach this step (speculative, as contacts
    // are): its velocity may close the gap, no more. A joint already past
    // it (set there) may not go further; the positions are put back after.
    const double reach = h * std::abs(u_free(d));
    if (std::isfinite(link.limits.upper) && link.limits.upper - q <= reach) {
      rows.push_back(makeRow(offset, d, -1.0, -std::max(link.limits.upper - q, 0.0) / h, 0.0, kInfinity));
    }
    if (std::isfinite(link.limits.lower) && q - link.limits.lower <= reach) {
      rows.push_back(makeRow(offset, d, 1.0, std::min(link.limits.lower - q, 0.0) / h, 0.0, kInfinity));
    }
    // Coulomb friction: holds the joint while it can, at most friction · h.
    if (link.friction > 0.0) rows.push_back(makeRow(offset, d, 1.0, 0.0, -link.friction * h, link.friction * h));
    // A mimic joint: q = m q_k + offset, its error of this step taken out
    // by the velocity over it.
    if (link.mimic.joint > 0) {
      const Mimic& mimic = link.mimic;
      const double error = q - mimic.multiplier * state.q(mimic.joint - 1) - mimic.offset;
      JointRow row = makeRow(offset, d, 1.0, -error / h, -kInfinity, kInfinity);
      row.other = model.dofOf(mimic.joint);
      row.coefficient = -mimic.multiplier;
      rows.push_back(row);
    }
  }
}

void respond(const CoordinateBlock& block, const Columns& J, Columns& response) {
  if (block.factor != nullptr) {
    response = block.factor->solve(J);
    return;
  }
  response.resize(6, 3);
  response.topRows<3>() = block.inv_mass * J.topRows<3>();
  response.bottomRows<3>() = block.inv_inertia_W * J.bottomRows<3>();
}

namespace {

/// The block that starts at `offset` (blocks are in u's order).
const CoordinateBlock& blockAt(const std::vector<CoordinateBlock>& blocks, int offset) {
  const auto it = std::lower_bound(blocks.begin(), blocks.end(), offset,
                                   [](const CoordinateBlock& b, int at) { return b.offset < at; });
  return *it;
}

}  // namespace

void solveRows(const SolverSettings& settings, const std::vector<CoordinateBlock>& blocks, std::vector<JointRow>& rows,
               std::vector<ContactRows>& contacts, Eigen::VectorXd& u, Eigen::VectorXd& impulse) {
  for (JointRow& row : rows) {
    const CoordinateBlock& block = blockAt(blocks, row.offset);
    Eigen::VectorXd J = Eigen::VectorXd::Zero(block.size);
    J(row.dof) = row.sign;
    if (row.other >= 0) J(row.other) += row.coefficient;
    row.response = block.factor->solve(J);
    row.mass = 1.0 / J.dot(row.response);
    row.impulse = 0.0;
  }
  for (ContactRows& c : contacts) {
    c.K.setZero();
    double moves = 0.0;  // the largest change of a coordinate per unit normal impulse
    for (int s = 0; s < c.sides; ++s) {
      RowSide& side = c.side[s];
      respond(blockAt(blocks, side.offset), side.J, side.response);
      c.K.noalias() += side.J.transpose() * side.response;
      moves = std::max(moves, side.response.col(0).cwiseAbs().maxCoeff());
    }
    c.most = moves > 0.0 ? 2.0 * c.speed / moves : std::numeric_limits<double>::infinity();
    c.impulse = c.warm_start;
    if (!c.warm_start.isZero(0.0)) c.apply(c.warm_start, u);
    const Eigen::Matrix2d tangent_k = c.K.bottomRightCorner<2, 2>();
    c.block = tangent_k.determinant() > 1e-9 * tangent_k.trace() * tangent_k.trace();
    if (c.block) c.tangent_mass = tangent_k.inverse();
    c.eigen.ready = false;
    c.nu = 0.0;
  }
  // Sweeps until no row changes a velocity by more than the joint-space
  // tolerance (relative to the fastest joint), at most joint_space_sweeps;
  // or until they stall below the free bodies' tolerance: friction whose
  // limit moves with the normal impulse can cycle there instead of
  // converging (the free bodies' stall rule, §5.5: a sweep that takes off
  // more than stall_ratio of what the sweep four before took).
  const double tolerance = settings.joint_space_tolerance * std::max(1.0, u.cwiseAbs().maxCoeff());
  double recent[4] = {kInfinity, kInfinity, kInfinity, kInfinity};
  for (int sweep = 0; sweep < settings.joint_space_sweeps && !(rows.empty() && contacts.empty()); ++sweep) {
    double largest = 0.0;
    for (JointRow& row : rows) {
      const double next = std::clamp(row.impulse + row.mass * (row.target - rowVelocity(row, u)), row.lower, row.upper);
      const double change = next - row.impulse;
      if (change == 0.0) continue;
      row.impulse = next;
      u.segment(row.offset, row.response.size()) += change * row.response;
      largest = std::max(largest, std::abs(change) / row.mass);
    }
    for (ContactRows& c : contacts) largest = std::max(largest, sweepContactRows(settings, c, u));
    if (largest <= tolerance) break;
    const bool stalled = sweep >= settings.stall_min_sweeps && largest < settings.velocity_tolerance &&
                         largest > settings.stall_ratio * recent[sweep % 4];
    if (stalled) break;
    recent[sweep % 4] = largest;
  }
  for (const JointRow& row : rows) {
    impulse(row.offset + row.dof) += row.sign * row.impulse;
    if (row.other >= 0) impulse(row.offset + row.other) += row.coefficient * row.impulse;
  }
  for (const ContactRows& c : contacts) {
    for (int s = 0; s < c.sides; ++s) {
      impulse.segment(c.side[s].offset, c.side[s].J.rows()).noalias() += c.side[s].J * c.impulse;
    }
  }
}

}  // namespace rigid_body_sim::core::detail
