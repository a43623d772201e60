// The scratch memory of a step (private to the core): what the stages leave
// for each other and reuse from step to step. Workspace::scratch points here.
#pragma once

#include <array>
#include <memory>
#include <mutex>
#include <utility>
#include <vector>

#include "contacts/solver_contact.h"
#include "rigid_body_sim/core/step/loads.h"
#include "rigid_body_sim/core/step/parallel.h"
#include "rigid_body_sim/core/step/workspace.h"

namespace rigid_body_sim::core::detail {

/// A contact point found by the detection, before the reduction.
struct ContactCandidate {
  int other = -1;
  int item = -1;
  int point = 0;
  int region = 0;
  double separation = 0.0;        ///< m
  Vec3 normal_W = Vec3::UnitZ();  ///< ∇φ at the point
  Vec3 r_B = Vec3::Zero();        ///< where: the contact point's r_B, or where its round feature touches (m)
};

/// Scratch memory of one part of a stage (one thread's share).
struct PartScratch {
  std::vector<ContactCandidate> candidates;
  std::vector<Vec3> region_normals;
  std::vector<int> region_members;
  std::vector<Vec3> region_points;
  std::vector<double> separations;
  std::vector<int> impact_contacts;
  std::vector<int> kept;                        ///< candidates kept by the reduction
  std::vector<Contact> contacts;                ///< this part's contacts, before they are merged
  std::vector<std::pair<int, int>> directions;  ///< broad phase: this part's directions, before they are merged
  double deepest = 0.0;                         ///< m
};

/// A step that changed nothing but the time and the still times, bit for bit
/// (fixed_point.h): the input it was given, kept to compare the next one with.
struct FixedPoint {
  /// The last step returned its input, kept below, unchanged.
  bool holds = false;
  const Model* model = nullptr;          ///< the model the input was stepped with
  std::vector<BodyState> bodies;         ///< still times aside
  std::vector<ContactImpulse> impulses;  ///< the warm start
  Loads loads;
  bool islands_known = false;  ///< the last step's islands are in island_root
  bool kept = false;           ///< the input of the step being computed is kept above
};

struct StepScratch {
  /// Per body: touched the scene or another body this step (only bodies in contact may sleep).
  std::vector<char> in_contact;
  /// Per body: solved as a stiff body this step (stiff_body.h), so corrected as one.
  std::vector<char> stiff;
  std::vector<int> stiff_contacts;  ///< position stage: the contacts of one stiff body
  /// Impulse solver: the contacts island by island (see island_starts).
  std::vector<SolverContact> solver_contacts;
  /// Impulse solver: the velocities of the bodies in contact, side by side.
  std::vector<BodyVelocity> velocities;
  /// Impulse solver: the awake bodies' inverse inertia in world axes, R I⁻¹ Rᵀ (1/(kg·m²)).
  std::vector<Mat3> inverse_inertias;
  /// Shape matching: where each vertex of the current body went (m, world).
  std::vector<Vec3> positions;
  /// Broad phase: bodies in sweep order, and their boxes.
  std::vector<int> sweep_order;  ///< by (strip along y, lo x)
  std::vector<double> margins, box_lo, box_hi, box_strip, sorted_boxes;
  /// Both directions (a, o) of every pair whose boxes overlap, sorted: a's points against o's solid.
  std::vector<std::pair<int, int>> directions;
  std::vector<std::pair<int, int>> unsorted_directions;  ///< the parts' directions, merged
  std::vector<int> direction_starts;                     ///< per body a: where its directions start
  /// Islands of the impulse solve: contact indices island by island, and offsets.
  std::vector<int> island_contacts, island_starts, island_of;
  /// Per body: its island's root, the island's smallest body index (findIslands).
  std::vector<int> island_root;
  std::vector<char> island_flags;     ///< per island root: scratch of the sleep and position stages
  std::vector<char> island_touching;  ///< per body: touches something, for the sleep stage
  /// Per body: pushed by a contact (λ_N > 0) and left exactly still (v = ω = 0)
  /// by this step's impulse solve: in equilibrium, so it may sleep at once.
  std::vector<char> held_still;
  std::vector<int> correct_contacts;  ///< the contacts the position stage corrects
  /// The pairs that pressed on each other last step (λ_N > 0), sorted: an
  /// impact between them is plastic (a rocking impact, docs/physics.md
  /// §5.5). (lower body, higher body or −1 for the scene, scene item or −1).
  std::vector<std::array<int, 3>> pressed_pairs;
  /// Log barrier (barrier.h): each contact's separation at the end of the
  /// step's previous pass (m; empty in a first pass), where the last pass
  /// ended, and per body the sums Σ k w and Σ c w of its step control.
  std::vector<double> barrier_end, barrier_settled, barrier_stiffness, barrier_damping;
  std::vector<PartScratch> parts;  ///< one per part of a split stage
  std::mutex guard_mutex;          ///< guard.h: putBack() from the parts of a split stage
  std::shared_ptr<WorkerPool> pool;
  FixedPoint fixed_point;
};

// Not exported from the library (only its own files and the core tests,
// which link its objects, call it), so link-time optimisation may inline it.
#pragma GCC visibility push(hidden)

/// How many parts a stage of `work` units (awake bodies, contacts) splits
/// into: one unless there is enough for another core to pay (and then the
/// workspace's thread count, whose pool this makes); at least that many
/// PartScratch are ready in ws.scratch->parts.
int partsFor(Workspace& ws, std::size_t work);

#pragma GCC visibility pop

/// Runs part(k) for k < parts (parallelFor on the workspace's pool).
template <class Part>
void runParts(Workspace& ws, int parts, Part&& part) {
  parallelFor(ws.scratch->pool.get(), parts, std::forward<Part>(part));
}

}  // namespace rigid_body_sim::core::detail
