// What rviz draws: the scene and each body's collision shapes as
// visualization_msgs markers. Built once at start; the node latches them.
#pragma once

#include <visualization_msgs/MarkerArray.h>

#include <string>
#include <vector>

#include "rigid_body_sim/core/model.h"

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

}  // namespace rigid_body_sim::node
