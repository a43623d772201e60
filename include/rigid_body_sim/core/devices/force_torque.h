// A force-torque sensor on a robot's joint, as gazebo_ros_ft_sensor reads
// one (docs/physics.md §10.10): the wrench the joint carries from its parent
// onto its child link, in the child's axes about its origin, from the step's
// motion, gravity, the loads on the links beyond it and their contacts.
#pragma once

#include <cstdint>
#include <random>
#include <vector>

#include "rigid_body_sim/core/articulations/articulation_dynamics.h"
#include "rigid_body_sim/core/articulations/scene.h"
#include "rigid_body_sim/core/bodies/state.h"
#include "rigid_body_sim/core/contacts/contact.h"
#include "rigid_body_sim/core/devices/sample_seed.h"

namespace rigid_body_sim::core {

struct ForceTorqueSettings {
  double noise = 0.0;      ///< σ of each of the six numbers' Gaussian noise (N and N·m alike, as the plugin's)
  std::uint64_t seed = 0;  ///< of the noise: the same seed, the same readings
};

/// Throws std::invalid_argument naming the field: noise not finite ≥ 0.
void checkForceTorque(const ForceTorqueSettings& s);

/// The wrench `contacts` (a step's, impulses over its `h` s) put on each
/// link of `robot` (its links' bodies from robot.first_body, state `bodies`
/// at the step's end, the links placed by `kin`): per link, [moment about
/// its origin; force] in its axes, N·m and N; zero for a link with no body.
std::vector<Vec6> contactWrenches_L(const SceneRobot& robot, const ArticulationKinematics& kin,
                                    const std::vector<BodyState>& bodies, const std::vector<Contact>& contacts,
                                    double h);

class ForceTorqueSensor {
 public:
  /// On the joint of link `link` (> 0) of its robot.
  ForceTorqueSensor(int link, const ForceTorqueSettings& settings);
  int link() const { return link_; }

  /// The reading at the step that took the robot's velocity from `u_before`
  /// to the state of `kin` (its velocity `u`) in `h` s, under gravity g_W,
  /// the step's loads on its links `wrench_L` (empty: none) and its
  /// contacts' (contactWrenches_L): jointWrenches at u̇ = (u − u_before)/h,
  /// its link's entry, with the noise (reading k's own, sampleSeed(seed, k)). [torque; force].
  Vec6 reading(const ArticulationModel& model, const ArticulationKinematics& kin, const Eigen::VectorXd& u,
               const Eigen::VectorXd& u_before, double h, const Vec3& g_W, const std::vector<Vec6>& wrench_L);
  /// A reading due but not taken (nobody reads it): the next one is reading k + 1 all the same.
  void pass() { ++readings_; }
  /// The next reading is reading 0 again: the noise from its seed (a world reset).
  void restart() { readings_ = 0; }

 private:
  int link_;
  ForceTorqueSettings settings_;
  std::uint64_t readings_ = 0;  ///< readings so far, taken or passed
  std::mt19937_64 rng_;
  std::normal_distribution<double> normal_{0.0, 1.0};
};

}  // namespace rigid_body_sim::core
