// The links of a URDF gathered into rigid groups (private to io): a link
// and everything hanging from it by fixed joints is one group, its masses
// lumped (docs/physics.md §2) and its <collision> elements posed in the
// group's root link frame. Shared by the body loader (one group) and the
// articulation loader (a group per moving link).
#pragma once

#include <urdf_model/model.h>

#include <string>
#include <vector>

#include "rigid_body_sim/core/geometry.h"
#include "rigid_body_sim/core/inertia.h"
#include "rigid_body_sim/core/model.h"
#include "urdf_parse.h"

namespace rigid_body_sim::io::detail {

core::Pose toPose(const urdf::Pose& u);

/// "revolute", "fixed", ...: a joint type as the URDF spells it.
const char* jointTypeName(int type);

/// A movable joint met while gathering a group: where it hangs from.
struct MovingJoint {
  const urdf::Joint* joint = nullptr;
  const urdf::Link* child = nullptr;
  core::Pose X_LJ;  ///< the joint frame in the group's root link frame
};

/// One group: its parts' mass properties, shapes and fixed links, in the
/// frame of its root link L.
struct LinkGroup {
  std::vector<core::MassProperties> parts;
  std::vector<core::CollisionShape> shapes;
  std::vector<core::FixedLink> frames;
  std::vector<MovingJoint> moving;  ///< the movable joints leaving it, in URDF order
};

class Lumper {
 public:
  Lumper(std::string source, std::string base_dir) : source_(std::move(source)), base_dir_(std::move(base_dir)) {}

  /// urdfdom's model of `xml`, read through parseUrdf's guards after the
  /// text's size and shape are checked; refused with UrdfError. Remembers
  /// which collisions were capsules. Its root link is never null.
  urdf::ModelInterfaceSharedPtr parse(const std::string& xml);

  /// Throws UrdfError: the source, then `what`.
  [[noreturn]] void fail(const std::string& what) const;

  /// Mass properties of `link` in L, given the pose of the link in L.
  core::MassProperties part(const urdf::Link& link, const core::Pose& X_LK) const;

  /// The link's <collision> elements as shapes posed in L.
  void collisions(const urdf::Link& link, const core::Pose& X_LK, std::vector<core::CollisionShape>& out) const;

  /// Adds `root` and, through fixed joints, everything below it, depth first
  /// in URDF order (with a stack of its own, so a long chain of links cannot
  /// overflow the call stack). A movable joint is refused when
  /// `allow_moving` is false, else listed in group.moving. `massless_root`:
  /// the root needs no <inertial> (the world).
  void collect(const urdf::Link& root, LinkGroup& group, bool allow_moving, bool massless_root = false) const;

 private:
  std::string source_;
  std::string base_dir_;
  CapsuleSet capsules_;
};

}  // namespace rigid_body_sim::io::detail
