// The force-torque sensors on robots' joints: joint_wrenches.h.
#include "rigid_body_sim/ros/joint_wrenches.h"

#include <geometry_msgs/WrenchStamped.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "rigid_body_sim/ros/conversions.h"
#include "rigid_body_sim/ros/topic_claims.h"

namespace rigid_body_sim::node {

void JointWrenches::addRobot(const std::string& robot, const std::string& prefix, const std::string& frame_prefix,
                             const std::vector<io::RobotForceTorque>& sensors) {
  ros::NodeHandle& nh = *handles_.emplace_back(ownHandle(nh_));
  RobotPorts ports;
  for (const io::RobotForceTorque& s : sensors) {
    const io::ForceTorqueEntry& e = s.entry;
    Port p{core::ForceTorqueSensor(s.link, e.settings), "", 1, {}};
    p.every = e.rate > 0.0 ? std::max(1LL, std::llround(1.0 / (e.rate * dt_))) : 1;
    const std::string topic = deviceTopic(prefix, e.topic);
    p.wrench = CountedPublisher::advertise<geometry_msgs::WrenchStamped>(nh, topic, 10);
    ROS_INFO("sim_node: robot '%s': the force-torque sensor of joint '%s' on %s at %g Hz", robot.c_str(),
             e.joint.c_str(), nh_.resolveName(topic).c_str(), 1.0 / (static_cast<double>(p.every) * dt_));
    ports.ports.push_back(std::move(p));
  }
  robots_.push_back(std::move(ports));
  frames_prefix_.push_back(frame_prefix);
}

void JointWrenches::restart() {
  for (RobotPorts& r : robots_) {
    for (Port& p : r.ports) p.sensor.restart();
    r.u_before.resize(0);
  }
}

void JointWrenches::before(const core::Simulation& sim) {
  for (std::size_t r = 0; r < robots_.size(); ++r) {
    if (!robots_[r].ports.empty()) {
      robots_[r].u_before = core::generalizedVelocity(sim.scene.robots()[r].model, sim.robots[r]);
    }
  }
}

void JointWrenches::publish(const core::Simulation& sim, const std::vector<core::ArticulationLoads>& robot_loads,
                            long long steps, const ros::Time& stamp) {
  std::vector<core::Contact> touching;
  bool found = false;
  for (std::size_t r = 0; r < robots_.size(); ++r) {
    RobotPorts& ports = robots_[r];
    const core::SceneRobot& robot = sim.scene.robots()[r];
    const core::ArticulationState& state = sim.robots[r];
    bool placed = false;
    std::vector<core::Vec6> wrench_L;
    Eigen::VectorXd u;
    for (Port& p : ports.ports) {
      if (steps % p.every != 0 || !p.wrench.listened() || !ros::ok()) continue;
      if (!found) {  // the world's touching contacts, once for every sensor
        touching = sim.contacts.touchingNow(sim.state, sim.workspace.bodies.contacts);
        found = true;
      }
      if (!placed) {  // the links' loads of the step: its contacts' and those given
        core::kinematics(robot.model, state, kin_);
        wrench_L = core::contactWrenches_L(robot, kin_, sim.state.bodies, touching, dt_);
        if (r < robot_loads.size()) {
          const core::ArticulationLoads& l = robot_loads[r];
          for (std::size_t k = 0; k < wrench_L.size(); ++k) {
            if (k < l.wrench_L.size()) wrench_L[k] += l.wrench_L[k];
            if (k < l.impulse_L.size()) wrench_L[k] += l.impulse_L[k] / dt_;
          }
        }
        u = core::generalizedVelocity(robot.model, state);
        if (ports.u_before.size() != u.size()) ports.u_before = u;  // no step yet: as if steady
        placed = true;
      }
      const core::Vec6 w = p.sensor.reading(robot.model, kin_, u, ports.u_before, dt_, sim.model().gravity(), wrench_L);
      if (!w.allFinite()) continue;  // nothing is published non-finite
      geometry_msgs::WrenchStamped m;
      m.header.stamp = stamp;
      m.header.frame_id = frames_prefix_[r] + robot.model.links[static_cast<std::size_t>(p.sensor.link())].name;
      m.wrench.torque = toVector3(w.head<3>());
      m.wrench.force = toVector3(w.tail<3>());
      p.wrench.publish(m);
    }
  }
}

}  // namespace rigid_body_sim::node
