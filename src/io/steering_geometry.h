// Where a steered base's wheels and steering joints are (private to io):
// its URDF at rest, read into the core's SteeringSpec (docs/physics.md
// §11.14) for an AckermannSteeringController or gazebo_ros_tricycle_drive.
#pragma once

#include <string>
#include <vector>

#include "rigid_body_sim/core/articulations/articulation.h"
#include "rigid_body_sim/core/controllers/steering.h"

namespace rigid_body_sim::io::detail {

/// The joints of a steered base (link indices) and the keys naming them.
struct SteeredJoints {
  std::vector<int> driven, steers, fixed_axle;
  std::string driven_key, steers_key;
};

/// The steering of `joints` on `model` at rest, in its base's frame from
/// the fixed axle's centre: the mean of the `fixed_axle` wheels' centres,
/// else of the driven wheels that no steering joint carries. `wheelbase`
/// (m; ≤ 0: the steering joints' mean x from that centre). Refused
/// (ConfigError naming the key): a steering axis not within 25° of the
/// base's z, no wheel on the fixed axle, a wheelbase not > 0.
core::SteeringSpec steeringOf(const core::ArticulationModel& model, const SteeredJoints& joints, double wheelbase);

}  // namespace rigid_body_sim::io::detail
