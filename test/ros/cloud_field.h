// Reading a PointCloud2's field of point k by copying its bytes: the
// Velodyne layout's 22-byte points leave every other float unaligned, which
// sensor_msgs' PointCloud2Iterator reads by reference (undefined behaviour,
// flagged by UBSan), as PCL's own readers copy instead.
#pragma once

#include <sensor_msgs/PointCloud2.h>

#include <cstddef>
#include <cstring>
#include <stdexcept>
#include <string>

namespace rbs_test {

template <typename T>
T cloudField(const sensor_msgs::PointCloud2& cloud, std::size_t k, const std::string& name) {
  for (const sensor_msgs::PointField& f : cloud.fields) {
    if (f.name != name) continue;
    T value{};
    std::memcpy(&value, &cloud.data.at(k * cloud.point_step + f.offset), sizeof(T));
    return value;
  }
  throw std::invalid_argument("the cloud has no field '" + name + "'");
}

}  // namespace rbs_test
