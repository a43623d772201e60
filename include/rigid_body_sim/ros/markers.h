// What rviz draws: the scene and each body's collision shapes as
// visualization_msgs markers, built by plain functions; MarkerPublisher
// keeps the two latched sets and edits them body by body.
#pragma once

#include <ros/ros.h>
#include <visualization_msgs/MarkerArray.h>

#include <optional>
#include <string>
#include <vector>

#include "rigid_body_sim/core/bodies/model.h"

namespace rigid_body_sim::node {

/// The scene in `world_frame`: planes as thin square slabs `scene_size` m
/// across, boxes, spheres and cylinders as rviz's own shapes (through
/// unions), any other shape or composition as its surface φ = 0 in triangles.
visualization_msgs::MarkerArray sceneMarkers(const std::vector<core::Sdf>& scene, const std::string& world_frame,
                                             double scene_size);

/// Each body's <collision> shapes in its tf frame `frames[i]`, frame_locked
/// so rviz moves them with tf: boxes, spheres and cylinders as themselves,
/// meshes as their triangles, a bare point cloud as points. Namespace: the
/// body's name; body i in colour `colours[i]` of a palette, in turn (the
/// order it entered the world in: a body keeps its colour when another leaves).
visualization_msgs::MarkerArray bodyMarkers(const core::Model& model, const std::vector<std::string>& frames,
                                            const std::vector<std::size_t>& colours);
/// `markers` without body `body`'s, after a DELETEALL (rviz forgets what it
/// drew, then draws those left).
void eraseBodyMarkers(const std::string& body, visualization_msgs::MarkerArray& markers);
/// One body's markers, as bodyMarkers() draws body i, after those in `markers`.
void appendBodyMarkers(const core::BodyModel& body, const std::string& frame, std::size_t colour,
                       visualization_msgs::MarkerArray& markers);

/// ~scene_markers and ~body_markers, latched: each set kept whole (a later
/// subscriber gets all of it) and sent again once a new subscriber has had
/// tf for a while (afterTf).
class MarkerPublisher {
 public:
  /// Advertises both topics on `pnh` and sends `scene` and `bodies`.
  MarkerPublisher(ros::NodeHandle& pnh, visualization_msgs::MarkerArray scene, visualization_msgs::MarkerArray bodies);
  MarkerPublisher(const MarkerPublisher&) = delete;  // the topics' callbacks hold `this`
  MarkerPublisher& operator=(const MarkerPublisher&) = delete;

  /// `body`, drawn in `frame` in `colour`, joins the body set, sent whole.
  void added(const core::BodyModel& body, const std::string& frame, std::size_t colour);
  /// The body named `name` leaves the set: rviz forgets every body marker
  /// and draws those left.
  void removed(const std::string& name);
  /// Call after each tf update: sends both sets again when due.
  void afterTf();

 private:
  ros::Publisher scene_pub_, body_pub_;
  visualization_msgs::MarkerArray scene_, bodies_;
  struct Resend {
    ros::WallTime connected;  ///< when a subscriber connected
    int updates = 0;          ///< tf updates since
  };
  std::optional<Resend> resend_;
};

}  // namespace rigid_body_sim::node
