// The contact sensors on robots' links: link_contacts.h.
#include "rigid_body_sim/ros/link_contacts.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "rigid_body_sim/core/contacts/contact_report.h"
#include "rigid_body_sim/core/devices/link_sensors.h"
#include "rigid_body_sim/ros/state_publisher.h"
#include "rigid_body_sim/ros/topic_claims.h"

namespace rigid_body_sim::node {

void LinkContacts::addRobot(const std::string& robot, const std::string& prefix, const std::string& frame_prefix,
                            const std::vector<io::RobotContactSensor>& sensors) {
  ros::NodeHandle& nh = *handles_.emplace_back(ownHandle(nh_));
  std::vector<Port> ports;
  for (const io::RobotContactSensor& s : sensors) {
    const io::ContactSensorEntry& e = s.entry;
    Port p;
    p.link = s.link;
    p.in_world = e.frame_id.empty();
    p.X_LS = s.X_LS;
    p.frame = p.in_world ? world_frame_ : frame_prefix + e.frame_id;
    p.every = e.rate > 0.0 ? std::max(1LL, std::llround(1.0 / (e.rate * dt_))) : 1;
    const std::string topic = deviceTopic(prefix, e.topic);
    p.contacts = CountedPublisher::advertise<Contacts>(nh, topic, 10);
    ROS_INFO("sim_node: robot '%s': the contacts of link '%s' on %s in '%s' at %g Hz", robot.c_str(), e.link.c_str(),
             nh_.resolveName(topic).c_str(), p.frame.c_str(), 1.0 / (static_cast<double>(p.every) * dt_));
    ports.push_back(std::move(p));
  }
  robots_.push_back(std::move(ports));
}

void LinkContacts::publish(const core::Simulation& sim, long long steps, const ros::Time& stamp) {
  bool found = false;
  std::vector<core::ContactPairReport> pairs;
  for (std::size_t r = 0; r < robots_.size(); ++r) {
    const core::SceneRobot& robot = sim.scene.robots()[r];
    bool placed = false;
    for (Port& p : robots_[r]) {
      if (steps % p.every != 0 || !p.contacts.listened() || !ros::ok()) continue;
      if (!found) {  // the world's touching pairs, once for every sensor
        pairs = core::contactPairs(sim.model(), sim.state,
                                   sim.contacts.touchingNow(sim.state, sim.workspace.bodies.contacts));
        found = true;
      }
      // The link's body, if it has a collision shape (one without never touches).
      const auto at = std::find(robot.link.begin(), robot.link.end(), p.link);
      const int body = at == robot.link.end() ? -1 : robot.first_body + static_cast<int>(at - robot.link.begin());
      std::vector<core::ContactPairReport> mine;
      for (const core::ContactPairReport& c : pairs) {
        if (c.body == body) mine.push_back(c);
        if (c.other == body) {  // seen from the link: the other side of the same pair
          core::ContactPairReport flipped = c;
          std::swap(flipped.body, flipped.other);
          flipped.normal_W = -c.normal_W;
          flipped.normal_force_W = -c.normal_force_W;
          flipped.friction_force_W = -c.friction_force_W;
          mine.push_back(flipped);
        }
      }
      std_msgs::Header header;
      header.stamp = stamp;
      header.frame_id = p.frame;
      if (!p.in_world) {  // into the frame fixed to the link
        if (!placed) {
          core::kinematics(robot.model, sim.robots[r], kin_);
          placed = true;
        }
        const core::LinkState F = core::frameState(core::linkStateOf(kin_, p.link), p.X_LS);
        const core::Quat q_FW = F.q_WL.conjugate();
        for (core::ContactPairReport& c : mine) {
          for (core::Vec3& q : c.points_W) q = q_FW * (q - F.p_WL);
          c.normal_W = q_FW * c.normal_W;
          c.normal_force_W = q_FW * c.normal_force_W;
          c.friction_force_W = q_FW * c.friction_force_W;
        }
      }
      p.contacts.publish(contactsMessage(sim.model(), mine, header));
    }
  }
}

}  // namespace rigid_body_sim::node
