// A load's one refusal and its notes (the repairs made, the markup nothing
// reads), each said once, for the lumper: urdf_lumper.h.
#include <algorithm>
#include <map>
#include <sstream>

#include "rigid_body_sim/core/bodies/ranges.h"
#include "rigid_body_sim/io/urdf_loader.h"
#include "urdf_lumper.h"

namespace rigid_body_sim::io::detail {

std::string maxFriction() {
  std::ostringstream os;
  os << core::ranges::kMaxFriction;
  return os.str();
}

namespace {

/// "a, b and c" of up to `most` names, then "and N more".
std::string nameList(const std::vector<std::string>& names, std::size_t most = 12) {
  std::string out;
  const std::size_t shown = std::min(names.size(), most);
  for (std::size_t i = 0; i < shown; ++i) {
    out += (i == 0 ? "" : (i + 1 == shown && shown == names.size() ? " and " : ", ")) + ("'" + names[i] + "'");
  }
  if (names.size() > shown) out += " and " + std::to_string(names.size() - shown) + " more";
  return out;
}

/// The items, "; " between them.
std::string joined(const std::vector<std::string>& items) {
  std::string out;
  for (std::size_t i = 0; i < items.size(); ++i) out += (i == 0 ? "" : "; ") + items[i];
  return out;
}

std::string count(std::size_t n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

}  // namespace

void Lumper::fail(const std::string& what) const {
  std::string all;
  for (const std::string& p : problems_) all += p + "; ";
  throw UrdfError(source_ + ": " + all + what);
}

void Lumper::finish() const {
  if (!problems_.empty()) {
    const std::string many = problems_.size() == 1 ? "" : std::to_string(problems_.size()) + " problems: ";
    throw UrdfError(source_ + ": " + many + joined(problems_));
  }
  if (options_.notes == nullptr) return;
  noteUnreadMarkup();
  if (!lifted_.empty() && options_.notes != nullptr) {
    options_.notes->push_back(source_ + ": gazebo_ros_control's robotSimType steer_bot_hardware_gazebo sets joints " +
                              "past their URDF limits, so the effort or speed limit 0 of " +
                              count(lifted_.size(), "joint is", "joints are") + " read as none (" + nameList(lifted_) +
                              ")");
  }
  if (repairs_.empty()) return;
  std::map<Repair, std::vector<std::string>> by_kind;
  for (const auto& [kind, what] : repairs_) {
    std::vector<std::string>& list = by_kind[kind];
    if (std::find(list.begin(), list.end(), what) == list.end()) list.push_back(what);
  }
  std::vector<std::string> parts;
  for (const auto& [kind, what] : by_kind) {
    const std::size_t n = what.size();
    switch (kind) {
      case Repair::kNoInertial:
        parts.push_back(
            count(n, "link without <inertial> is a massless frame", "links without <inertial> are massless frames") +
            " (" + nameList(what) + ")");
        break;
      case Repair::kMassZero:
        parts.push_back(count(n, "link of mass 0 is a massless frame", "links of mass 0 are massless frames") +
                        ", the inertia given dropped (" + nameList(what) + ")");
        break;
      case Repair::kInertia:
        parts.push_back(count(n, "inertia no body can have was", "inertias no body can have were") +
                        " replaced by the nearest valid one (principal moments, kg*m^2): " + joined(what));
        break;
      case Repair::kPointMass:
        parts.push_back(count(n, "link with mass but no inertia (a point mass) was",
                              "links with mass but no inertia (point masses) were") +
                        " given the inertia of a solid sphere of water of its mass: " + joined(what));
        break;
      case Repair::kShapeMass:
        parts.push_back(count(n, "moving link without mass was given the mass of its",
                              "moving links without mass were given the mass of their") +
                        " collision shapes filled with water, as MuJoCo's compiler does (" + joined(what) + ")");
        break;
      case Repair::kMimicDropped:
        parts.push_back(count(n, "<mimic> names", "<mimic>s name") + " no joint and " + (n == 1 ? "was" : "were") +
                        " dropped, the joint moving on its own (Gazebo classic ignores <mimic>): " + joined(what));
        break;
      case Repair::kHeld:
        parts.push_back(count(n, "joint moves", "joints move") + " only massless links and " + (n == 1 ? "is" : "are") +
                        " held where it starts, as if fixed, and still reported in joint_states (Gazebo drops such a "
                        "link, MuJoCo refuses it): " +
                        joined(what));
        break;
      case Repair::kEmptyCollision:
        parts.push_back(count(n, "<collision> of size 0 has", "<collision>s of size 0 have") + " no volume and " +
                        (n == 1 ? "was" : "were") + " dropped: " + joined(what));
        break;
      case Repair::kFixedBase:
        parts.push_back(what.front());
        break;
      case Repair::kPackageSlashes:
        parts.push_back(count(n, "mesh URI", "mesh URIs") + " with package:/// read as package:// (" +
                        nameList(what, 3) + ")");
        break;
      case Repair::kFrictionCapped:
        parts.push_back(count(n, "friction coefficient", "friction coefficients") + " of Gazebo markup above " +
                        maxFriction() + " (a Gazebo user's 'never slip') read as " + maxFriction() +
                        ", the largest here: " + joined(what));
        break;
    }
  }
  std::string message = source_ +
                        ": loaded with repairs, as Gazebo and KDL load it (urdf.repair: false refuses it "
                        "instead; docs/physics.md 2.1): ";
  for (std::size_t i = 0; i < parts.size(); ++i) message += (i == 0 ? "" : "; ") + parts[i];
  options_.notes->push_back(message);
}

void Lumper::noteUnreadMarkup() const {
  if (unread_markup_.empty()) return;
  std::vector<std::string> parts;
  for (const auto& [kind, names] : unread_markup_) parts.push_back(kind + " (" + nameList(names, 6) + ")");
  options_.notes->push_back(source_ +
                            ": markup for Gazebo that nothing here simulates, skipped (sensors, plugins, surface "
                            "and joint tuning, transmissions; a robot's controllers come from its controller "
                            "config; docs/physics.md 2.1): " +
                            joined(parts));
}

}  // namespace rigid_body_sim::io::detail
