// Rays against the world and the lidar (docs/physics.md §10.5-10.6), against
// closed forms: a beam to a plane at an angle, a sphere off its centre, a
// box's edge and faces, a cylinder's side and cap, a capsule's cap, a
// union's nearest part, a traced room (a difference of boxes); bodies at
// their poses, a skipped body, REP 117's ±inf, seeded noise.
#include "rigid_body_sim/core/devices/ray_cast.h"

#include <gtest/gtest.h>
#include <malloc.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "../../sanitizers.h"
#include "../../test_util.h"
#include "rigid_body_sim/core/devices/depth_camera.h"
#include "rigid_body_sim/core/devices/lidar.h"

namespace rigid_body_sim::test {
namespace {

using core::castRay;
using core::kNoHit;
using core::Sdf;

const Vec3 kX = Vec3::UnitX(), kY = Vec3::UnitY(), kZ = Vec3::UnitZ();

TEST(CastRay, MeetsAPlaneAtItsDistanceOverTheSineOfTheAngle) {
  const Sdf ground = Sdf::plane(kZ);
  for (const double alpha : {0.1, 0.5, 1.2, M_PI / 2}) {
    const Vec3 d(std::cos(alpha), 0.0, -std::sin(alpha));
    EXPECT_NEAR(castRay(ground, Vec3(0, 0, 1.5), d, 100.0), 1.5 / std::sin(alpha), 1e-12) << alpha;
  }
  EXPECT_EQ(castRay(ground, Vec3(0, 0, 1.5), kX, 100.0), kNoHit);                // parallel
  EXPECT_EQ(castRay(ground, Vec3(0, 0, 1.5), Vec3(0.6, 0, -0.8), 1.0), kNoHit);  // 1.875 m away
  EXPECT_EQ(castRay(ground, Vec3(0, 0, -0.1), kX, 100.0), 0.0);                  // starts inside
  // A tilted plane through (3, 0, 0) facing (-1, 0, 1)/√2: from the origin along x it is 3 m away.
  const Sdf tilted = Sdf::plane(Vec3(-1, 0, 1), Vec3(3, 0, 0));
  EXPECT_NEAR(castRay(tilted, Vec3::Zero(), kX, 100.0), 3.0, 1e-12);
}

TEST(CastRay, MeetsASphereOffItsCentre) {
  const Sdf ball = Sdf::sphere(0.5).transformed({Quat::Identity(), Vec3(4, 0, 0)});
  for (const double b : {0.0, 0.3, 0.49}) {
    EXPECT_NEAR(castRay(ball, Vec3(0, b, 0), kX, 100.0), 4.0 - std::sqrt(0.25 - b * b), 1e-12) << b;
  }
  EXPECT_EQ(castRay(ball, Vec3(0, 0.51, 0), kX, 100.0), kNoHit);
  EXPECT_EQ(castRay(ball, Vec3(0, 0, 0), -kX, 100.0), kNoHit);  // behind
  EXPECT_EQ(castRay(ball, Vec3(4.1, 0, 0), kX, 100.0), 0.0);
}

TEST(CastRay, MeetsABoxAtItsEdgeAndFaces) {
  // A 2 m cube turned 45° about z: its vertical edge at x = −√2 faces a ray along x.
  const Sdf cube = Sdf::box(Vec3(2, 2, 2)).transformed({Quat(Eigen::AngleAxisd(M_PI / 4, kZ)), Vec3::Zero()});
  EXPECT_NEAR(castRay(cube, Vec3(-5, 0, 0), kX, 100.0), 5.0 - std::sqrt(2.0), 1e-12);
  // 0.1 m to the side it meets a face at 45°, 0.1 m further on.
  EXPECT_NEAR(castRay(cube, Vec3(-5, 0.1, 0), kX, 100.0), 5.0 - std::sqrt(2.0) + 0.1, 1e-12);
  EXPECT_NEAR(castRay(cube, Vec3(0, 0, 5), -kZ, 100.0), 4.0, 1e-12);  // its top
  EXPECT_EQ(castRay(cube, Vec3(-5, 0, 1.01), kX, 100.0), kNoHit);
}

TEST(CastRay, MeetsACylindersSideAndCapAndACapsulesCap) {
  const Sdf can = Sdf::cylinder(0.5, 1.0);
  EXPECT_NEAR(castRay(can, Vec3(-3, 0, 0.2), kX, 100.0), 2.5, 1e-12);
  EXPECT_NEAR(castRay(can, Vec3(0.3, 0, 3), -kZ, 100.0), 2.5, 1e-12);
  EXPECT_NEAR(castRay(can, Vec3(-3, 0.3, 0), kX, 100.0), 3.0 - 0.4, 1e-12);
  EXPECT_EQ(castRay(can, Vec3(-3, 0, 0.6), kX, 100.0), kNoHit);
  EXPECT_EQ(castRay(can, Vec3(0.51, 0, 3), -kZ, 100.0), kNoHit);
  const Sdf pill = Sdf::capsule(0.5, 1.0);  // the segment z in [-0.5, 0.5]
  EXPECT_NEAR(castRay(pill, Vec3(0, 0, 3), -kZ, 100.0), 2.0, 1e-12);
  EXPECT_NEAR(castRay(pill, Vec3(-3, 0, 0.7), kX, 100.0), 3.0 - std::sqrt(0.25 - 0.04), 1e-12);
  EXPECT_NEAR(castRay(pill, Vec3(-3, 0, 0.3), kX, 100.0), 2.5, 1e-12);
}

TEST(CastRay, MeetsAUnionsNearestPartAndTracesARoom) {
  const Sdf two = Sdf::unite({Sdf::sphere(0.5).transformed({Quat::Identity(), Vec3(5, 0, 0)}),
                              Sdf::box(Vec3(1, 1, 1)).transformed({Quat::Identity(), Vec3(3, 0, 0)})})
                      .transformed({Quat(Eigen::AngleAxisd(M_PI / 2, kZ)), Vec3(0, 1, 0)});
  // Turned a quarter about z and moved 1 m along y: the box's near face is 3.5 m up y from y = 1.
  EXPECT_NEAR(castRay(two, Vec3::Zero(), kY, 100.0), 1.0 + 2.5, 1e-12);
  // The room (walls x, y = ±1, floor z = 0): a difference, traced to within 1 µm.
  const Sdf walls = room();
  for (const double theta : {0.0, 0.3, 0.7, 2.0}) {
    const Vec3 d(std::cos(theta), std::sin(theta), 0.0);
    const double expected = 1.0 / std::max(std::abs(d.x()), std::abs(d.y()));
    EXPECT_NEAR(castRay(walls, Vec3(0, 0, 0.5), d, 100.0), expected, 2e-6) << theta;
  }
  EXPECT_NEAR(castRay(walls, Vec3(0.2, 0, 0.5), Vec3(0.6, 0, -0.8), 100.0), 0.5 / 0.8, 2e-6);
}

/// The ground, a 1 m cube centred at (3, 0, 0.5) turned 30° about z, and a ball of radius 0.25 at (0, 2, 0.25).
struct World {
  core::Model model;
  core::State state;
  World() : model(spec()), state(core::restState(model)) {
    core::LinkState cube;
    cube.p_WL = Vec3(3, 0, 0.5);
    cube.q_WL = Quat(Eigen::AngleAxisd(M_PI / 6, kZ));
    state.bodies[0] = core::bodyStateFromLink(model.body(0), cube);
    core::LinkState ball;
    ball.p_WL = Vec3(0, 2, 0.25);
    state.bodies[1] = core::bodyStateFromLink(model.body(1), ball);
  }
  static core::ModelSpec spec() {
    core::ModelSpec s;
    s.bodies = {boxBody(Vec3(0.5, 0.5, 0.5)), ballBody(0.25)};
    s.bodies[1].name = "ball";
    s.scene = {Sdf::plane(kZ)};
    return s;
  }
};

TEST(CastRay, SeesBodiesWhereTheirStatePutsThemUnlessSkipped) {
  const World w;
  // Along x at 0.5 m: the cube's face turned 30° crosses y = 0 at x = 3 − 0.5 / cos 30°.
  const core::RayHit cube = castRay(w.model, w.state, Vec3(0, 0, 0.5), kX, 100.0);
  EXPECT_NEAR(cube.range, 3.0 - 0.5 / std::cos(M_PI / 6), 1e-12);
  EXPECT_EQ(cube.body, 0);
  const core::RayHit ball = castRay(w.model, w.state, Vec3(0, 0, 0.25), kY, 100.0);
  EXPECT_NEAR(ball.range, 1.75, 1e-12);
  EXPECT_EQ(ball.body, 1);
  // Skipped, the ball is not seen; down, the ground is.
  EXPECT_EQ(castRay(w.model, w.state, Vec3(0, 0, 0.25), kY, 100.0, {0, 1}).range, kNoHit);
  const core::RayHit ground = castRay(w.model, w.state, Vec3(0, 0, 1), -kZ, 100.0);
  EXPECT_NEAR(ground.range, 1.0, 1e-15);
  EXPECT_EQ(ground.body, -1);
}

/// 60 cubes and balls at random poses around the origin, on the ground.
struct Pile {
  core::Model model;
  core::State state;
  Pile() : model(spec()), state(core::restState(model)) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> across(-6.0, 6.0), up(0.2, 3.0), turn(-M_PI, M_PI);
    for (std::size_t i = 0; i < model.bodyCount(); ++i) {
      core::LinkState at;
      at.p_WL = Vec3(across(rng), across(rng), up(rng));
      at.q_WL = Quat(Eigen::AngleAxisd(turn(rng), Vec3(turn(rng), turn(rng), turn(rng)).normalized()));
      state.bodies[i] = core::bodyStateFromLink(model.body(i), at);
    }
  }
  static core::ModelSpec spec() {
    core::ModelSpec s;
    for (int i = 0; i < 60; ++i) {
      s.bodies.push_back(i % 2 == 0 ? boxBody(Vec3(0.3, 0.2, 0.4)) : ballBody(0.3));
      s.bodies.back().name = "b" + std::to_string(i);
    }
    s.scene = {Sdf::plane(kZ)};
    return s;
  }
};

// A cull keeps every body a ray inside its cone can meet: those rays meet
// what they meet against every body, bit for bit, while most bodies are
// culled away.
TEST(CastRay, ACulledConeMeetsWhatEveryBodyGives) {
  const Pile p;
  const core::RayWorld world(p.model, p.state);
  const Vec3 o(0.1, -0.2, 1.0);
  std::mt19937_64 rng(3);
  std::normal_distribution<double> normal;
  std::vector<int> among;
  std::size_t hits = 0, kept = 0, cones = 0;
  for (const double half_angle : {0.01, 0.05, 0.2, 0.6}) {
    for (int c = 0; c < 40; ++c, ++cones) {
      const Vec3 axis = Vec3(normal(rng), normal(rng), normal(rng)).normalized();
      world.cull(o, axis, half_angle, 20.0, among);
      kept += among.size();
      // Rays inside the cone, out to its rim.
      const Vec3 across = axis.unitOrthogonal();
      for (int r = 0; r < 50; ++r) {
        const double off = half_angle * (r == 0 ? 1.0 : std::abs(std::fmod(normal(rng), 1.0)));
        const Vec3 d = Eigen::AngleAxisd(off, Eigen::AngleAxisd(normal(rng), axis) * across) * axis;
        const core::RayHit all = world.cast(o, d, 20.0), culled = world.cast(o, d, 20.0, among);
        EXPECT_EQ(culled.range, all.range);
        EXPECT_EQ(culled.body, all.body);
        hits += all.body >= 0 ? 1 : 0;
      }
    }
  }
  EXPECT_GT(hits, 400u);            // the rays do meet bodies
  EXPECT_LT(kept, cones * 60 / 4);  // and most bodies are culled away
}

// A depth camera's and a lidar's images (cast by tiles and groups of rays,
// each culled once) are those of casting every pixel against every body.
TEST(CastRay, TilesOfRaysGiveTheImageEveryBodyGives) {
  const Pile p;
  const core::RayWorld world(p.model, p.state);
  core::Pose X_WS;
  X_WS.translation = Vec3(0.1, -0.2, 1.0);
  X_WS.rotation = Quat(Eigen::AngleAxisd(0.7, kZ) * Eigen::AngleAxisd(0.2, kY));
  core::DepthCameraSettings cs;
  cs.width = 70;
  cs.height = 50;
  cs.max_depth = 20.0;
  core::DepthCamera camera(cs);
  std::vector<double> depth;
  camera.capture(p.model, p.state, X_WS, {}, depth);
  const Mat3 R_WS = X_WS.rotation.toRotationMatrix();
  // The same infinity, or within rounding (the test builds its rays anew).
  const auto same = [](double a, double b) { return a == b || std::abs(a - b) < 1e-12; };
  int met = 0;
  for (int v = 0; v < cs.height; ++v) {
    for (int u = 0; u < cs.width; ++u) {
      const Vec3 ray(1.0, -(u - camera.cx()) / camera.focal(), -(v - camera.cy()) / camera.focal());
      const double t = world.cast(X_WS.translation, R_WS * ray.normalized(), cs.max_depth * ray.norm()).range;
      const double z = t == kNoHit ? kNoHit : t / ray.norm();
      const double expected = z == kNoHit ? kNoHit : z < cs.min_depth ? -kNoHit : z;
      ASSERT_TRUE(same(depth[static_cast<std::size_t>(v * cs.width + u)], expected)) << u << ", " << v;
      met += std::isfinite(expected) ? 1 : 0;
    }
  }
  EXPECT_GT(met, 100);
  core::LidarSettings ls;
  ls.samples = 500;
  ls.min_angle = -M_PI;
  ls.max_angle = M_PI;
  ls.vertical_samples = 3;
  ls.vertical_min_angle = -0.3;
  ls.vertical_max_angle = 0.3;
  ls.max_range = 20.0;
  core::Lidar lidar(ls);
  std::vector<double> ranges;
  lidar.scan(p.model, p.state, X_WS, {}, ranges);
  int seen = 0;
  for (int f = 0; f < 3; ++f) {
    const double e = -0.3 + 0.3 * f;
    for (int k = 0; k < ls.samples; ++k) {
      const double a = -M_PI + k * 2.0 * M_PI / (ls.samples - 1);
      const Vec3 d(std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e));
      const double t = world.cast(X_WS.translation, R_WS * d, ls.max_range).range;
      ASSERT_TRUE(same(ranges[static_cast<std::size_t>(f * ls.samples + k)], t)) << f << ", " << k;
      seen += std::isfinite(t) ? 1 : 0;
    }
  }
  EXPECT_GT(seen, 100);
}

TEST(Lidar, ReadsAWallAsItsDistanceOverTheCosineAndRep117Beyond) {
  core::ModelSpec s;
  // A ball of radius 0.045 m 0.1 m to the sensor's right, nearer than min_range, and one far away (a world of one
  // body builds no solid).
  s.bodies = {ballBody(0.045), ballBody(0.045)};
  s.bodies[1].name = "far";
  s.scene = {Sdf::plane(-kX, Vec3(2, 0, 0))};
  const core::Model model(s);
  core::State state = core::restState(model);
  core::LinkState near;
  near.p_WL = Vec3(0, -0.1, 0);
  state.bodies[0] = core::bodyStateFromLink(model.body(0), near);
  near.p_WL = Vec3(0, 0, -50);
  state.bodies[1] = core::bodyStateFromLink(model.body(1), near);
  core::LidarSettings settings;
  settings.samples = 181;
  settings.min_angle = -M_PI / 2;
  settings.max_angle = M_PI / 2;
  settings.min_range = 0.1;
  settings.max_range = 5.0;
  core::Lidar lidar(settings);
  EXPECT_DOUBLE_EQ(lidar.angleIncrement(), M_PI / 180);
  std::vector<double> ranges;
  lidar.scan(model, state, core::Pose{}, {}, ranges);
  ASSERT_EQ(ranges.size(), 181u);
  for (int k = 0; k < 181; ++k) {
    const double theta = -M_PI / 2 + k * M_PI / 180, expected = 2.0 / std::cos(theta);
    if (k < 90 && 0.1 * std::sin(k * M_PI / 180) < 0.045) {  // the ball's rays (k <= 26): too close
      EXPECT_EQ(ranges[k], -kNoHit) << k;
    } else if (expected <= 5.0) {
      EXPECT_NEAR(ranges[k], expected, 1e-12) << k;
    } else {
      EXPECT_EQ(ranges[k], kNoHit) << k;  // past max_range
    }
  }
  // Turned to face away, it sees nothing.
  lidar.scan(model, state, core::Pose{Quat(Eigen::AngleAxisd(M_PI, kZ)), Vec3(0, 0, 0)}, {1, 1}, ranges);
  for (const double r : ranges) EXPECT_EQ(r, kNoHit);
}

TEST(Lidar, NoiseIsSeededGaussianOfItsSigma) {
  core::ModelSpec s;
  s.bodies = {ballBody(0.1)};
  s.scene = {Sdf::plane(kZ)};
  const core::Model model(s);
  const core::State state = core::restState(model);
  core::LidarSettings settings;
  settings.samples = 1000;
  settings.vertical_samples = 10;
  settings.min_angle = -1.0;
  settings.max_angle = 1.0;
  settings.vertical_min_angle = -1.2;
  settings.vertical_max_angle = -0.8;
  settings.noise = 0.01;
  settings.seed = 7;
  core::Lidar a(settings), b(settings);
  EXPECT_NEAR(a.verticalIncrement(), 0.4 / 9, 1e-15);
  const core::Pose X_WS{Quat::Identity(), Vec3(0, 0, 2)};
  std::vector<double> ra, rb;
  a.scan(model, state, X_WS, {1}, ra);
  b.scan(model, state, X_WS, {1}, rb);
  EXPECT_EQ(ra, rb);  // the same seed, the same scan
  std::vector<double> residual;
  for (std::size_t k = 0; k < ra.size(); ++k) {
    const Vec3& d = a.direction(k);
    residual.push_back(ra[k] - 2.0 / -d.z());
  }
  const auto [mean, sigma] = meanAndSigma(residual);
  EXPECT_NEAR(mean, 0.0, 4.0 * 0.01 / std::sqrt(10000.0));
  EXPECT_NEAR(sigma, 0.01, 0.0005);
  a.scan(model, state, X_WS, {1}, rb);
  EXPECT_NE(ra, rb);  // the next scan draws new noise
  a.restart();
  a.scan(model, state, X_WS, {1}, rb);
  EXPECT_EQ(ra, rb);
}

TEST(Lidar, AScanDueButNotCastLeavesTheNextOneAsItWouldHaveBeen) {
  // The node casts no scan nobody listens to: a subscriber that comes late
  // must get the scans a subscriber from the start gets, noise and all.
  core::ModelSpec s;
  s.scene = {Sdf::plane(kZ)};
  const core::Model model(s);
  const core::State state = core::restState(model);
  core::LidarSettings settings;
  settings.samples = 200;
  settings.min_angle = -1.0;
  settings.max_angle = 1.0;
  settings.vertical_samples = 3;
  settings.vertical_min_angle = -1.2;
  settings.vertical_max_angle = -0.8;
  settings.noise = 0.01;
  settings.seed = 11;
  core::Lidar every(settings), late(settings);
  const core::Pose X_WS{Quat::Identity(), Vec3(0, 0, 2)};
  std::vector<double> first, second, after_pass;
  every.scan(model, state, X_WS, {}, first);
  every.scan(model, state, X_WS, {}, second);
  late.pass();
  late.scan(model, state, X_WS, {}, after_pass);
  EXPECT_EQ(after_pass, second);
  EXPECT_NE(first, second);  // each scan its own noise
}

TEST(Lidar, RefusesSettingsNamingTheField) {
  const auto refused = [](core::LidarSettings s, const char* what) {
    try {
      core::Lidar lidar(s);
      ADD_FAILURE() << "accepted; expected " << what;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
  };
  core::LidarSettings s;
  s.samples = 0;
  refused(s, "samples");
  s = {};
  s.min_angle = 1.0;
  s.max_angle = 0.5;
  refused(s, "min_angle and max_angle");
  s = {};
  s.max_range = std::numeric_limits<double>::infinity();
  refused(s, "min_range < max_range");
  s = {};
  s.noise = -1.0;
  refused(s, "noise");
  s = {};
  s.samples = 2000;
  s.vertical_samples = 1000;
  refused(s, "<= 1e6");
  // Finite, but beyond what LaserScan's float32 fields hold: published as ±inf once.
  for (const double a : {1e308, 1e39, 13.0}) {
    s = {};
    s.min_angle = -a;
    s.max_angle = a;
    refused(s, "min_angle and max_angle must be within [-4 pi, 4 pi]");
  }
  s = {};
  s.max_range = 1e39;
  refused(s, "max_range must be <= 1e5 m");
  s = {};
  s.min_angle = 0.0;  // TurtleBot3's LDS: a full turn, rounded up past 2 pi
  s.max_angle = 6.28319;
  s.max_range = 1e5;
  EXPECT_NO_THROW(core::Lidar{s});
  s.min_angle = -4.0 * M_PI;  // two turns each way are still taken
  s.max_angle = 4.0 * M_PI;
  EXPECT_NO_THROW(core::Lidar{s});
}

// Settings whose CameraInfo or cloud would hold inf are refused: an hfov of
// 1e-320 rad made the focal length, K and P, inf. SDF's own narrowest,
// 1e-3 rad, gives a focal length a float32 holds.
TEST(DepthCamera, RefusesSettingsWhoseMessagesWouldNotBeFinite) {
  core::DepthCameraSettings s;
  s.hfov = 1e-320;
  EXPECT_THROW(core::DepthCamera{s}, std::invalid_argument);
  s.hfov = 0.5e-3;
  EXPECT_THROW(core::DepthCamera{s}, std::invalid_argument);
  s.hfov = 1e-3;
  const core::DepthCamera narrow(s);
  EXPECT_LT(narrow.focal(), 1e6);
  s = {};
  s.max_depth = 1e39;
  try {
    core::DepthCamera camera(s);
    ADD_FAILURE() << "max_depth 1e39 accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("max_depth must be <= 1e5 m"), std::string::npos) << e.what();
  }
}

// What a device is counted as before it is built (the node's devices.memory)
// covers what it allocates: measured on the heap, it holds at least what the
// device's own arrays take and no more than the count.
TEST(DeviceBytes, CoverWhatTheLidarAndTheCameraAllocate) {
#if defined(RBS_UNDER_ASAN) || defined(RBS_UNDER_TSAN)
  GTEST_SKIP() << "a sanitizer's allocator keeps no mallinfo";
#endif
  const auto heap = [] {  // in use: small blocks, and large ones malloc maps apart
    const struct mallinfo2 m = mallinfo2();
    return static_cast<std::uintmax_t>(m.uordblks + m.hblkhd);
  };
  core::ModelSpec spec;
  const core::Model model(spec);
  const core::State state = core::restState(model);
  core::LidarSettings l;
  l.samples = 2000;
  l.vertical_samples = 50;
  const std::uintmax_t before_lidar = heap();
  {
    core::Lidar lidar(l);
    std::vector<double> ranges;
    lidar.scan(model, state, core::Pose{}, {}, ranges);
    const std::uintmax_t used = heap() - before_lidar;
    EXPECT_LE(used, core::lidarBytes(l));
    EXPECT_GE(used, core::lidarBytes(l) / 3) << "the count is far above what the lidar holds";
  }
  core::DepthCameraSettings c;
  c.width = 400;
  c.height = 300;
  const std::uintmax_t before_camera = heap();
  {
    core::DepthCamera camera(c);
    std::vector<double> depth;
    camera.capture(model, state, core::Pose{}, {}, depth);
    const std::uintmax_t used = heap() - before_camera;
    EXPECT_LE(used, core::depthCameraBytes(c));
    EXPECT_GE(used, core::depthCameraBytes(c) / 3) << "the count is far above what the camera holds";
  }
}

TEST(DepthCamera, AnImageDueButNotCastLeavesTheNextOneAsItWouldHaveBeen) {
  core::ModelSpec s;
  s.scene = {Sdf::plane(Vec3(-1.0, 0.0, 0.0), Vec3(2, 0, 0))};
  const core::Model model(s);
  const core::State state = core::restState(model);
  core::DepthCameraSettings settings;
  settings.width = 16;
  settings.height = 12;
  settings.noise = 0.01;
  settings.seed = 5;
  core::DepthCamera every(settings), late(settings);
  std::vector<double> first, second, after_pass;
  every.capture(model, state, core::Pose{}, {}, first);
  every.capture(model, state, core::Pose{}, {}, second);
  late.pass();
  late.capture(model, state, core::Pose{}, {}, after_pass);
  EXPECT_EQ(after_pass, second);
  EXPECT_NE(first, second);
  every.restart();
  every.capture(model, state, core::Pose{}, {}, second);
  EXPECT_EQ(second, first);  // from its seed again
}

TEST(DepthCamera, ReadsAPlaneAtAnAngleAsItsDepthPerPixel) {
  // A plane through (2, 0, 0) leaning back by 30 degrees (x = 2 + z tan 30 deg); the camera at the origin looks along
  // x.
  const double tan_b = std::tan(M_PI / 6);
  core::ModelSpec s;
  s.scene = {Sdf::plane(Vec3(-1.0, 0.0, tan_b), Vec3(2, 0, 0))};
  const core::Model model(s);
  const core::State state = core::restState(model);
  core::DepthCameraSettings settings;
  settings.width = 64;
  settings.height = 48;
  settings.hfov = M_PI / 2;
  settings.max_depth = 3.0;
  core::DepthCamera camera(settings);
  EXPECT_DOUBLE_EQ(camera.focal(), 32.0);  // (width / 2) / tan(hfov / 2)
  EXPECT_DOUBLE_EQ(camera.cx(), 31.5);
  EXPECT_DOUBLE_EQ(camera.cy(), 23.5);
  std::vector<double> depth;
  camera.capture(model, state, core::Pose{}, {}, depth);
  ASSERT_EQ(depth.size(), 64u * 48u);
  for (int v = 0; v < 48; ++v) {
    // Row v looks up by b = (cy - v) / f: the ray (1, a, b) meets the plane at depth 2 / (1 - b tan 30 deg).
    const double b = (23.5 - v) / 32.0, expected = 2.0 / (1.0 - b * tan_b);
    for (int u = 0; u < 64; ++u) {
      const double d = depth[static_cast<std::size_t>(v * 64 + u)];
      if (expected <= 3.0) {
        EXPECT_NEAR(d, expected, 1e-12) << u << ", " << v;
      } else {
        EXPECT_EQ(d, kNoHit) << u << ", " << v;  // past max_depth, at the top of the image
      }
    }
  }
  EXPECT_EQ(depth[0], kNoHit);  // the top row: 2 / (1 - 0.734 tan 30 deg) = 3.45 m
  EXPECT_NEAR(depth[47 * 64], 2.0 / (1.0 + 23.5 / 32.0 * tan_b), 1e-12);  // the bottom row, nearer
  // Turned to look at the plane's back (from beyond it, facing -x): inside the half-space, every pixel is too close.
  camera.capture(model, state, core::Pose{Quat(Eigen::AngleAxisd(M_PI, kZ)), Vec3(5, 0, 0)}, {}, depth);
  EXPECT_EQ(depth[0], -kNoHit);
}

}  // namespace
}  // namespace rigid_body_sim::test
