// Config parsing: the shipped defaults, overrides, and refusals that name the key.
#include "rigid_body_sim/io/config.h"

#include <gtest/gtest.h>

#include "../test_util.h"
#include "rigid_body_sim/core/step/step.h"
#include "rigid_body_sim/core/step/workspace.h"
#include "rigid_body_sim/io/world.h"

namespace rigid_body_sim::test {
namespace {

io::SimConfig parse(const std::string& yaml) { return io::parseConfig(YAML::Load(yaml)); }

void expectRefused(const std::string& yaml, std::initializer_list<std::string> parts) {
  expectThrowsWith<io::ConfigError>([&] { parse(yaml); }, parts);
}

TEST(Config, ShippedDefaultsAreTheCodeDefaults) {
  const io::SimConfig file = io::parseConfig(io::loadYamlFile(std::string(RBS_SOURCE_DIR) + "/config/default.yaml"));
  const io::SimConfig code = parse("");
  EXPECT_EQ(file.model.dt, code.model.dt);
  EXPECT_EQ(file.model.gravity_W, code.model.gravity_W);
  EXPECT_EQ(file.model.gyroscopic, code.model.gyroscopic);
  EXPECT_EQ(file.model.damping.linear, code.model.damping.linear);
  EXPECT_EQ(file.model.damping.angular, code.model.damping.angular);
  EXPECT_EQ(file.model.damping.linear_drag, code.model.damping.linear_drag);
  EXPECT_EQ(file.model.damping.angular_drag, code.model.damping.angular_drag);
  EXPECT_EQ(file.initial.p_WL, code.initial.p_WL);
  EXPECT_EQ(file.initial.q_WL.coeffs(), code.initial.q_WL.coeffs());
  EXPECT_EQ(file.initial.v_WL, code.initial.v_WL);
  EXPECT_EQ(file.initial.w_W, code.initial.w_W);
  const core::ContactSettings &fc = file.model.contact, &cc = code.model.contact;
  EXPECT_EQ(fc.method, cc.method);
  EXPECT_EQ(fc.restitution, cc.restitution);
  EXPECT_EQ(fc.friction, cc.friction);
  EXPECT_EQ(fc.friction_combine, cc.friction_combine);
  EXPECT_EQ(fc.restitution_combine, cc.restitution_combine);
  EXPECT_EQ(fc.restitution_threshold, cc.restitution_threshold);
  EXPECT_EQ(fc.sample_spacing, cc.sample_spacing);
  EXPECT_EQ(fc.iterations, cc.iterations);
  EXPECT_EQ(fc.position_slop, cc.position_slop);
  EXPECT_EQ(fc.penalty_stiffness, cc.penalty_stiffness);
  EXPECT_EQ(fc.penalty_damping, cc.penalty_damping);
  EXPECT_EQ(fc.penalty_buffer, cc.penalty_buffer);
  EXPECT_EQ(fc.barrier_strength, cc.barrier_strength);
  EXPECT_EQ(fc.barrier_buffer, cc.barrier_buffer);
  EXPECT_EQ(file.model.limits.max_linear_speed, code.model.limits.max_linear_speed);
  EXPECT_EQ(file.model.limits.max_angular_speed, code.model.limits.max_angular_speed);
  const core::SleepSettings &fs = file.model.sleep, &cs = code.model.sleep;
  EXPECT_EQ(fs.enabled, cs.enabled);
  EXPECT_EQ(fs.linear_velocity, cs.linear_velocity);
  EXPECT_EQ(fs.angular_velocity, cs.angular_velocity);
  EXPECT_EQ(fs.time, cs.time);
  const core::SolverSettings &fv = file.model.solver, &cv = code.model.solver;
  EXPECT_EQ(fv.velocity_tolerance, cv.velocity_tolerance);
  EXPECT_EQ(fv.relative_tolerance, cv.relative_tolerance);
  EXPECT_EQ(fv.resting_speed, cv.resting_speed);
  EXPECT_EQ(fv.position_iterations, cv.position_iterations);
  EXPECT_EQ(fv.mesh_grid_resolution, cv.mesh_grid_resolution);
  // The default scene is the ground plane z = 0, in the file and in the code.
  for (const io::SimConfig* c : {&file, &code}) {
    ASSERT_EQ(c->model.scene.size(), 1u);
    EXPECT_EQ(c->model.scene[0].kind(), core::Sdf::Kind::kPlane);
    EXPECT_DOUBLE_EQ(c->model.scene[0].eval(Vec3(3, -2, 0.7)), 0.7);
  }
}

TEST(Config, SceneShapesAndCompositions) {
  const io::SimConfig c = parse(R"(
scene:
  - {type: plane, normal: [0, 0, 2], position: [0, 0, -1]}
  - {type: box, size: [1, 2, 3], position: [5, 0, 0], rpy: [0, 0, 1.5707963267948966]}
  - {type: sphere, radius: 0.5, position: [0, 5, 0]}
  - {type: capsule, radius: 0.2, length: 1}
  - {type: cylinder, radius: 0.2, length: 1, quaternion: [0, 0, 0, 1]}
  - type: difference
    position: [0, 0, 10]
    shapes:
      - {type: box, size: [2.2, 2.2, 1.2], position: [0, 0, 0.5]}
      - {type: box, size: [2, 2, 1.5], position: [0, 0, 0.75]}
)");
  ASSERT_EQ(c.model.scene.size(), 6u);
  EXPECT_DOUBLE_EQ(c.model.scene[0].eval(Vec3(1, 1, 1)), 2.0);      // normal normalized
  EXPECT_NEAR(c.model.scene[1].eval(Vec3(5, 0.6, 0)), 0.1, 1e-12);  // turned: its x is world y
  EXPECT_NEAR(c.model.scene[2].eval(Vec3(0, 5, 1)), 0.5, 1e-12);
  EXPECT_NEAR(c.model.scene[3].eval(Vec3(0, 0, 1.5)), 0.8, 1e-12);
  EXPECT_NEAR(c.model.scene[4].eval(Vec3(1, 0, 0)), 0.8, 1e-12);
  EXPECT_NEAR(c.model.scene[5].eval(Vec3(0, 0, 10.3)), 0.3, 1e-12);  // the room's floor, moved up
  EXPECT_TRUE(parse("scene: []").model.scene.empty());
}

TEST(Config, ContactAndSleepKeys) {
  const io::SimConfig c = parse(R"(
contact: {method: penalty_log_barrier, restitution: 0.4, friction: 0.8, restitution_threshold: 0.2,
          sample_spacing: 0.05, iterations: 12, position_slop: 0.0002, penalty_stiffness: 5000,
          penalty_damping: 20, penalty_buffer: 0.01, barrier_strength: 0.02, barrier_buffer: 0.004}
sleep: {enabled: false, linear_velocity: 0.02, angular_velocity: 0.1, time: 1.5}
)");
  EXPECT_EQ(c.model.contact.method, core::ContactMethod::kPenaltyLogBarrier);
  EXPECT_EQ(c.model.contact.restitution, 0.4);
  EXPECT_EQ(c.model.contact.friction, 0.8);
  EXPECT_EQ(c.model.contact.restitution_threshold, 0.2);
  EXPECT_EQ(c.model.contact.sample_spacing, 0.05);
  EXPECT_EQ(c.model.contact.iterations, 12);
  EXPECT_EQ(c.model.contact.position_slop, 0.0002);
  EXPECT_EQ(c.model.contact.penalty_stiffness, 5000);
  EXPECT_EQ(c.model.contact.penalty_damping, 20);
  EXPECT_EQ(c.model.contact.penalty_buffer, 0.01);
  EXPECT_EQ(c.model.contact.barrier_strength, 0.02);
  EXPECT_EQ(c.model.contact.barrier_buffer, 0.004);
  EXPECT_FALSE(c.model.sleep.enabled);
  EXPECT_EQ(c.model.sleep.linear_velocity, 0.02);
  EXPECT_EQ(c.model.sleep.angular_velocity, 0.1);
  EXPECT_EQ(c.model.sleep.time, 1.5);
  for (const char* m : {"impulse", "penalty_quadratic", "shape_matching"}) {
    EXPECT_NO_THROW(parse(std::string("contact: {method: ") + m + "}"));
  }
}

TEST(Config, SolverKeysSetTheTolerancesAUserMayNeed) {
  const io::SimConfig c = parse(
      "solver: {velocity_tolerance: 1.0e-6, relative_tolerance: 1.0e-5, resting_speed: 0, position_iterations: 8, "
      "mesh_grid_resolution: 48}");
  EXPECT_EQ(c.model.solver.velocity_tolerance, 1e-6);
  EXPECT_EQ(c.model.solver.relative_tolerance, 1e-5);
  EXPECT_EQ(c.model.solver.resting_speed, 0.0);
  EXPECT_EQ(c.model.solver.position_iterations, 8);
  EXPECT_EQ(c.model.solver.mesh_grid_resolution, 48);
  expectRefused("solver: {stall_ratio: 0.5}", {"'solver.stall_ratio'", "unknown key"});
  expectRefused("solver: {position_iterations: 2.5}", {"'solver.position_iterations'", "whole number"});
  const io::SimConfig zero = parse("scene: []\nsolver: {velocity_tolerance: 0}");
  expectThrowsWith<std::invalid_argument>([&] { io::buildModel(zero, shippedBox()); },
                                          {"solver.velocity_tolerance = 0", "> 0"});
}

TEST(Config, BadScenesAndContactsAreRefusedByKey) {
  expectRefused("scene: {type: plane}", {"'scene'", "expected a list"});
  expectRefused("scene: [{type: cone}]", {"'scene[0].type'", "unknown shape 'cone'"});
  expectRefused("scene: [{type: box}]", {"'scene[0].size'", "needs size"});
  expectRefused("scene: [{type: box, size: [1, 0, 1]}]", {"'scene[0].size'", "> 0"});
  expectRefused("scene: [{type: sphere, radius: -1}]", {"'scene[0].radius'", "> 0"});
  expectRefused("scene: [{type: plane, normal: [0, 0, 0]}]", {"'scene[0].normal'", "not be zero"});
  expectRefused("scene: [{type: plane, size: [1, 1, 1]}]", {"'scene[0].size'", "unknown key"});
  expectRefused("scene: [{type: difference, shapes: [{type: sphere, radius: 1}]}]",
                {"'scene[0].shapes'", "at least 2"});
  expectRefused("scene: [{type: union, shapes: [{type: ball}]}]", {"'scene[0].shapes[0].type'"});
  expectRefused("contact: {method: magic}", {"'contact.method'", "unknown method 'magic'"});
  expectRefused("contact: {iterations: 2.5}", {"'contact.iterations'", "whole number"});
  expectRefused("contact: {frction: 1}", {"'contact.frction'", "unknown key"});
  expectRefused("sleep: {enabled: sometimes}", {"'sleep.enabled'", "true or false"});
}

TEST(Config, ContactValidationNamesTheField) {
  const io::SimConfig bad = parse("contact: {restitution: 1.5}");
  expectThrowsWith<std::invalid_argument>([&] { io::buildModel(bad, shippedBox()); },
                                          {"contact.restitution = 1.5", "[0, 1]"});
  // A body without collision geometry is kept, as Gazebo keeps it, and
  // touches nothing: over the ground, it falls through (it was refused).
  const core::Model model = io::buildModel(parse(""), shippedBox());
  EXPECT_NE(io::touchesNothing(model.body(0)).find("body 'box' has no <collision> geometry: it touches nothing"),
            std::string::npos);
  core::State state;
  core::LinkState start;
  start.p_WL.z() = 0.05;  // resting height of a collision box; this one has none
  state.bodies = {core::bodyStateFromLink(model.body(0), start)};
  core::Workspace ws;
  for (int k = 0; k < 1000; ++k) core::step(model, state, {}, &ws);  // 1 s
  EXPECT_NEAR(core::linkState(model.body(0), state.bodies[0]).p_WL.z(), 0.05 - 0.5 * 9.81, 0.02);
  EXPECT_NO_THROW(io::buildModel(parse("scene: []"), shippedBox()));
}

TEST(Config, ReadsEveryKey) {
  const io::SimConfig c = parse(R"(
dt: 0.002
gravity: [0, 0, -1.62]
gyroscopic: false
damping: {linear: 0.1, angular: 0.2, linear_drag: 0.3, angular_drag: 0.0004}
initial:
  position: [1, 2, 3]
  quaternion: [0, 0, 1, 0]
  linear_velocity: [4, 5, 6]
  angular_velocity: [0.01, 3, 0.01]
)");
  EXPECT_EQ(c.model.dt, 0.002);
  EXPECT_EQ(c.model.gravity_W, Vec3(0, 0, -1.62));
  EXPECT_FALSE(c.model.gyroscopic);
  EXPECT_EQ(c.model.damping.linear, 0.1);
  EXPECT_EQ(c.model.damping.angular, 0.2);
  EXPECT_EQ(c.model.damping.linear_drag, 0.3);
  EXPECT_EQ(c.model.damping.angular_drag, 0.0004);
  EXPECT_EQ(c.initial.p_WL, Vec3(1, 2, 3));
  // [x, y, z, w] = [0, 0, 1, 0]: half a turn about z (not about x, Eigen's (w, x, y, z) order).
  EXPECT_LT((c.initial.q_WL * Vec3::UnitX() - Vec3(-1, 0, 0)).norm(), 1e-15);
  EXPECT_EQ(c.initial.q_WL.z(), 1.0);
  EXPECT_EQ(c.initial.v_WL, Vec3(4, 5, 6));
  EXPECT_EQ(c.initial.w_W, Vec3(0.01, 3, 0.01));
}

TEST(Config, RpyFollowsTheUrdfConvention) {
  // Fixed axes: roll about x first, then pitch about y, then yaw about z.
  const io::SimConfig c = parse("initial: {rpy: [1.5707963267948966, 0, 1.5707963267948966]}");
  EXPECT_LT((c.initial.q_WL * Vec3::UnitY() - Vec3(0, 0, 1)).norm(), 1e-15);  // roll: y → z, yaw keeps z
  EXPECT_LT((c.initial.q_WL * Vec3::UnitX() - Vec3(0, 1, 0)).norm(), 1e-15);  // yaw: x → y
}

TEST(Config, OverridesSetAnyKeyWithAYamlValue) {
  YAML::Node tree = YAML::Load("dt: 0.001\ninitial: {position: [0, 0, 1]}");
  io::applyOverride(tree, "gravity=[0,0,0]");
  io::applyOverride(tree, "initial.angular_velocity=[0.01,3,0.01]");
  io::applyOverride(tree, "damping.linear=0.5");  // creates the map
  io::applyOverride(tree, "gyroscopic=false");
  io::applyOverride(tree, "dt=0.01");
  const io::SimConfig c = io::parseConfig(tree);
  EXPECT_EQ(c.model.gravity_W, Vec3::Zero());
  EXPECT_EQ(c.initial.w_W, Vec3(0.01, 3, 0.01));
  EXPECT_EQ(c.initial.p_WL, Vec3(0, 0, 1));  // untouched sibling
  EXPECT_EQ(c.model.damping.linear, 0.5);
  EXPECT_FALSE(c.model.gyroscopic);
  EXPECT_EQ(c.model.dt, 0.01);
  YAML::Node empty;
  io::applyOverride(empty, "initial.position=[1,2,3]");
  EXPECT_EQ(io::parseConfig(empty).initial.p_WL, Vec3(1, 2, 3));
}

TEST(Config, BadOverridesAreRefused) {
  YAML::Node tree = YAML::Load("dt: 0.001");
  expectThrowsWith<io::ConfigError>([&] { io::applyOverride(tree, "gravity"); }, {"--set 'gravity'", "KEY=VALUE"});
  expectThrowsWith<io::ConfigError>([&] { io::applyOverride(tree, "dt.x=1"); }, {"'dt.x'", "not a map"});
  expectThrowsWith<io::ConfigError>([&] { io::applyOverride(tree, "gravity=[0,0"); }, {"not valid YAML"});
}

TEST(Config, RefusalsNameTheKeyAndTheValue) {
  expectRefused("dampign: {linear: 1}", {"config key 'dampign'", "unknown key"});
  expectRefused("damping: {lineer: 1}", {"'damping.lineer'", "unknown key", "linear_drag"});
  expectRefused("dt: fast", {"'dt'", "expected a number, got fast"});
  expectRefused("dt: .nan", {"'dt'", "finite"});
  expectRefused("gravity: [0, 0]", {"'gravity'", "expected [x, y, z], got [0, 0]"});
  expectRefused("gravity: [0, 0, x]", {"'gravity[2]'", "got x"});
  expectRefused("gyroscopic: maybe", {"'gyroscopic'", "true or false"});
  expectRefused("initial: {rpy: [0, 0, 0], quaternion: [0, 0, 0, 1]}", {"not both"});
  expectRefused("initial: {quaternion: [0, 0, 0, 2]}", {"'initial.quaternion'", "norm 2"});
  expectRefused("initial: {quaternion: [0, 0, 1]}", {"[x, y, z, w]"});
  expectRefused("[1, 2]", {"expected a map"});
  // yaml-cpp's own "bad conversion" named no key.
  expectRefused("scene: [{type: {a: 1}}]", {"'scene[0].type'", "expected a non-empty string"});
  expectRefused("damping: {[1, 2]: 3}", {"'damping'", "a key must be a plain name"});
  expectRefused("limits: {max_linear_speed: fast}", {"'limits.max_linear_speed'", "expected a number"});
  expectRefused("limits: {max_speed: 3}", {"'limits.max_speed'", "unknown key"});
}

TEST(Config, SpeedLimitsAreKeys) {
  const io::SimConfig c = parse("limits: {max_linear_speed: 20, max_angular_speed: 7}");
  EXPECT_EQ(c.model.limits.max_linear_speed, 20.0);
  EXPECT_EQ(c.model.limits.max_angular_speed, 7.0);
  const io::SimConfig d = parse("dt: 0.001");
  EXPECT_EQ(d.model.limits.max_linear_speed, core::SpeedLimits().max_linear_speed);
}

TEST(Config, BodiesListNamesUrdfsAndInitialStates) {
  const io::SimConfig c = io::parseConfig(YAML::Load(R"(
bodies:
  - {name: a, urdf: box.urdf, initial: {position: [0, 0, 1], rpy: [0, 0, 1.5707963267948966]}}
  - {name: b, urdf: /abs/ball.urdf}
  - {name: c, urdf: package://rigid_body_sim/urdf/bunny.urdf, initial: {linear_velocity: [1, 0, 0]}}
)"),
                                          "/worlds");
  ASSERT_EQ(c.bodies.size(), 3u);
  EXPECT_EQ(c.bodies[0].name, "a");
  EXPECT_EQ(c.bodies[0].urdf, "/worlds/box.urdf");  // relative to the config's folder
  EXPECT_EQ(c.bodies[0].initial.p_WL, Vec3(0, 0, 1));
  EXPECT_LT((c.bodies[0].initial.q_WL * Vec3::UnitX() - Vec3::UnitY()).norm(), 1e-15);
  EXPECT_EQ(c.bodies[1].urdf, "/abs/ball.urdf");
  EXPECT_EQ(c.bodies[2].urdf, "package://rigid_body_sim/urdf/bunny.urdf");
  EXPECT_EQ(c.bodies[2].initial.v_WL, Vec3(1, 0, 0));
  EXPECT_TRUE(parse("").bodies.empty());
}

TEST(Config, BodiesHaveTheirOwnSurfacesCombinedByARule) {
  const io::SimConfig c = parse(R"(
contact: {friction: 0.9, restitution: 0.1, friction_combine: multiply, restitution_combine: average}
bodies:
  - {name: a, urdf: a.urdf, contact: {friction: 0.2, restitution: 0.7}}
  - {name: b, urdf: b.urdf, contact: {friction: 0.4}}
  - {name: c, urdf: c.urdf}
)");
  EXPECT_EQ(c.model.contact.friction_combine, core::CombineRule::kMultiply);
  EXPECT_EQ(c.model.contact.restitution_combine, core::CombineRule::kAverage);
  EXPECT_EQ(c.bodies[0].friction, 0.2);
  EXPECT_EQ(c.bodies[0].restitution, 0.7);
  EXPECT_EQ(c.bodies[1].friction, 0.4);
  EXPECT_FALSE(c.bodies[1].restitution.has_value());
  EXPECT_FALSE(c.bodies[2].friction.has_value());
  const std::pair<const char*, core::CombineRule> rules[] = {{"min", core::CombineRule::kMin},
                                                             {"max", core::CombineRule::kMax},
                                                             {"average", core::CombineRule::kAverage},
                                                             {"multiply", core::CombineRule::kMultiply},
                                                             {"geometric", core::CombineRule::kGeometric}};
  for (const auto& [name, rule] : rules) {
    EXPECT_EQ(parse(std::string("contact: {friction_combine: ") + name + "}").model.contact.friction_combine, rule);
  }
  expectRefused("contact: {friction_combine: harmonic}", {"'contact.friction_combine'", "unknown rule 'harmonic'"});
  EXPECT_EQ(parse("").model.articulation_integrator, core::ArticulationIntegrator::kVerlet);
  EXPECT_EQ(parse("articulation_integrator: symplectic_euler").model.articulation_integrator,
            core::ArticulationIntegrator::kSymplecticEuler);
  expectRefused("articulation_integrator: rk4", {"'articulation_integrator'", "unknown integrator 'rk4'"});
  expectRefused("bodies: [{name: a, urdf: x.urdf, contact: {friction: high}}]", {"'bodies[0].contact.friction'"});
  expectRefused("bodies: [{name: a, urdf: x.urdf, contact: {grip: 1}}]", {"'bodies[0].contact.grip'", "unknown key"});
}

TEST(Config, AnImuIsReadForTheOneBodyOrEachBodyOfAWorld) {
  const io::SimConfig one = parse(
      "imu: {frame_id: gyro, pose: {position: [0.1, 0, 0.2], rpy: [0, 0, 1]}, rate: 250, seed: 9, gyro_noise: 0.01, "
      "accel_noise: 0.1, gyro_bias_walk: 0.001, accel_bias_walk: 0.02, orientation_noise: 0.005}");
  ASSERT_TRUE(one.imu.has_value());
  EXPECT_EQ(one.imu->frame_id, "gyro");
  const core::ImuSettings& s = one.imu->settings;
  EXPECT_EQ(s.X_LS.translation, Vec3(0.1, 0, 0.2));
  EXPECT_NEAR(s.X_LS.rotation.angularDistance(Quat(Eigen::AngleAxisd(1.0, Vec3::UnitZ()))), 0.0, 1e-15);
  EXPECT_EQ(s.rate, 250.0);
  EXPECT_EQ(s.seed, 9u);
  EXPECT_EQ(s.gyro_noise, 0.01);
  EXPECT_EQ(s.accel_noise, 0.1);
  EXPECT_EQ(s.gyro_bias_walk, 0.001);
  EXPECT_EQ(s.accel_bias_walk, 0.02);
  EXPECT_EQ(s.orientation_noise, 0.005);
  EXPECT_FALSE(parse("").imu.has_value());
  const io::SimConfig world = parse("bodies: [{name: a, urdf: x.urdf}, {name: b, urdf: y.urdf, imu: {rate: 50}}]");
  EXPECT_FALSE(world.bodies[0].imu.has_value());
  ASSERT_TRUE(world.bodies[1].imu.has_value());
  EXPECT_EQ(world.bodies[1].imu->settings.rate, 50.0);
  EXPECT_EQ(world.bodies[1].imu->frame_id, "");  // the node names it imu_link
}

TEST(Config, BadImusAreRefusedByKey) {
  expectRefused("imu: {rate: 0}", {"imu.rate = 0"});
  expectRefused("dt: 0.01\nimu: {rate: 200}", {"imu.rate = 200", "1/dt"});
  expectRefused("imu: {gyro_noise: -0.1}", {"imu.gyro_noise = -0.1"});
  expectRefused("imu: {seed: -3}", {"'imu.seed'"});
  expectRefused("imu: {frame: x}", {"'imu.frame'", "unknown key"});
  expectRefused("imu: {pose: {position: [0, 0, nan]}}", {"'imu.pose.position[2]'"});
  expectRefused("bodies: [{name: a, urdf: x.urdf, imu: {accel_noise: .inf}}]", {"bodies[0].imu.accel_noise"});
  expectRefused("bodies: [{name: a, urdf: x.urdf}]\nimu: {rate: 10}", {"'imu'", "bodies[i].imu"});
  expectThrowsWith<io::ConfigError>([] { io::parseImuText("{rate: -1}", "imu", 1e-3); }, {"imu.rate = -1"});
  expectThrowsWith<io::ConfigError>([] { io::parseImuText("[1, 2", "imu", 1e-3); }, {"imu"});
  EXPECT_EQ(io::parseImuText("{rate: 20}", "imu", 1e-3).settings.rate, 20.0);
}

TEST(Config, OdometryNoiseIsReadAndCheckedByKey) {
  const io::SimConfig one = parse(
      "odom_noise: {position: 0.01, orientation: 0.02, linear_velocity: 0.03, angular_velocity: 0.04, "
      "drift: {x: 0.05, y: 0.06, yaw: 0.07}, seed: 5}");
  ASSERT_TRUE(one.odom_noise.has_value());
  const core::OdomNoiseSettings& s = *one.odom_noise;
  EXPECT_EQ(s.position, 0.01);
  EXPECT_EQ(s.orientation, 0.02);
  EXPECT_EQ(s.linear_velocity, 0.03);
  EXPECT_EQ(s.angular_velocity, 0.04);
  EXPECT_EQ(s.drift_x, 0.05);
  EXPECT_EQ(s.drift_y, 0.06);
  EXPECT_EQ(s.drift_yaw, 0.07);
  EXPECT_EQ(s.seed, 5u);
  EXPECT_FALSE(parse("").odom_noise.has_value());
  EXPECT_TRUE(parse("bodies: [{name: a, urdf: x.urdf, odom_noise: {position: 1}}]").bodies[0].odom_noise.has_value());
  expectRefused("odom_noise: {position: -1}", {"odom_noise.position = -1"});
  expectRefused("odom_noise: {drift: {z: 1}}", {"'odom_noise.drift.z'", "unknown key"});
  expectRefused("bodies: [{name: a, urdf: x.urdf, odom_noise: {drift: {yaw: -0.1}}}]",
                {"bodies[0].odom_noise.drift.yaw = -0.1"});
  expectRefused("bodies: []\nodom_noise: {position: 1}", {"'odom_noise'", "bodies[i].odom_noise"});
}

TEST(Config, AVelocityDriverIsReadAndCheckedByKey) {
  const io::SimConfig one = parse(
      "cmd_vel: {max_force: 30, max_torque: 4, linear_gain: 20, linear_integral_gain: 100, angular_gain: 10, "
      "angular_integral_gain: 25, max_linear_speed: 2, max_angular_speed: 1.5, timeout: 0.25, planar: true}");
  ASSERT_TRUE(one.cmd_vel.has_value());
  const core::DriverSettings& s = *one.cmd_vel;
  EXPECT_EQ(s.max_force, 30.0);
  EXPECT_EQ(s.max_torque, 4.0);
  EXPECT_EQ(s.linear_gain, 20.0);
  EXPECT_EQ(s.linear_integral_gain, 100.0);
  EXPECT_EQ(s.angular_gain, 10.0);
  EXPECT_EQ(s.angular_integral_gain, 25.0);
  EXPECT_EQ(s.max_linear_speed, 2.0);
  EXPECT_EQ(s.max_angular_speed, 1.5);
  EXPECT_EQ(s.timeout, 0.25);
  EXPECT_TRUE(s.planar);
  EXPECT_FALSE(parse("").cmd_vel.has_value());
  expectRefused("cmd_vel: {max_force: 0}", {"cmd_vel.max_force = 0"});
  expectRefused("cmd_vel: {planar: maybe}", {"'cmd_vel.planar'"});
  expectRefused("bodies: [{name: a, urdf: x.urdf, cmd_vel: {timeout: -1}}]", {"bodies[0].cmd_vel.timeout = -1"});
  EXPECT_EQ(io::parseDriverText("{max_force: 3}", "cmd_vel").max_force, 3.0);
  // Up to what limits.* may be raised to (1e4): a driver may ask for any
  // speed the world allows (600 m/s and 150 rad/s were refused at 500 and 100).
  const io::SimConfig fast = parse(
      "limits: {max_linear_speed: 1000, max_angular_speed: 200}\n"
      "cmd_vel: {max_linear_speed: 600, max_angular_speed: 150}");
  EXPECT_EQ(fast.cmd_vel->max_linear_speed, 600.0);
  EXPECT_EQ(fast.cmd_vel->max_angular_speed, 150.0);
  expectRefused("cmd_vel: {max_linear_speed: 2e4}", {"cmd_vel.max_linear_speed = 20000", "[0, 10000]"});
}

TEST(Config, BadBodiesAreRefusedByKey) {
  expectRefused("bodies: {name: a}", {"'bodies'", "expected a list"});
  expectRefused("bodies: [{urdf: a.urdf}]", {"'bodies[0].name'", "needs a name"});
  expectRefused("bodies: [{name: a}]", {"'bodies[0].urdf'", "needs a urdf"});
  expectRefused("bodies: [{name: a, urdf: x.urdf}, {name: a, urdf: y.urdf}]", {"'bodies[1].name'", "already"});
  // spawn_body's rule for names: it names topics and frames (a/b was taken at start).
  expectRefused("bodies: [{name: a/b, urdf: x.urdf}]", {"'bodies[0].name'", "'a/b'", "starts with a letter"});
  expectRefused("bodies: [{name: 1a, urdf: x.urdf}]", {"'bodies[0].name'", "'1a'"});
  EXPECT_EQ(io::bodyNameProblem("box_2"), "");
  EXPECT_NE(io::bodyNameProblem(std::string(65, 'a')), "");
  // A key said twice in one map is refused, not half-read.
  for (const char* twice : {"dt: 0.001\ndt: 0.002\n", "bodies: [{name: a, urdf: x.urdf, name: b}]"}) {
    expectThrowsWith<io::ConfigError>([&] { io::parseConfigText(twice, "config.yaml", {}); },
                                      {"config.yaml: line ", "appears twice in one map"});
  }
  expectThrowsWith<io::ConfigError>([&] { io::parseImuText("{rate: 100, rate: 200}", "imu", 1e-3); },
                                    {"imu: line 1: key 'rate' appears twice"});
  expectRefused("bodies: [{name: a, urdf: x.urdf, colour: red}]", {"'bodies[0].colour'", "unknown key"});
  expectRefused("bodies: [{name: a, urdf: x.urdf, initial: {position: [0, 0]}}]",
                {"'bodies[0].initial.position'", "[x, y, z]"});
  expectRefused("initial: {position: [0, 0, 1]}\nbodies: [{name: a, urdf: x.urdf}]",
                {"'initial'", "bodies[i].initial"});
}

// The node hands its bodies list over an entry at a time
// (parseConfigWithBodies): the same bodies and the same refusals as the
// list in the tree, each entry asked for once, in order, and none after
// the first refused.
TEST(Config, ABodiesListGivenApartIsTheListInTheTree) {
  const std::vector<std::string> entries = {"{name: a, urdf: /a.urdf, initial: {position: [1, 2, 3]}}",
                                            "{name: b, urdf: b.urdf, contact: {friction: 0.25}}"};
  const YAML::Node root = YAML::Load("dt: 0.002");
  std::vector<std::size_t> asked;
  const auto entry = [&](std::size_t i) {
    asked.push_back(i);
    return YAML::Load(entries[i]);
  };
  const io::SimConfig apart = io::parseConfigWithBodies(root, entries.size(), entry, "/base");
  const io::SimConfig tree =
      io::parseConfig(YAML::Load("dt: 0.002\nbodies: [" + entries[0] + ", " + entries[1] + "]"), "/base");
  EXPECT_EQ(asked, (std::vector<std::size_t>{0, 1}));
  EXPECT_FALSE(root["bodies"]);  // unchanged
  EXPECT_TRUE(apart.bodies_listed);
  EXPECT_EQ(apart.model.dt, 0.002);
  ASSERT_EQ(apart.bodies.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(apart.bodies[i].name, tree.bodies[i].name);
    EXPECT_EQ(apart.bodies[i].urdf, tree.bodies[i].urdf);
    EXPECT_EQ(apart.bodies[i].initial.p_WL, tree.bodies[i].initial.p_WL);
    EXPECT_EQ(apart.bodies[i].friction, tree.bodies[i].friction);
  }
  EXPECT_EQ(apart.bodies[0].initial.p_WL, Vec3(1, 2, 3));
  EXPECT_EQ(apart.bodies[1].urdf, "/base/b.urdf");
  EXPECT_TRUE(io::parseConfigWithBodies(root, 0, entry, "").bodies_listed);  // bodies: []

  // The first refusal, by key, and nothing asked after it.
  asked.clear();
  const auto twice = [&](std::size_t i) {
    asked.push_back(i);
    return YAML::Load("{name: a, urdf: x.urdf}");
  };
  expectThrowsWith<io::ConfigError>([&] { io::parseConfigWithBodies(root, 5, twice, ""); },
                                    {"'bodies[1].name'", "already"});
  EXPECT_EQ(asked, (std::vector<std::size_t>{0, 1}));
  // A key of the tree is checked first, as in a file.
  expectThrowsWith<io::ConfigError>(
      [&] { io::parseConfigWithBodies(YAML::Load("initial: {position: [0, 0, 1]}"), 2, twice, ""); },
      {"'initial'", "bodies[i].initial"});
}

TEST(Config, ModelValidationNamesTheField) {
  const io::SimConfig c = parse("dt: -0.001\nscene: []");
  expectThrowsWith<std::invalid_argument>([&] { io::buildModel(c, shippedBox()); },
                                          {"dt = -0.001", "must be within [1e-06, 0.1] s"});
}

}  // namespace
}  // namespace rigid_body_sim::test
