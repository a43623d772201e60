// The stages of a scene's step (private to the core), docs/physics.md §11.9:
// stepScene (scene_step.cpp) lists them with the free bodies' stages and the
// robots' two halves; the islands that hold a robot and their one solve are
// scene_solve.cpp, their sleep and waking scene_sleep.cpp.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "joint_rows.h"
#include "rigid_body_sim/core/articulations/scene.h"

namespace rigid_body_sim::core::detail {

/// The solve of the islands that hold a robot, over u: every robot's
/// joint-space velocity, then every awake free body in them (v_W, ω_W).
struct RobotSolve {
  std::vector<CoordinateBlock> blocks;
  std::vector<int> robot_offset;  ///< per robot; −1: no dofs
  std::vector<int> body_offset;   ///< per body; −1: not a block (a link, a sleeper, a body elsewhere)
  Eigen::VectorXd u, impulse, pseudo;
  std::vector<JointRow> rows;
  std::vector<ContactRows> contacts;
  bool lift = false;  ///< pseudo moves something
};

/// What a scene's stages keep between and within steps.
struct SceneScratch {
  std::vector<Contact> robot_contacts;        ///< the contacts the robots' solve takes, during a step
  std::vector<ContactImpulse> last_impulses;  ///< the last step's, for the robots' warm start, during a step
  std::vector<int> island_root;               ///< per body: its island's smallest body, during a step
  RobotSolve solve;
};

// The stages are not exported from the library (only its own files and the
// core tests, which link its objects, call them).
#pragma GCC visibility push(hidden)

/// Robot r's loads (none when the scene's loads give none).
const ArticulationLoads& robotLoads(const SceneLoads& loads, std::size_t r);

/// Robot r's links as bodies where it is now, moving as it does; a
/// sleeping robot's as sleepers.
void placeLinks(const Scene& scene, std::size_t r, SceneState& state, SceneWorkspace& ws);

/// Robot r's first half (awake, with dofs): its velocity without rows, its
/// links placed moving at it (for the speculative margins); else its links
/// placed where it is.
void predictRobot(const Scene& scene, std::size_t r, const ArticulationLoads& loads, double h, SceneState& state,
                  SceneWorkspace& ws);

/// Moves the contacts of the islands that hold an awake robot (bodies
/// joined by contacts between awake bodies, a robot's links joined to each
/// other) out of ws.bodies.contacts into ws.robot_contacts; both stay
/// sorted by key. Keeps each body's island in ws.island_root. The free
/// bodies' stages then see only the other islands' contacts.
void takeRobotContacts(const Scene& scene, const State& state, SceneWorkspace& ws);

/// The one solve of the islands that hold a robot: every awake robot's
/// joint rows and every contact of those islands, warm started; the
/// velocities back (the robots' ws.next, the bodies' v and ω), the
/// impulses into ws.robot_contacts, and the position correction's pseudo
/// velocity in `solve`.
void solveRobotIslands(const Scene& scene, SceneState& state, double h, SceneWorkspace& ws, RobotSolve& solve);

/// The free bodies of the robots' islands moved by the position
/// correction's pseudo velocity (their velocities kept).
void liftBodies(const Scene& scene, const RobotSolve& solve, double h, SceneState& state);

/// Awake, its still time restarted.
inline void wakeRobot(ArticulationState& rs) {
  rs.asleep = false;
  rs.still_time = 0.0;
}

/// A sleeping robot whose link the detection woke (something came at it)
/// wakes, and takes its first half now. A robot woken this step (by that or
/// by a load, `woken`) wakes the sleeping bodies its links touch: they
/// slept as one island, and a robot pressing on a sleeper it rested against
/// would not come at it fast enough to wake it (the free bodies' rule).
void wakeHitRobots(const Scene& scene, const SceneLoads& loads, double h, std::vector<char>& woken, SceneState& state,
                   SceneWorkspace& ws);

/// Sleep for the islands that hold a robot (§6, §11.9): every robot in it
/// touching, slower than the sleep speeds for the sleep time, and every
/// awake free body in it still as long: all of them fall asleep.
void sleepRobotIslands(const Scene& scene, double h, SceneState& state, SceneWorkspace& ws);

#pragma GCC visibility pop

}  // namespace rigid_body_sim::core::detail
