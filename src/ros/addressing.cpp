// What a request addresses: a body by name, and the axes its vectors are
// given in (the world, the body's own frame, or another body's).
#include "rigid_body_sim/ros/sim_node.h"

namespace rigid_body_sim::node {

using core::Quat;

std::optional<int> SimNode::findBody(const std::string& name, std::string& error) const {
  if (name.empty() && model_.bodyCount() == 1) return 0;
  std::string names;
  for (std::size_t i = 0; i < model_.bodyCount(); ++i) {
    if (model_.body(i).name == name) return static_cast<int>(i);
    names += (i ? ", '" : "'") + model_.body(i).name + "'";
  }
  error = name.empty() ? "there are several bodies: give body (" + names + ")"
                       : "unknown body '" + name + "' (the bodies: " + names + ")";
  return std::nullopt;
}

std::optional<SimNode::Axes> SimNode::findFrame(const std::string& frame, int body, std::string& error) const {
  if (frame.empty() || frame == settings_.world_frame || frame == "world") return Axes{};
  if (frame == frames_[body] || frame == model_.body(body).link) return Axes{core::Frame::kBody, -1};
  for (std::size_t i = 0; i < frames_.size(); ++i) {
    if (frame == frames_[i]) return Axes{core::Frame::kWorld, static_cast<int>(i)};
  }
  error = "unknown frame '" + frame + "' (use '" + settings_.world_frame + "', the body's frame '" + frames_[body] +
          "'" + (frames_.size() > 1 ? " or another body's tf frame" : "") + ")";
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
