// Gathering a URDF's links into rigid groups: urdf_lumper.h (its refusal and
// notes: urdf_load_notes.cpp).
#include "urdf_lumper.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "gazebo_plugins.h"
#include "rigid_body_sim/core/bodies/ranges.h"
#include "rigid_body_sim/core/bodies/shape_mass.h"
#include "rigid_body_sim/io/input_bounds.h"
#include "rigid_body_sim/io/mesh_loader.h"
#include "rigid_body_sim/io/orientation.h"
#include "rigid_body_sim/io/urdf_loader.h"

namespace rigid_body_sim::io::detail {

using core::Mat3;
using core::Pose;
using core::Vec3;

core::Pose toPose(const urdf::Pose& u) {
  return {quaternionFromXyzw(u.rotation.x, u.rotation.y, u.rotation.z, u.rotation.w).normalized(),
          Vec3(u.position.x, u.position.y, u.position.z)};
}

const char* jointTypeName(int type) {
  switch (type) {
    case urdf::Joint::REVOLUTE:
      return "revolute";
    case urdf::Joint::CONTINUOUS:
      return "continuous";
    case urdf::Joint::PRISMATIC:
      return "prismatic";
    case urdf::Joint::FLOATING:
      return "floating";
    case urdf::Joint::PLANAR:
      return "planar";
    case urdf::Joint::FIXED:
      return "fixed";
    default:
      return "unknown";
  }
}

urdf::ModelInterfaceSharedPtr Lumper::parse(const std::string& xml) {
  if (xml.size() > InputCaps::kUrdfBytes) {
    fail("the URDF text is " + std::to_string(xml.size()) + " bytes, more than the " +
         std::to_string(InputCaps::kUrdfBytes) + " a URDF may have");
  }
  const std::string problem = xmlProblem(xml);
  if (!problem.empty()) fail("refused before parsing: " + problem);
  ParsedUrdf parsed;
  try {
    parsed = parseUrdf(xml);
  } catch (const std::invalid_argument& e) {
    fail(e.what());
  }
  capsules_ = std::move(parsed.capsules);
  surface_friction_ = std::move(parsed.surface_friction);
  unread_markup_ = std::move(parsed.unread_markup);
  sets_past_limits_ = parsed.sensors.robot_sim_type == kSteerBotSimType;
  if (options_.sensors != nullptr) {
    *options_.sensors = std::move(parsed.sensors);
    dropStillDrives(*parsed.model, options_.sensors->controllers);
  } else {  // a body's, or a load that runs no sensors
    for (auto& [kind, names] : parsed.sensor_markup) {
      std::vector<std::string>& all = unread_markup_[kind];
      all.insert(all.end(), names.begin(), names.end());
    }
  }
  for (const std::string& above : parsed.friction_above) {
    if (repair()) {
      repaired(Repair::kFrictionCapped, above);
    } else {
      this->problem(above + " is above " + maxFriction() +
                    ", the largest friction coefficient (urdf.repair: true reads it as that)");
    }
  }
  if (!parsed.model->getRoot()) fail("no root link");
  return std::move(parsed.model);
}

void Lumper::dropStillDrives(const urdf::ModelInterface& urdf, std::vector<ControllerEntry>& controllers) {
  const auto moves = [&urdf](const std::string& joint) {
    const urdf::JointConstSharedPtr j = urdf.getJoint(joint);
    return j && j->type != urdf::Joint::FIXED;
  };
  // gazebo_ros_diff_drive on a wheel the URDF fixes (MATLAB's and Adept's
  // pioneer3dx): Gazebo lumps the joint away and the plugin fails to load,
  // the robot runs without it; so here, said.
  const auto still = [&](const ControllerEntry& c) {
    if (!c.drive || c.key.rfind("<gazebo>", 0) != 0) return false;  // the config's are refused, naming the key
    if (std::all_of(c.joints.begin(), c.joints.end(), moves)) return false;
    unread_markup_
        ["<plugin> drive (gazebo_ros_diff_drive, gazebo_ros_skid_steer_drive) on a joint that is missing "
         "or does not move (Gazebo does not run it)"]
            .push_back(c.name);
    return true;
  };
  controllers.erase(std::remove_if(controllers.begin(), controllers.end(), still), controllers.end());
}

core::MassProperties Lumper::part(const urdf::Link& link, const Pose& X_LK) {
  const std::string where = "link '" + link.name + "'";
  if (!link.inertial) {
    if (repair()) {
      repaired(Repair::kNoInertial, link.name);
    } else {
      problem(where +
              " has no <inertial>: every link of the body needs a mass and an inertia (urdf.repair: true reads it "
              "as a massless frame)");
    }
    return {};
  }
  const urdf::Inertial& in = *link.inertial;
  if (!std::isfinite(in.mass) || in.mass < 0.0) {
    std::ostringstream value;
    value << in.mass;
    problem(where + ": <mass value> = " + value.str() + ": must be finite and >= 0 kg");
    return {};
  }
  Mat3 I;
  I << in.ixx, in.ixy, in.ixz,  //
      in.ixy, in.iyy, in.iyz,   //
      in.ixz, in.iyz, in.izz;
  if (in.mass == 0.0) {
    if (!I.allFinite() || I.isZero(0.0)) {
      if (!I.allFinite()) problem(where + ": <inertia> must be finite");
      return {};
    }
    if (!repair()) {
      problem(where + ": mass is 0 kg but <inertia> is not zero (urdf.repair: true reads it as a massless frame)");
    } else {
      repaired(Repair::kMassZero, link.name);
    }
    return {};
  }
  if (repair() && core::pointMass(in.mass, I)) {
    I.setZero();  // rounding around nothing: a point mass, as inertiaForPointMass reads it
  } else if (repair()) {
    try {
      // No repaired moment below 1e-6 of the largest: a link a body can be.
      const core::InertiaRepair fix = core::nearestValidInertia(I, "<inertia>", 1e-6);
      if (fix.changed) {
        std::ostringstream text;
        text.precision(3);
        const double largest = fix.moments.cwiseAbs().maxCoeff();
        text << "'" << link.name << "' [" << fix.moments(0) << ", " << fix.moments(1) << ", " << fix.moments(2)
             << "] -> [" << fix.repaired(0) << ", " << fix.repaired(1) << ", " << fix.repaired(2) << "], changed by "
             << fix.change << " (" << 100.0 * fix.change / largest << "% of the largest)";
        repaired(Repair::kInertia, text.str());
        I = fix.I;
      }
    } catch (const std::invalid_argument& e) {
      problem(where + ": " + e.what());
      return {};
    }
  } else {
    try {
      core::validateInertia(I, "<inertia>", /*allow_zero=*/true);
    } catch (const std::invalid_argument& e) {
      problem(where + ": " + e.what() + " (urdf.repair: true replaces it by the nearest valid one)");
      return {};
    }
  }
  // <inertial><origin> places the centre of mass and the inertia axes.
  const Pose X_LI = X_LK * toPose(in.origin);
  const Mat3 R = X_LI.rotation.toRotationMatrix();
  return {in.mass, X_LI.translation, R * I * R.transpose()};
}

void Lumper::inertiaForPointMass(const std::string& name, core::MassProperties& mass) {
  if (!repair() || !core::pointMass(mass.mass, mass.I_C_F)) return;
  mass.I_C_F = core::waterSphereInertia(mass.mass);
  std::ostringstream text;
  text.precision(3);
  text << "'" << name << "' " << mass.mass << " kg: " << mass.I_C_F(0, 0) << " kg*m^2 about each axis";
  repaired(Repair::kPointMass, text.str());
}

void Lumper::massFromShapes(const std::string& name, const std::vector<core::CollisionShape>& shapes,
                            core::MassProperties& mass) {
  if (!repair() || mass.mass != 0.0 || shapes.empty()) return;
  mass = core::shapesMassProperties(shapes, core::kWaterDensity);
  std::ostringstream text;
  text.precision(3);
  text << "'" << name << "' " << mass.mass << " kg";
  repaired(Repair::kShapeMass, text.str());
}

void Lumper::collisions(const urdf::Link& link, const Pose& X_LK, std::vector<core::CollisionShape>& out) {
  for (std::size_t i = 0; i < link.collision_array.size(); ++i) {
    const urdf::Collision& col = *link.collision_array[i];
    const std::string where = "link '" + link.name + "' <collision> " + std::to_string(i);
    if (!col.geometry) {
      problem(where + " has no <geometry>");
      continue;
    }
    core::CollisionShape shape;
    shape.X_LS = X_LK * toPose(col.origin);
    shape.name = where;
    bool ok = true;
    auto positive = [&](double x, const std::string& field) {
      if (!ok) return;
      if (x == 0.0 && repair()) {  // a placeholder: no volume, nothing to touch
        repaired(Repair::kEmptyCollision,
                 "'" + link.name + "' <collision> " + std::to_string(i) + " (" + field + " 0)");
        ok = false;
      } else if (!std::isfinite(x) || !(x > 0.0)) {
        std::ostringstream value;
        value << x;
        problem(where + ": " + field + " = " + value.str() + ": must be finite and > 0 m" +
                (x == 0.0 ? " (urdf.repair: true drops such a <collision>)" : ""));
        ok = false;
      }
    };
    switch (col.geometry->type) {
      case urdf::Geometry::BOX: {
        const auto& box = static_cast<const urdf::Box&>(*col.geometry);
        shape.kind = core::CollisionShape::Kind::kBox;
        shape.size = Vec3(box.dim.x, box.dim.y, box.dim.z);
        positive(box.dim.x, "box size x");
        positive(box.dim.y, "box size y");
        positive(box.dim.z, "box size z");
        break;
      }
      case urdf::Geometry::SPHERE: {
        const auto& sphere = static_cast<const urdf::Sphere&>(*col.geometry);
        shape.kind = core::CollisionShape::Kind::kSphere;
        shape.radius = sphere.radius;
        positive(sphere.radius, "sphere radius");
        break;
      }
      case urdf::Geometry::CYLINDER: {
        const auto& cyl = static_cast<const urdf::Cylinder&>(*col.geometry);
        const bool capsule = capsules_.count({link.name, i}) > 0;
        shape.kind = capsule ? core::CollisionShape::Kind::kCapsule : core::CollisionShape::Kind::kCylinder;
        shape.radius = cyl.radius;
        shape.length = cyl.length;
        positive(cyl.radius, capsule ? "capsule radius" : "cylinder radius");
        positive(cyl.length, capsule ? "capsule length" : "cylinder length");
        break;
      }
      case urdf::Geometry::MESH: {
        const auto& mesh = static_cast<const urdf::Mesh&>(*col.geometry);
        shape.kind = core::CollisionShape::Kind::kPoints;
        const Vec3 scale(mesh.scale.x, mesh.scale.y, mesh.scale.z);
        if (!scale.allFinite() || (scale.array() == 0.0).any()) {
          problem(where + ": mesh scale must be finite and non-zero");
          ok = false;
          break;
        }
        std::string uri = mesh.filename;
        const std::string slashes = "package:///";
        if (const std::size_t name = uri.find_first_not_of('/', slashes.size());
            repair() && uri.rfind(slashes, 0) == 0 && name != std::string::npos) {
          repaired(Repair::kPackageSlashes, uri);
          uri = "package://" + uri.substr(name);
        }
        try {
          shape.mesh = loadMesh(resolveMeshUri(uri, base_dir_), scale);
        } catch (const MeshError& e) {
          problem(where + ": " + e.what());
          ok = false;
        }
        shape.name += " (" + mesh.filename + ")";
        break;
      }
      default:
        problem(where + ": unsupported geometry type");
        ok = false;
    }
    if (ok) out.push_back(std::move(shape));
  }
}

void Lumper::collect(const urdf::Link& root, LinkGroup& group, bool allow_moving, bool massless_root) {
  std::vector<std::pair<const urdf::Link*, Pose>> todo{{&root, Pose{}}};
  while (!todo.empty()) {
    const auto [link, X_LK] = todo.back();
    todo.pop_back();
    if (!(massless_root && link == &root)) group.parts.push_back(part(*link, X_LK));
    const std::size_t first_shape = group.shapes.size();
    collisions(*link, X_LK, group.shapes);
    // A link lumped in keeps its own surface on its shapes (Gazebo's
    // <gazebo reference> is per link); the root's is the body's.
    if (link != &root) {
      const std::optional<double> own = surfaceFriction(link->name);
      for (std::size_t s = first_shape; s < group.shapes.size(); ++s) group.shapes[s].friction = own;
    }
    const std::size_t first_child = todo.size();
    for (const auto& joint : link->child_joints) {
      const auto child = std::find_if(link->child_links.begin(), link->child_links.end(),
                                      [&](const auto& l) { return l->name == joint->child_link_name; });
      if (child == link->child_links.end()) fail("joint '" + joint->name + "' has no child link");
      const Pose X_KC = toPose(joint->parent_to_joint_origin_transform);
      if (joint->type != urdf::Joint::FIXED) {
        if (!allow_moving) {
          fail(std::string("joint '") + joint->name + "' is " + jointTypeName(joint->type) +
               ": only fixed joints are supported in a body");
        }
        group.moving.push_back({joint.get(), child->get(), X_LK * X_KC});
        continue;
      }
      todo.push_back({child->get(), X_LK * X_KC});
      group.frames.push_back({(*child)->name, link->name, X_KC});
    }
    // Children come off the stack in URDF order.
    std::reverse(todo.begin() + static_cast<std::ptrdiff_t>(first_child), todo.end());
  }
}

}  // namespace rigid_body_sim::io::detail
