// Loading a robot from URDF as an articulation: articulation_loader.h.
#include "rigid_body_sim/io/articulation_loader.h"

#include <urdf_model/model.h>

#include <algorithm>
#include <deque>
#include <filesystem>
#include <map>
#include <stdexcept>

#include "rigid_body_sim/io/input_bounds.h"
#include "urdf_lumper.h"

namespace rigid_body_sim::io {
namespace {

using core::ArticulatedLink;
using core::JointType;
using core::Vec3;

/// One lumped link: the group rooted at `link`.
ArticulatedLink lumpedLink(const detail::Lumper& lumper, const urdf::Link& link, bool is_world,
                           detail::LinkGroup& group) {
  lumper.collect(link, group, /*allow_moving=*/true, /*massless_root=*/is_world);
  ArticulatedLink out;
  out.name = link.name;
  out.mass = core::combine(group.parts);
  out.collision = std::move(group.shapes);
  out.fixed_links = std::move(group.frames);
  return out;
}

/// The joint's own fields: type, origin, axis, limits, dynamics.
void readJoint(const detail::Lumper& lumper, const detail::MovingJoint& moving, ArticulatedLink& link) {
  const urdf::Joint& joint = *moving.joint;
  const std::string where = "joint '" + joint.name + "'";
  link.joint = joint.name;
  link.X_PJ = moving.X_LJ;
  switch (joint.type) {
    case urdf::Joint::REVOLUTE:
      link.type = JointType::Revolute;
      break;
    case urdf::Joint::CONTINUOUS:
      link.type = JointType::Continuous;
      break;
    case urdf::Joint::PRISMATIC:
      link.type = JointType::Prismatic;
      break;
    default:
      lumper.fail(where + " is " + detail::jointTypeName(joint.type) +
                  ": a robot's joints may be revolute, continuous, prismatic or fixed");
  }
  const Vec3 axis(joint.axis.x, joint.axis.y, joint.axis.z);
  if (!axis.allFinite() || !(axis.norm() > 0.0)) {
    lumper.fail(where + ": <axis xyz> = (" + std::to_string(axis.x()) + ", " + std::to_string(axis.y()) + ", " +
                std::to_string(axis.z()) + "): must be finite and not zero");
  }
  link.axis_J = axis.normalized();
  if (joint.limits) {
    link.limits.effort = joint.limits->effort;
    link.limits.velocity = joint.limits->velocity;
    if (link.type != JointType::Continuous) {
      link.limits.lower = joint.limits->lower;
      link.limits.upper = joint.limits->upper;
    }
  }
  if (joint.dynamics) {
    link.damping = joint.dynamics->damping;
    link.friction = joint.dynamics->friction;
  }
  if (joint.mimic) {
    link.mimic.multiplier = joint.mimic->multiplier;
    link.mimic.offset = joint.mimic->offset;
  }
}

}  // namespace

core::ArticulationModel loadArticulationString(const std::string& xml, const std::string& source,
                                               const std::string& base_dir) {
  detail::Lumper lumper(source, base_dir);
  const urdf::ModelInterfaceSharedPtr urdf_model = lumper.parse(xml);
  const urdf::Link& root = *urdf_model->getRoot();
  core::ArticulationModel model;
  model.name = urdf_model->getName();
  model.fixed_base = root.name == "world";
  // Breadth first: a link's parent is always numbered before it.
  struct Pending {
    detail::MovingJoint joint;
    int parent;
  };
  std::deque<Pending> pending;
  std::map<std::string, std::string> mimics;  // joint -> the joint it follows
  const auto add = [&](ArticulatedLink link, detail::LinkGroup& group) {
    const int index = static_cast<int>(model.links.size());
    model.links.push_back(std::move(link));
    for (const detail::MovingJoint& moving : group.moving) pending.push_back({moving, index});
  };
  detail::LinkGroup base_group;
  add(lumpedLink(lumper, root, model.fixed_base, base_group), base_group);
  while (!pending.empty()) {
    const Pending next = pending.front();
    pending.pop_front();
    detail::LinkGroup group;
    ArticulatedLink link = lumpedLink(lumper, *next.joint.child, false, group);
    link.parent = next.parent;
    readJoint(lumper, next.joint, link);
    if (next.joint.joint->mimic) mimics[link.joint] = next.joint.joint->mimic->joint_name;
    add(std::move(link), group);
  }
  if (model.links.size() == 1) {
    lumper.fail("robot '" + model.name + "' has no revolute, continuous or prismatic joint: it is one body");
  }
  for (ArticulatedLink& link : model.links) {
    const auto mimic = mimics.find(link.joint);
    if (link.parent < 0 || mimic == mimics.end()) continue;
    for (std::size_t k = 1; k < model.links.size(); ++k) {
      if (model.links[k].joint == mimic->second) link.mimic.joint = static_cast<int>(k);
    }
    if (link.mimic.joint < 0) {
      lumper.fail("joint '" + link.joint + "' <mimic joint> = '" + mimic->second + "': no moving joint has that name");
    }
  }
  try {
    core::checkArticulation(model);
  } catch (const std::invalid_argument& e) {
    lumper.fail(e.what());
  }
  return model;
}

bool describesRobot(const std::string& xml, const std::string& source) {
  detail::Lumper lumper(source, "");
  const urdf::ModelInterfaceSharedPtr urdf = lumper.parse(xml);
  return std::any_of(urdf->joints_.begin(), urdf->joints_.end(),
                     [](const auto& joint) { return joint.second->type != urdf::Joint::FIXED; });
}

core::ArticulationModel loadArticulationFile(const std::string& path) {
  return loadArticulationString(readInput<UrdfError>(path, InputCaps::kUrdfBytes, "URDF"), path,
                                std::filesystem::path(path).parent_path().string());
}

}  // namespace rigid_body_sim::io
