// The links of a URDF gathered into rigid groups (private to io): a link
// and everything hanging from it by fixed joints is one group, its masses
// lumped (docs/physics.md §2) and its <collision> elements posed in the
// group's root link frame. Shared by the body loader (one group) and the
// articulation loader (a group per moving link). It keeps what a load
// repaired (§2.1) and every problem it met, so a URDF's problems are all
// reported in one refusal and its repairs in one message.
#pragma once

#include <urdf_model/model.h>

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "rigid_body_sim/core/bodies/geometry.h"
#include "rigid_body_sim/core/bodies/inertia.h"
#include "rigid_body_sim/core/bodies/model.h"
#include "rigid_body_sim/io/urdf_loader.h"
#include "urdf_parse.h"

namespace rigid_body_sim::io::detail {

core::Pose toPose(const urdf::Pose& u);

/// "revolute", "fixed", ...: a joint type as the URDF spells it.
const char* jointTypeName(int type);

/// The largest friction coefficient, as text ("10"): urdf_load_notes.cpp.
std::string maxFriction();

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

/// What a load repaired, by kind, for the one message it gives.
enum class Repair {
  kNoInertial,      ///< a link without <inertial>: a massless frame (the link's name)
  kMassZero,        ///< mass 0 with an inertia: a massless frame (the link's name)
  kInertia,         ///< an inertia replaced by the nearest valid one (the link and the figures)
  kPointMass,       ///< mass without inertia, given a water sphere's (the link and the figures)
  kShapeMass,       ///< a moving link without mass, given its collision shapes' full of water (the link, the mass)
  kHeld,            ///< a moving joint that moves only massless links, held (the joint and where)
  kMimicDropped,    ///< a <mimic> of no joint, dropped (the joint and the name it gave)
  kEmptyCollision,  ///< a <collision> of size 0, dropped (the link, index and field)
  kFixedBase,       ///< a floating base without mass, fixed to the world (the whole sentence)
  kPackageSlashes,  ///< package:///NAME read as package://NAME (the URI)
  kFrictionCapped  ///< a <gazebo reference><mu1> or <mu2> above the largest friction, read as it (the link, tag, value)
};

class Lumper {
 public:
  Lumper(std::string source, std::string base_dir, UrdfOptions options = {})
      : source_(std::move(source)), base_dir_(std::move(base_dir)), options_(options) {}

  /// urdfdom's model of `xml`, read through parseUrdf's guards after the
  /// text's size and shape are checked; refused with UrdfError. Remembers
  /// which collisions were capsules. Its root link is never null.
  urdf::ModelInterfaceSharedPtr parse(const std::string& xml);

  /// The friction coefficient `link`'s Gazebo markup gives its surfaces
  /// (`<gazebo reference="LINK"><mu1>`), if any (after parse()).
  std::optional<double> surfaceFriction(const std::string& link) const {
    const auto it = surface_friction_.find(link);
    return it == surface_friction_.end() ? std::nullopt : std::optional<double>(it->second);
  }

  /// Throws UrdfError: the source, then `what`, after the problems met so far.
  [[noreturn]] void fail(const std::string& what) const;

  /// A problem that refuses the URDF but lets the reading go on, so that
  /// finish() names all of them at once.
  void problem(const std::string& what) { problems_.push_back(what); }

  /// A repair the load made (only with options.repair), said by finish().
  void repaired(Repair kind, const std::string& what) { repairs_.push_back({kind, what}); }

  bool repair() const { return options_.repair; }

  /// Whether the robot's gazebo_ros_control runs steer_bot_hardware_gazebo
  /// (after parse()), which sets joints past their URDF limits: a joint's
  /// effort or speed limit of 0 is then read as none, each one so read
  /// named by finish() (liftedLimit).
  bool setsJointsPastLimits() const { return sets_past_limits_; }
  void liftedLimit(const std::string& joint) { lifted_.push_back(joint); }

  /// Throws UrdfError naming every problem, if there was one; else hands
  /// the repairs, as one message, to options.notes.
  void finish() const;

  /// Mass properties of `link` in L, given the pose of the link in L. A
  /// link without <inertial>, or of mass 0, is a massless frame (mass 0,
  /// no inertia) when repairing; an inertia no body can have is replaced by
  /// the nearest valid one (core::nearestValidInertia).
  core::MassProperties part(const urdf::Link& link, const core::Pose& X_LK);

  /// A rigid group `name` with mass but no inertia at all (a point mass,
  /// which a moving rigid body cannot be) is given a water sphere's
  /// (core::waterSphereInertia), when repairing.
  void inertiaForPointMass(const std::string& name, core::MassProperties& mass);

  /// A rigid group `name` without mass but with `shapes` is given their
  /// mass filled with water (core::shapesMassProperties), when repairing.
  void massFromShapes(const std::string& name, const std::vector<core::CollisionShape>& shapes,
                      core::MassProperties& mass);

  /// The link's <collision> elements as shapes posed in L.
  void collisions(const urdf::Link& link, const core::Pose& X_LK, std::vector<core::CollisionShape>& out);

  /// Adds `root` and, through fixed joints, everything below it, depth first
  /// in URDF order (with a stack of its own, so a long chain of links cannot
  /// overflow the call stack). A movable joint is refused when
  /// `allow_moving` is false, else listed in group.moving. `massless_root`:
  /// the root needs no <inertial> (the world).
  void collect(const urdf::Link& root, LinkGroup& group, bool allow_moving, bool massless_root = false);

 private:
  /// One note naming the markup nothing here reads (unread_markup_;
  /// urdf_load_notes.cpp, with fail() and finish()).
  void noteUnreadMarkup() const;
  /// Drops the Gazebo markup's drives on a joint the URDF fixes or lacks,
  /// said as unread markup (Gazebo's plugin fails to load on them).
  void dropStillDrives(const urdf::ModelInterface& urdf, std::vector<ControllerEntry>& controllers);

  std::string source_;
  std::string base_dir_;
  UrdfOptions options_;
  CapsuleSet capsules_;
  std::map<std::string, double> surface_friction_;
  std::map<std::string, std::vector<std::string>> unread_markup_;  ///< ParsedUrdf's
  std::vector<std::string> problems_;
  std::vector<std::pair<Repair, std::string>> repairs_;
  bool sets_past_limits_ = false;
  std::vector<std::string> lifted_;  ///< the joints whose 0 limits were read as none
};

}  // namespace rigid_body_sim::io::detail
