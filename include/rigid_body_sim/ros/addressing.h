// What a request addresses: a body by name, the axes its vectors are given
// in (the world's, the body's own, or another body's, turning with it), and
// a frame's pose now. It reads the world as it is between steps; a deletion
// moves later bodies' indices, so an index is good until the next edit.
#pragma once

#include <optional>
#include <string>

#include "rigid_body_sim/core/step/simulation.h"
#include "rigid_body_sim/ros/body_ports.h"

namespace rigid_body_sim::node {

/// The axes a request's vectors are given in, for the body it addresses.
struct Axes {
  core::Frame frame = core::Frame::kWorld;  ///< kBody: the body's own root link, turning with it
  int other = -1;                           ///< ≥ 0: this other body's root link, turning with it
};

/// What a request addresses: a body, and the axes of its vectors.
struct Target {
  int body;
  Axes axes;
};

class Addressing {
 public:
  /// `world_frame` is the node's ~world_frame; "world" is always taken too.
  Addressing(const core::Simulation& sim, const PortRegistry& ports, const std::string& world_frame)
      : sim_(sim), ports_(ports), world_frame_(world_frame) {}

  /// The body named `name` ("" = the only body), or an error message.
  std::optional<int> body(const std::string& name, std::string& error) const;
  /// `frame` for `body`: "" or the world frame → world; the body's tf frame
  /// (or root link name) → its own axes; another body's tf frame → that
  /// body's axes; anything else is an error.
  std::optional<Axes> axes(const std::string& frame, int body, std::string& error) const;
  /// A body by name and the axes of its vectors (both as above).
  std::optional<Target> target(const std::string& body, const std::string& frame, std::string& error) const;
  /// The pose of `frame` ("" or the world frame: the identity, else a
  /// body's tf frame as it is now) in the world, or an error message.
  std::optional<core::Pose> pose(const std::string& frame, std::string& error) const;
  /// The orientation of `axes` now, for `body` (world: the identity).
  core::Quat orientationOf(const Axes& axes, int body) const;
  /// The frame that names `axes` for `body` in a message.
  const std::string& frameOf(const Axes& axes, int body) const;

 private:
  bool isWorld(const std::string& frame) const { return frame.empty() || frame == world_frame_ || frame == "world"; }

  const core::Simulation& sim_;
  const PortRegistry& ports_;
  const std::string& world_frame_;
};

}  // namespace rigid_body_sim::node
