#include "rigid_body_sim/ros/addressing.h"

#include "rigid_body_sim/io/config.h"

namespace rigid_body_sim::node {

std::optional<int> Addressing::body(const std::string& name, std::string& error) const {
  const std::size_t n = sim_.freeBodyCount();
  if (n == 0) {
    error = "the world has no bodies (~spawn_body adds one)";
    return std::nullopt;
  }
  if (name.empty() && n == 1) return 0;
  const BodyDirectory& directory = ports_.directory();
  if (const auto found = directory.byName(name)) return found;
  error = name.empty() ? "there are several bodies: give body (" + directory.names() + ")"
                       : "unknown body '" + io::shownName(name) + "' (the bodies: " + directory.names() + ")";
  return std::nullopt;
}

std::optional<Axes> Addressing::axes(const std::string& frame, int body, std::string& error) const {
  if (isWorld(frame)) return Axes{};
  if (frame == ports_[body].frame || frame == sim_.model().body(body).link) return Axes{core::Frame::kBody, -1};
  if (const auto other = ports_.directory().byFrame(frame)) return Axes{core::Frame::kWorld, *other};
  error = "unknown frame '" + io::shownName(frame) + "' (use '" + world_frame_ + "', the body's frame '" +
          ports_[body].frame + "'" + (ports_.size() > 1 ? " or another body's tf frame" : "") + ")";
  return std::nullopt;
}

std::optional<Target> Addressing::target(const std::string& body_name, const std::string& frame_name,
                                         std::string& error) const {
  const auto found = body(body_name, error);
  if (!found) return std::nullopt;
  const auto frame = axes(frame_name, *found, error);
  if (!frame) return std::nullopt;
  return Target{*found, *frame};
}

std::optional<core::Pose> Addressing::pose(const std::string& frame, std::string& error) const {
  if (isWorld(frame)) return core::Pose{};
  if (const auto body = ports_.directory().byFrame(frame)) {
    const core::LinkState link = core::linkState(sim_.model().body(*body), sim_.state.bodies[*body]);
    return core::Pose{link.q_WL, link.p_WL};
  }
  error = "frame: unknown frame '" + io::shownName(frame) + "' (use '" + world_frame_ + "'" +
          (ports_.size() == 0 ? "" : " or a body's tf frame" + ports_.directory().frames()) + ")";
  return std::nullopt;
}

core::Quat Addressing::orientationOf(const Axes& axes, int body) const {
  const int owner = axes.other >= 0 ? axes.other : axes.frame == core::Frame::kBody ? body : -1;
  if (owner < 0) return core::Quat::Identity();
  return core::linkState(sim_.model().body(owner), sim_.state.bodies[owner]).q_WL;
}

const std::string& Addressing::frameOf(const Axes& axes, int body) const {
  if (axes.other >= 0) return ports_[axes.other].frame;
  return axes.frame == core::Frame::kBody ? ports_[body].frame : world_frame_;
}

}  // namespace rigid_body_sim::node
