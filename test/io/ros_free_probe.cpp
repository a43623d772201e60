// Compiled by the io_rejects_ros_headers test with the io library's include
// path: it must fail on the ROS header (see cmake/ros_free.cmake).
#include <ros/time.h>

#include "rigid_body_sim/io/world.h"
