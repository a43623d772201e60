// What a range sensor costs (bench/README.md, "Range sensors"): rays per
// second of core::castRay on one core, against one plane (the ceiling: the
// cheapest distance function) and in a world of 100 boxes and the shipped
// wheeled robot on the ground inside four walls, for the three sensors of
// issue 46 mounted on the robot: a 360-beam lidar, a 16 x 1,800-beam lidar
// and a 320 x 240 depth camera (60 degrees across). Each is timed over
// interleaved rounds; the median round is printed, with the share of one
// core each sensor takes at its rate (10, 10 and 30 Hz). "world" casts each
// ray against every body's bounding sphere; "sensor" is the sensor's own
// scan (core::Lidar::scan, core::DepthCamera::capture), which culls the
// bodies once per group of 16 beams or tile of 16 x 16 pixels: the same
// ranges (core_ray_cast_test), timed in the same rounds.
// Usage: ray_bench [ROUNDS]   (Release build)
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "median.h"
#include "rigid_body_sim/core/devices/depth_camera.h"
#include "rigid_body_sim/core/devices/lidar.h"
#include "rigid_body_sim/io/scene_loader.h"

namespace core = rigid_body_sim::core;
namespace io = rigid_body_sim::io;

namespace {

using rigid_body_sim::bench::median;

struct Sensor {
  const char* name;
  double rate;                   // Hz
  std::vector<core::Vec3> rays;  // unit, in the sensor frame (x forward, z up)
  /// Seconds of the sensor's own scan from X_WS (a checksum added to `sum`).
  using Scan = std::function<double(const core::Model&, const core::State&, const core::Pose&, const std::vector<char>&,
                                    double&)>;
  Scan scan;
};

core::LidarSettings lidarSettings(int samples, int fans, double low, double high) {
  core::LidarSettings s;
  s.samples = samples;
  s.vertical_samples = fans;
  s.vertical_min_angle = low;
  s.vertical_max_angle = high;
  s.max_range = 30.0;
  return s;
}

std::vector<core::Vec3> lidarRays(const core::LidarSettings& s) {
  const core::Lidar lidar(s);
  std::vector<core::Vec3> rays;
  for (std::size_t k = 0; k < lidar.rayCount(); ++k) rays.push_back(lidar.direction(k));
  return rays;
}

/// A pinhole camera's rays, w x h pixels, `hfov` rad across, looking along x.
std::vector<core::Vec3> cameraRays(int w, int h, double hfov) {
  const double f = 0.5 * w / std::tan(0.5 * hfov);
  std::vector<core::Vec3> rays;
  for (int v = 0; v < h; ++v) {
    for (int u = 0; u < w; ++u) rays.push_back(core::Vec3(f, 0.5 * w - u - 0.5, 0.5 * h - v - 0.5).normalized());
  }
  return rays;
}

/// Seconds to cast every ray of `rays` from X_WS.
double castAll(const core::Model& model, const core::State& state, const core::Pose& X_WS,
               const std::vector<core::Vec3>& rays, const std::vector<char>& skip, double& sum) {
  const core::Mat3 R = X_WS.rotation.toRotationMatrix();
  const auto t0 = std::chrono::steady_clock::now();
  const core::RayWorld world(model, state, skip);  // once per scan, as core::Lidar does
  for (const core::Vec3& d : rays) {
    const double r = world.cast(X_WS.translation, R * d, 30.0).range;
    sum += std::isfinite(r) ? r : 0.0;
  }
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// Times `run(out)` (a scan into `out`), adding its finite values to `sum`.
template <class Run>
double timed(Run&& run, std::vector<double>& out, double& sum) {
  const auto t0 = std::chrono::steady_clock::now();
  run(out);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  for (const double r : out) sum += std::isfinite(r) ? r : 0.0;
  return seconds;
}

/// The sensor's own scan: a lidar of `s`.
Sensor::Scan lidarScan(const core::LidarSettings& s) {
  auto lidar = std::make_shared<core::Lidar>(s);
  auto out = std::make_shared<std::vector<double>>();
  return [lidar, out](const core::Model& m, const core::State& st, const core::Pose& X, const std::vector<char>& skip,
                      double& sum) {
    return timed([&](std::vector<double>& r) { lidar->scan(m, st, X, skip, r); }, *out, sum);
  };
}

/// The sensor's own capture: a depth camera of w x h pixels, `hfov` across.
Sensor::Scan cameraScan(int w, int h, double hfov) {
  core::DepthCameraSettings s;
  s.width = w;
  s.height = h;
  s.hfov = hfov;
  s.max_depth = 30.0;
  auto camera = std::make_shared<core::DepthCamera>(s);
  auto out = std::make_shared<std::vector<double>>();
  return [camera, out](const core::Model& m, const core::State& st, const core::Pose& X, const std::vector<char>& skip,
                       double& sum) {
    return timed([&](std::vector<double>& r) { camera->capture(m, st, X, skip, r); }, *out, sum);
  };
}

}  // namespace

int main(int argc, char** argv) {
  const int rounds = argc > 1 ? std::atoi(argv[1]) : 5;
  // 100 shipped boxes on a 10 x 10 grid 1.5 m apart around the robot, four walls 8 m out.
  std::string yaml = "scene:\n  - {type: plane, normal: [0, 0, 1]}\n";
  for (const char* wall : {"[8.1, 0, 1]", "[-8.1, 0, 1]"}) {
    yaml += std::string("  - {type: box, size: [0.2, 16.4, 2], position: ") + wall + "}\n";
  }
  for (const char* wall : {"[0, 8.1, 1]", "[0, -8.1, 1]"}) {
    yaml += std::string("  - {type: box, size: [16.4, 0.2, 2], position: ") + wall + "}\n";
  }
  const std::string urdf = std::string(RBS_SOURCE_DIR) + "/urdf/";
  yaml += "bodies:\n  - {name: rover, urdf: " + urdf + "diff_drive.urdf, initial: {position: [0.75, 0.75, 0.08]}}\n";
  for (int i = 0; i < 100; ++i) {
    const double x = -7.0 + 1.5 * (i % 10), y = -7.0 + 1.5 * (i / 10);
    yaml += "  - {name: b" + std::to_string(i) + ", urdf: " + urdf + "box.urdf, initial: {position: [" +
            std::to_string(x) + ", " + std::to_string(y) + ", 0.05]}}\n";
  }
  const io::SceneSetup world = io::buildScene(io::parseConfig(YAML::Load(yaml)));
  const core::Model& model = world.scene.model();
  const core::State& state = world.state.bodies;
  // The robot's links are not seen by its own sensors.
  std::vector<char> skip(model.bodyCount(), 0);
  for (const int link : world.scene.robots().at(0).link) skip.at(static_cast<std::size_t>(link)) = 1;
  // Sensors 0.2 m above the robot's base, facing x; the ceiling's, 1 m above a plane, looking down.
  const core::Pose X_WS{core::Quat::Identity(), core::Vec3(0.75, 0.75, 0.28)};
  core::ModelSpec plane_spec;
  plane_spec.scene = {core::Sdf::plane(core::Vec3::UnitZ())};
  const core::Model plane(plane_spec);
  const core::State empty = core::restState(plane);
  const core::Pose X_down{core::Quat(Eigen::AngleAxisd(M_PI / 2, core::Vec3::UnitY())), core::Vec3(0, 0, 1)};

  const core::LidarSettings flat = lidarSettings(360, 1, 0.0, 0.0), sixteen = lidarSettings(1800, 16, -0.2618, 0.2618);
  const std::vector<Sensor> sensors = {
      {"lidar 360", 10.0, lidarRays(flat), lidarScan(flat)},
      {"lidar 16 x 1800", 10.0, lidarRays(sixteen), lidarScan(sixteen)},
      {"depth 320 x 240", 30.0, cameraRays(320, 240, M_PI / 3), cameraScan(320, 240, M_PI / 3)}};
  std::vector<std::vector<double>> world_times(sensors.size()), plane_times(sensors.size()),
      sensor_times(sensors.size());
  double sum = 0.0;
  for (int r = 0; r < rounds; ++r) {  // interleaved: each sensor in the world, its own scan, on the plane
    for (std::size_t s = 0; s < sensors.size(); ++s) {
      world_times[s].push_back(castAll(model, state, X_WS, sensors[s].rays, skip, sum));
      sensor_times[s].push_back(sensors[s].scan(model, state, X_WS, skip, sum));
      plane_times[s].push_back(castAll(plane, empty, X_down, sensors[s].rays, {}, sum));
    }
  }
  std::printf("ray_bench: %zu bodies (100 boxes, a robot of %zu links), %d rounds, median (checksum %.3f)\n",
              model.bodyCount(), world.scene.robots()[0].link.size(), rounds, sum);
  std::printf("%-16s %8s %14s %14s %14s %10s %10s %10s\n", "sensor", "rays", "world rays/s", "sensor rays/s",
              "plane rays/s", "world ms", "sensor ms", "sensor %");
  for (std::size_t s = 0; s < sensors.size(); ++s) {
    const double n = static_cast<double>(sensors[s].rays.size());
    const double tw = median(world_times[s]), ts = median(sensor_times[s]), tp = median(plane_times[s]);
    std::printf("%-16s %8.0f %14.3e %14.3e %14.3e %10.3f %10.3f %9.1f%%\n", sensors[s].name, n, n / tw, n / ts, n / tp,
                1e3 * tw, 1e3 * ts, 100.0 * sensors[s].rate * ts);
  }
  return 0;
}
