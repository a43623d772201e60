#include "rigid_body_sim/io/urdf_loader.h"

#include <urdf_model/model.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>
#include <sstream>
#include <vector>

#include "rigid_body_sim/core/bodies/inertia.h"
#include "rigid_body_sim/io/input_bounds.h"
#include "rigid_body_sim/io/mesh_loader.h"
#include "rigid_body_sim/io/orientation.h"
#include "urdf_lumper.h"
#include "urdf_parse.h"

namespace rigid_body_sim::io {

using detail::Lumper;

core::BodySpec loadUrdfString(const std::string& xml, const std::string& source, const std::string& base_dir,
                              const UrdfOptions& options) {
  Lumper lumper(source, base_dir, options);
  const urdf::ModelInterfaceSharedPtr model = lumper.parse(xml);
  const urdf::LinkConstSharedPtr root = model->getRoot();
  // A robot is not a body: said first, whatever else its links lack (a
  // `world` root has no <inertial>).
  for (const auto& [name, joint] : model->joints_) {
    if (joint->type != urdf::Joint::FIXED) {
      lumper.fail("joint '" + name + "' is " + detail::jointTypeName(joint->type) +
                  ": only fixed joints are supported in a body; a URDF with moving joints is a robot, which rbsim "
                  "and the node run (rbsim --urdf ROBOT.urdf, the node's robot_description, or among a config's "
                  "bodies) and ~spawn_body does not take yet");
    }
  }

  detail::LinkGroup group;
  lumper.collect(*root, group, /*allow_moving=*/false);
  core::MassProperties total = core::combine(group.parts);
  lumper.massFromShapes(root->name, group.shapes, total);  // no mass anywhere but shapes: theirs
  lumper.inertiaForPointMass(root->name, total);
  if (!(total.mass > 0.0)) lumper.problem("the body rooted at link '" + root->name + "' has a total mass of 0 kg");
  lumper.finish();
  core::BodySpec spec;
  spec.name = root->name;
  spec.link = root->name;
  spec.mass = total.mass;
  spec.p_LC = total.p_FC;
  spec.I_C_L = total.I_C_F;
  spec.collision = std::move(group.shapes);
  spec.fixed_links = std::move(group.frames);
  // Its surface: the root link's <gazebo reference> <mu1>/<mu2>, as a
  // robot link's (a config entry's or a spawn's own friction wins over it).
  spec.friction = lumper.surfaceFriction(root->name);
  return spec;
}

core::BodySpec loadUrdfFile(const std::string& path, const UrdfOptions& options) {
  return loadUrdfString(readInput<UrdfError>(path, InputCaps::kUrdfBytes, "URDF"), path,
                        std::filesystem::path(path).parent_path().string(), options);
}

}  // namespace rigid_body_sim::io
