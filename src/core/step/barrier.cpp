// The log barrier's force law and step control (docs/physics.md §7.2).
#include "barrier.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "rigid_body_sim/core/contacts/contact.h"
#include "scratch.h"

namespace rigid_body_sim::core {

double barrierPotential(const ContactSettings& cs, double phi) {
  const double eps = cs.barrier_buffer;
  if (phi >= eps) return 0.0;
  phi = std::max(phi, SolverSettings::kBarrierFloor);
  return cs.barrier_strength * (std::log(eps / phi) - 1.0 + phi / eps);
}

double barrierForce(const ContactSettings& cs, double phi0, double phi1) {
  const double a = std::max(phi0, SolverSettings::kBarrierFloor), b = std::max(phi1, SolverSettings::kBarrierFloor);
  if (std::abs(b - a) > 1e-6 * std::min(a, b)) {
    return (barrierPotential(cs, a) - barrierPotential(cs, b)) / (b - a);
  }
  const double mid = 0.5 * (a + b);
  return mid >= cs.barrier_buffer ? 0.0 : cs.barrier_strength * (1.0 / mid - 1.0 / cs.barrier_buffer);
}

namespace {

/// Each contact's separation at the end of the step from `before` to
/// `after`: its point carried by the body (and, between bodies, the other
/// body's point under it by the other), measured along the normal.
void endSeparations(const State& before, const State& after, std::vector<double>& end, const Workspace& ws) {
  end.resize(ws.contacts.size());
  const auto moved = [&](int i, const Vec3& r_W) {
    const BodyState &b0 = before.bodies[i], &b1 = after.bodies[i];
    return Vec3(b1.p_WB - b0.p_WB + b1.q_WB * (b0.q_WB.conjugate() * r_W) - r_W);
  };
  for (std::size_t k = 0; k < ws.contacts.size(); ++k) {
    const Contact& c = ws.contacts[k];
    Vec3 d = moved(c.body, c.r_W);
    if (c.other >= 0) d -= moved(c.other, c.r_other_W);
    end[k] = c.separation + c.normal_W.dot(d);
  }
}

/// Whether the barrier's springs, taken over h, are stiffer than the step
/// can follow: h² Σ k w > 1 or h Σ c w > 1 for some body, with k = ρ/φ² a
/// contact's stiffness at the nearer of its ends (ws' barrier_end holds the
/// step's end), c the damper and
/// w = 1/m + |r|²/I_min a bound of the point's inverse effective mass
/// (explicit integration of a spring is stable while h ω < 2).
bool tooStiff(const Model& model, const Workspace& ws, double h) {
  const ContactSettings& cs = model.contact();
  std::vector<double>& stiff = ws.scratch->barrier_stiffness;
  std::vector<double>& damp = ws.scratch->barrier_damping;
  stiff.assign(model.bodyCount(), 0.0);
  damp.assign(model.bodyCount(), 0.0);
  const auto weight = [&](int i, const Vec3& r) {
    const BodyModel& b = model.body(i);
    return b.inv_mass + r.squaredNorm() * b.inv_inertia_B.maxCoeff();
  };
  const std::vector<double>& end = ws.scratch->barrier_end;
  for (std::size_t n = 0; n < ws.contacts.size(); ++n) {
    const Contact& c = ws.contacts[n];
    const double phi = std::max(std::min(c.separation, end[n]), SolverSettings::kBarrierFloor);  // the stiffer end
    if (phi >= cs.barrier_buffer) continue;
    const double k = cs.barrier_strength / (phi * phi);
    double w = weight(c.body, c.r_W);
    if (c.other >= 0) w += weight(c.other, c.r_other_W);
    for (const int i : {c.body, c.other}) {
      if (i < 0) continue;
      stiff[i] += k * w;
      damp[i] += cs.penalty_damping * w;
    }
  }
  for (std::size_t i = 0; i < stiff.size(); ++i) {
    if (h * h * stiff[i] > 1.0 || h * damp[i] > 1.0) return true;
  }
  return false;
}

/// Whether a body's smallest φ inside the buffer reaches 0, or shrinks or
/// grows by more than the step factor, or crosses the buffer's edge from
/// farther than that factor inside it.
bool crossesTooFar(const Model& model, const State& before, const State& after) {
  const double growth = model.solver().barrier_step_factor;
  const double buffer = model.contact().barrier_buffer;
  for (std::size_t i = 0; i < model.bodyCount(); ++i) {
    const int body = static_cast<int>(i);
    const double was = minSeparation(model, before.bodies[i], body, buffer);
    const double now = minSeparation(model, after.bodies[i], body, buffer);
    const bool was_out = std::isinf(was), now_out = std::isinf(now);
    if (was_out && now_out) continue;  // outside the buffer throughout
    if (!(now > 0.0)) return true;
    if (was_out ? now < buffer / growth : now_out ? was < buffer / growth : now < was / growth || now > growth * was) {
      return true;
    }
  }
  return false;
}

}  // namespace

void advanceKeepingBarrier(const Model& model, State& state, const Loads& loads, double h, Workspace& ws,
                           const Advance& advance, int depth) {
  const SolverSettings& solver = model.solver();
  const State before = state;
  // The first pass takes each force at the start; the next take the exact
  // work from there to where the previous pass ended (a fixed point).
  detail::StepScratch& sc = *ws.scratch;
  sc.barrier_end.clear();
  advance(model, state, loads, h, ws);
  // Without contacts there is no barrier force: the passes would repeat the first.
  for (int pass = 0; pass < solver.barrier_passes && !ws.contacts.empty(); ++pass) {
    endSeparations(before, state, sc.barrier_end, ws);
    state = before;
    advance(model, state, loads, h, ws);
  }
  // Where the last pass ended against where its forces assumed it would: a
  // step too long for the fixed point to settle is taken again as halves.
  endSeparations(before, state, sc.barrier_settled, ws);
  bool redo = false;
  for (std::size_t k = 0; k < sc.barrier_end.size() && !redo; ++k) {
    const double assumed = sc.barrier_end[k], settled = sc.barrier_settled[k];
    redo = std::abs(settled - assumed) >
           SolverSettings::kBarrierSettle * std::max(std::min(settled, assumed), SolverSettings::kBarrierFloor);
  }
  sc.barrier_end.swap(sc.barrier_settled);
  redo = redo || tooStiff(model, ws, h) || crossesTooFar(model, before, state);
  sc.barrier_end.clear();
  if (!redo || depth >= solver.barrier_max_halvings) return;
  state = before;
  advanceKeepingBarrier(model, state, loads, 0.5 * h, ws, advance, depth + 1);
  advanceKeepingBarrier(model, state, loads, 0.5 * h, ws, advance, depth + 1);
}

}  // namespace rigid_body_sim::core
