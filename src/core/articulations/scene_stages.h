// The robots' stages of the one step (private to the core), docs/physics.md
// §11.9: step.cpp lists them among the free bodies' stages. The robots' two
// halves and their bookkeeping are scene_step.cpp; the islands that hold a
// robot and their one solve scene_solve.cpp, their sleep and waking
// scene_sleep.cpp. Each does nothing in a world without robots.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "joint_rows.h"
#include "rigid_body_sim/core/articulations/scene.h"
#include "step/world.h"

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
  std::vector<char> woken;                    ///< per robot: woken in this step, during a step
  std::vector<char> touching;                 ///< per robot: in contact, for the sleep stage
  RobotSolve solve;
};

// The stages are not exported from the library (only its own files and the
// core tests, which link its objects, call them).
#pragma GCC visibility push(hidden)

/// Throws std::invalid_argument when the state or the loads do not fit the
/// world (a state per body and per robot; loads per free body, per body
/// with the links' zero, or none; per robot, or none).
void checkWorld(const World& world, const WorldState& state, const WorldLoads& loads);

/// Robot r's loads (none when the world's loads give none).
const ArticulationLoads& robotLoads(const WorldLoads& loads, std::size_t r);

/// Robot r's links as bodies where it is now, moving as it does; a
/// sleeping robot's as sleepers. Its kinematics stay in ws.robots[r].kin,
/// where its first half (predictRobot) starts from.
void placeLinks(const World& world, std::size_t r, WorldState& state, WorldWorkspace& ws);

/// Robot r's first half (awake, with dofs), from the kinematics its
/// placement left: its velocity without rows, in its workspace (`next`);
/// where the step began (`start`, for the guard).
void predictRobot(const World& world, std::size_t r, const ArticulationLoads& loads, double h, WorldState& state,
                  WorldWorkspace& ws);

// ---- The robots' stages, in the order step.cpp lists them.

/// Before the stages: the robots' workspaces sized, and every sleeping
/// robot under a load awake (in scratch->woken).
void wakeLoadedRobots(const World& world, const WorldLoads& loads, WorldState& state, WorldWorkspace& ws);

/// Every robot's links placed where it now is (placeLinks): what detection
/// sees at the start, readers and the next step at the end.
void placeAllLinks(const World& world, WorldState& state, WorldWorkspace& ws);

/// Drops the detection's contacts between links joined by a joint (they
/// meet at it, and never touch).
void dropJoinedLinks(const World& world, Workspace& ws);

/// A sleeping robot whose link the detection woke (something came at it)
/// wakes, its links with it. A robot woken this step (by that or by a load,
/// scratch->woken) wakes the sleeping bodies its links touch: they slept as
/// one island, and a robot pressing on a sleeper it rested against would
/// not come at it fast enough to wake it (the free bodies' rule).
void wakeHitRobots(const World& world, WorldState& state, WorldWorkspace& ws);

/// Moves the contacts of the islands that hold an awake robot (bodies
/// joined by contacts between awake bodies, a robot's links joined to each
/// other) out of ws.bodies.contacts into scratch->robot_contacts; both stay
/// sorted by key. Keeps each body's island in scratch->island_root, and the
/// last step's impulses in scratch->last_impulses. The free bodies' stages
/// then see only the other islands' contacts, and no link: the links are
/// marked asleep until the robots place them again (placeAllLinks).
void takeRobotContacts(const World& world, WorldState& state, WorldWorkspace& ws);

/// Every robot's first half (predictRobot), beside the free bodies'
/// velocity stage (integrateVelocities in step.cpp).
void predictRobots(const World& world, const WorldLoads& loads, double h, WorldState& state, WorldWorkspace& ws);

/// The one solve of the islands that hold a robot: every awake robot's
/// joint rows and every contact of those islands, warm started; the
/// velocities back (the robots' ws.next, the bodies' v and ω), the
/// impulses into scratch->robot_contacts, and the position correction's
/// pseudo velocity in scratch->solve.
void solveRobotIslands(const World& world, WorldState& state, double h, WorldWorkspace& ws);

/// The free bodies of the robots' islands moved by the position
/// correction's pseudo velocity (their velocities kept).
void liftBodies(const World& world, const WorldWorkspace& ws, double h, WorldState& state);

/// Every awake robot's second half: its momenta from the solve's impulses,
/// its positions, the speed limits and the guard (ws.robot_diverged).
void finishRobots(const World& world, double h, WorldState& state, WorldWorkspace& ws);

/// The robots' contacts merged back among the others (sorted by key), and
/// every contact's impulses kept in the state for the next step's warm start.
void recordRobotContacts(const World& world, WorldState& state, WorldWorkspace& ws);

/// Awake, its still time restarted.
inline void wakeRobot(ArticulationState& rs) {
  rs.asleep = false;
  rs.still_time = 0.0;
}

#pragma GCC visibility pop

}  // namespace rigid_body_sim::core::detail
