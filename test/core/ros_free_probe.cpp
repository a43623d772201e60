// Compiled by the core_rejects_ros_headers test with the core's include
// path: it must fail on the ROS header (see cmake/ros_free.cmake).
#include <ros/time.h>

#include "rigid_body_sim/core/step/step.h"
