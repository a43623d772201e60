// What a request addresses: a body by name, and the axes its vectors are
// given in (the world, the body's own frame, or another body's).
#include "rigid_body_sim/ros/sim_node.h"

namespace rigid_body_sim::node {

using core::Quat;

std::optional<int> SimNode::findBody(const std::string& name, std::string& error) const {
  if (model_.bodyCount() == 0) {
    error = "the world has no bodies (~spawn_body adds one)";
    return std::nullopt;
  }
  if (name.empty() && model_.bodyCount() == 1) return 0;
  if (const auto found = ports_.directory().byName(name)) return found;
  error = name.empty() ? "there are several bodies: give body (" + ports_.directory().names() + ")"
                       : "unknown body '" + name + "' (the bodies: " + ports_.directory().names() + ")";
  return std::nullopt;
}

std::optional<SimNode::Axes> SimNode::findFrame(const std::string& frame, int body, std::string& error) const {
  if (frame.empty() || frame == settings_.world_frame || frame == "world") return Axes{};
  if (frame == ports_[body].frame || frame == model_.body(body).link) return Axes{core::Frame::kBody, -1};
  if (const auto other = ports_.directory().byFrame(frame)) return Axes{core::Frame::kWorld, *other};
  error = "unknown frame '" + frame + "' (use '" + settings_.world_frame + "', the body's frame '" +
          ports_[body].frame + "'" + (ports_.size() > 1 ? " or another body's tf frame" : "") + ")";
  return std::nullopt;
}

std::optional<core::Pose> SimNode::findPose(const std::string& frame, std::string& error) const {
  if (frame.empty() || frame == settings_.world_frame || frame == "world") return core::Pose{};
  if (const auto body = ports_.directory().byFrame(frame)) {
    const core::LinkState link = core::linkState(model_.body(*body), state_.bodies[*body]);
    return core::Pose{link.q_WL, link.p_WL};
  }
  error = "frame: unknown frame '" + frame + "' (use '" + settings_.world_frame + "'" +
          (ports_.directory().size() == 0 ? "" : " or a body's tf frame" + ports_.directory().frames()) + ")";
  return std::nullopt;
}

core::Quat SimNode::orientationOf(const Axes& axes, int body) const {
  const int owner = axes.other >= 0 ? axes.other : axes.frame == core::Frame::kBody ? body : -1;
  if (owner < 0) return Quat::Identity();
  return core::linkState(model_.body(owner), state_.bodies[owner]).q_WL;
}

std::optional<SimNode::Target> SimNode::findTarget(const std::string& body_name, const std::string& frame_name,
                                                   std::string& error) const {
  const auto body = findBody(body_name, error);
  if (!body) return std::nullopt;
  const auto frame = findFrame(frame_name, *body, error);
  if (!frame) return std::nullopt;
  return Target{*body, *frame};
}

}  // namespace rigid_body_sim::node
