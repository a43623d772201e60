// Loading a robot from URDF as an articulation: articulation_loader.h.
#include "rigid_body_sim/io/articulation_loader.h"

#include <urdf_model/model.h>

#include <algorithm>
#include <deque>
#include <filesystem>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>

#include "rigid_body_sim/core/articulations/articulation_dynamics.h"
#include "rigid_body_sim/io/input_bounds.h"
#include "urdf_lumper.h"

namespace rigid_body_sim::io {
namespace {

using core::ArticulatedLink;
using core::JointType;
using core::Vec3;

/// One lumped link: the group rooted at `link`.
ArticulatedLink lumpedLink(detail::Lumper& lumper, const urdf::Link& link, bool is_world, detail::LinkGroup& group) {
  lumper.collect(link, group, /*allow_moving=*/true, /*massless_root=*/is_world);
  ArticulatedLink out;
  out.name = link.name;
  out.mass = core::combine(group.parts);
  if (!is_world) lumper.inertiaForPointMass(link.name, out.mass);
  out.collision = std::move(group.shapes);
  out.fixed_links = std::move(group.frames);
  out.surface_friction = lumper.surfaceFriction(link.name);
  return out;
}

/// The joint's own fields: type, origin, axis, limits, dynamics.
void readJoint(detail::Lumper& lumper, const detail::MovingJoint& moving, ArticulatedLink& link) {
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
      lumper.problem(where + " is " + detail::jointTypeName(joint.type) +
                     ": a robot's joints may be revolute, continuous, prismatic or fixed");
  }
  const Vec3 axis(joint.axis.x, joint.axis.y, joint.axis.z);
  if (!axis.allFinite() || !(axis.norm() > 0.0)) {
    lumper.problem(where + ": <axis xyz> = (" + std::to_string(axis.x()) + ", " + std::to_string(axis.y()) + ", " +
                   std::to_string(axis.z()) + "): must be finite and not zero");
  } else {
    link.axis_J = axis.normalized();
  }
  if (joint.limits) {
    link.limits.effort = joint.limits->effort;
    link.limits.velocity = joint.limits->velocity;
    if (lumper.setsJointsPastLimits() && (link.limits.effort == 0.0 || link.limits.velocity == 0.0)) {
      const double none = std::numeric_limits<double>::infinity();
      if (link.limits.effort == 0.0) link.limits.effort = none;
      if (link.limits.velocity == 0.0) link.limits.velocity = none;
      lumper.liftedLimit(link.joint);
    }
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

/// The child link's frame in its parent's at joint position q.
core::Pose jointPose(const ArticulatedLink& link, double q) {
  const core::Placement X = core::jointPlacement(link, q);
  return {core::Quat(X.R_PC).normalized(), X.p_PC};
}

/// A moving link with no mass but collision shapes is given the mass of
/// its shapes filled with water (§2.1), as MuJoCo's compiler gives a body
/// without an inertial its geoms' at its default density; with repair off,
/// it stays massless.
void massFromShapes(core::ArticulationModel& model, detail::Lumper& lumper) {
  for (std::size_t i = 0; i < model.links.size(); ++i) {
    ArticulatedLink& link = model.links[i];
    if (i > 0 || !model.fixed_base) lumper.massFromShapes(link.name, link.collision, link.mass);
  }
}

/// Holds every moving link from which only massless links hang (§2.1): its
/// joint stays at its rest position (core::restPosition), and it and its collisions become fixed
/// links of the nearest link that still moves. With repair off, each is a
/// problem instead. Parent and mimic indices are renumbered.
void holdMassless(core::ArticulationModel& model, detail::Lumper& lumper) {
  const int n = static_cast<int>(model.links.size());
  std::vector<double> subtree(n);
  for (int i = 0; i < n; ++i) subtree[i] = model.links[i].mass.mass;
  for (int i = n - 1; i >= 1; --i) subtree[model.links[i].parent] += subtree[i];
  std::vector<int> kept_as(n, -1);  // a kept link's new index
  std::vector<int> holder(n, -1);   // a held link: the kept link it is fixed to
  std::vector<core::Pose> X_HL(n);  // a held link: its pose in its holder's frame
  std::vector<ArticulatedLink> links;
  for (int i = 0; i < n; ++i) {
    ArticulatedLink& link = model.links[i];
    if (i == 0 || subtree[i] > 0.0) {
      kept_as[i] = static_cast<int>(links.size());
      if (i > 0) link.parent = kept_as[link.parent];
      links.push_back(std::move(link));
      continue;
    }
    if (!lumper.repair()) {
      lumper.problem("joint '" + link.joint + "' moves only massless links (from '" + link.name +
                     "'): nothing to simulate (urdf.repair: true holds it where it starts)");
      continue;
    }
    const int p = link.parent;
    const bool parent_kept = kept_as[p] >= 0;
    holder[i] = parent_kept ? kept_as[p] : holder[p];
    const double q = core::restPosition(link);
    X_HL[i] = (parent_kept ? core::Pose{} : X_HL[p]) * jointPose(link, q);
    ArticulatedLink& to = links[holder[i]];
    const std::string parent_name = parent_kept ? links[kept_as[p]].name : model.links[p].name;
    to.fixed_links.push_back({link.name, parent_name, jointPose(link, q)});
    for (core::FixedLink& f : link.fixed_links) to.fixed_links.push_back(std::move(f));
    for (core::CollisionShape& shape : link.collision) {
      shape.X_LS = X_HL[i] * shape.X_LS;
      if (!shape.friction) shape.friction = link.surface_friction;  // the held link's own surface
      to.collision.push_back(std::move(shape));
    }
    model.held.push_back({link.joint, q});
    std::ostringstream text;
    text << "'" << link.joint << "' at " << q;
    lumper.repaired(detail::Repair::kHeld, text.str());
  }
  for (ArticulatedLink& link : links) {
    if (link.mimic.joint < 0) continue;
    const int leader = kept_as[link.mimic.joint];
    if (leader < 0) {
      lumper.problem("joint '" + link.joint + "' mimics joint '" + model.links[link.mimic.joint].joint +
                     "', which moves only massless links and is held");
    }
    link.mimic.joint = leader;
  }
  model.links = std::move(links);
}

/// The message for the joints whose zero lies outside their limits, which
/// start at the nearest limit (core::restPosition), or "".
std::string limitStartNote(const core::ArticulationModel& model, const std::string& source) {
  std::ostringstream list;
  list.precision(6);
  int count = 0;
  for (std::size_t i = 1; i < model.links.size(); ++i) {
    const ArticulatedLink& link = model.links[i];
    const double q = core::restPosition(link);
    if (q == 0.0 || link.mimic.joint > 0) continue;
    list << (count++ == 0 ? "" : "; ") << "'" << link.joint << "' 0 -> " << q << " (limits [" << link.limits.lower
         << ", " << link.limits.upper << "])";
  }
  if (count == 0) return "";
  return source + ": " + std::to_string(count) + (count == 1 ? " joint has its" : " joints have their") +
         " zero outside the limits and start" + (count == 1 ? "s" : "") +
         " at the nearest limit instead, unless the start sets them (Gazebo snaps them there on the first step): " +
         list.str();
}

}  // namespace

core::ArticulationModel loadArticulationString(const std::string& xml, const std::string& source,
                                               const std::string& base_dir, const UrdfOptions& options) {
  detail::Lumper lumper(source, base_dir, options);
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
  for (ArticulatedLink& link : model.links) {
    const auto mimic = mimics.find(link.joint);
    if (link.parent < 0 || mimic == mimics.end()) continue;
    for (std::size_t k = 1; k < model.links.size(); ++k) {
      if (model.links[k].joint == mimic->second) link.mimic.joint = static_cast<int>(k);
    }
    if (link.mimic.joint >= 0) continue;
    if (lumper.repair()) {
      link.mimic = {};
      lumper.repaired(detail::Repair::kMimicDropped, "'" + link.joint + "' -> '" + mimic->second + "'");
    } else {
      lumper.problem("joint '" + link.joint + "' <mimic joint> = '" + mimic->second +
                     "': no moving joint has that name (urdf.repair: true drops the <mimic>)");
    }
  }
  massFromShapes(model, lumper);
  holdMassless(model, lumper);
  // A floating base with no mass lumped into it cannot float (its joints
  // would turn it for nothing): Bullet reads a base of mass 0 as fixed, and
  // so does the loader, where the start puts it.
  if (!model.fixed_base && model.links[0].mass.mass == 0.0) {
    if (lumper.repair()) {
      model.fixed_base = true;
      lumper.repaired(detail::Repair::kFixedBase, "the base '" + model.links[0].name +
                                                      "' has no mass and is fixed to the world where the start puts "
                                                      "it, as Bullet reads a base of mass 0");
    } else {
      lumper.problem("the base '" + model.links[0].name +
                     "' has no mass: a floating base needs one (urdf.repair: true fixes it to the world)");
    }
  }
  if (model.links.size() == 1) {
    lumper.problem(!model.held.empty() && model.links[0].mass.mass == 0.0 && model.links[0].collision.empty()
                       ? "robot '" + model.name +
                             "' has no mass anywhere and no <collision> to give it one: a drawing, nothing to simulate"
                       : "robot '" + model.name +
                             "' has no revolute, continuous or prismatic joint that moves a mass: it is one body");
  }
  lumper.finish();
  try {
    core::checkArticulation(model);
  } catch (const std::invalid_argument& e) {
    lumper.fail(e.what());
  }
  if (const std::string note = limitStartNote(model, source); !note.empty() && options.notes != nullptr) {
    options.notes->push_back(note);
  }
  return model;
}

bool describesRobot(const std::string& xml, const std::string& source) {
  detail::Lumper lumper(source, "");
  const urdf::ModelInterfaceSharedPtr urdf = lumper.parse(xml);
  return std::any_of(urdf->joints_.begin(), urdf->joints_.end(),
                     [](const auto& joint) { return joint.second->type != urdf::Joint::FIXED; });
}

core::ArticulationModel loadArticulationFile(const std::string& path, const UrdfOptions& options) {
  return loadArticulationString(readInput<UrdfError>(path, InputCaps::kUrdfBytes, "URDF"), path,
                                std::filesystem::path(path).parent_path().string(), options);
}

}  // namespace rigid_body_sim::io
