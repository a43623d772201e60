// The differential-drive controller (docs/physics.md §11.12) against closed
// forms: ros_controllers' speed limiter, the odometry of wheels turning at
// constant speeds (an arc), the wheel speeds a twist asks for, the command's
// timeout, the default wheel gains, refusals, and a restart. The base driving
// on the ground is io/drive_test.cpp's, the node's diff_drive_controller.test's.
#include "rigid_body_sim/core/controllers/diff_drive.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <tuple>

#include "../articulations/articulation_models.h"
#include "rigid_body_sim/core/articulations/articulation_dynamics.h"

namespace rigid_body_sim::core {
namespace {

constexpr double kH = 1e-3;

/// A 10 kg base on two 1 kg wheels about y (0.02 kg m² about their axles),
/// 0.4 m apart, each with a 5 N m effort limit and a 30 rad/s speed limit.
ArticulationModel twoWheels() {
  ArticulationModel model;
  model.name = "rover";
  ArticulatedLink base;
  base.name = "base_link";
  base.mass = test::boxMass(10.0, Vec3(0.5, 0.4, 0.1));
  model.links.push_back(base);
  for (const auto& [name, y] : {std::pair<const char*, double>{"left", 0.2}, {"right", -0.2}}) {
    ArticulatedLink wheel;
    wheel.name = std::string(name) + "_wheel";
    wheel.joint = std::string(name) + "_wheel_joint";
    wheel.parent = 0;
    wheel.type = JointType::Continuous;
    wheel.X_PJ.translation = Vec3(0.0, y, 0.0);
    wheel.axis_J = Vec3::UnitY();
    wheel.limits.effort = 5.0;
    wheel.limits.velocity = 30.0;
    wheel.mass.mass = 1.0;
    wheel.mass.I_C_F = Vec3(0.01, 0.02, 0.01).asDiagonal();
    model.links.push_back(wheel);
  }
  checkArticulation(model);
  return model;
}

/// How fast twoWheels()'s wheel turns per unit impulse on its axle with
/// nothing touching, (M⁻¹)ᵢᵢ: the wheel (I_w = 0.02 kg m² about its axle) and
/// the base (I_b = 10 (0.5² + 0.1²) / 12 about y; the other wheel turns
/// freely on the same axis, its mass on it) turn against each other, so
/// r = 1 / I_w + 1 / I_b (1/(kg m²)).
constexpr double kResponse = 1.0 / 0.02 + 12.0 / (10.0 * (0.25 + 0.01));
/// What the wheel's servo divides its PID's effort by at gain p (§11.12).
double implicitBy(double p) { return 1.0 + p * kH * kResponse; }

DiffDriveSpec spec(double radius = 0.1) {
  DiffDriveSpec s;
  s.name = "base_controller";
  s.left = {1};
  s.right = {2};
  s.wheel_separation = 0.4;
  s.wheel_radius = radius;
  return s;
}

TEST(TwistLimiter, AreRosControllersSpeedLimiter) {
  TwistLimiter l;
  l.has_velocity_limits = true;
  l.min_velocity = -0.5;
  l.max_velocity = 1.0;
  EXPECT_DOUBLE_EQ(l.limit(2.0, 0.0, 0.0, 0.01), 1.0);
  EXPECT_DOUBLE_EQ(l.limit(-2.0, 0.0, 0.0, 0.01), -0.5);
  // Acceleration 2 m/s² over 0.01 s: at most 0.02 from the last value.
  l.has_acceleration_limits = true;
  l.min_acceleration = -4.0;
  l.max_acceleration = 2.0;
  EXPECT_DOUBLE_EQ(l.limit(1.0, 0.3, 0.3, 0.01), 0.32);
  EXPECT_DOUBLE_EQ(l.limit(-1.0, 0.3, 0.3, 0.01), 0.26);
  // Jerk 100 m/s³: the change may change by at most 100 · 2 · 0.01² = 0.02 from the last change (0.01).
  l.has_jerk_limits = true;
  l.min_jerk = -100.0;
  l.max_jerk = 100.0;
  EXPECT_DOUBLE_EQ(l.limit(1.0, 0.3, 0.29, 0.01), 0.32);  // the acceleration bound 0.02 is the tighter
  l.max_acceleration = 10.0;
  EXPECT_NEAR(l.limit(1.0, 0.3, 0.29, 0.01), 0.3 + 0.01 + 0.02, 1e-15);
}

/// The state with the wheels at `left`, `right` (rad) and turning at `wl`, `wr` (rad/s).
ArticulationState wheelsAt(const ArticulationModel& model, double left, double right, double wl = 0.0,
                           double wr = 0.0) {
  ArticulationState s = restState(model);
  s.q << left, right;
  s.v << wl, wr;
  return s;
}

TEST(DiffDriveOdometry, FollowsTheArcOfWheelsTurningSteadily) {
  const ArticulationModel model = twoWheels();
  DiffDrive drive(model, spec());
  // Left rim 0.3 m/s, right 0.5 m/s: v = 0.4 m/s, ω = 0.2 / 0.4 = 0.5 rad/s, an arc of radius 0.8 m.
  const double wl = 3.0, wr = 5.0, v = 0.4, w = 0.5, R = v / w;
  drive.restart(wheelsAt(model, 0.7, -0.2), true);  // the wheels need not start at 0
  const int steps = 4000;
  for (int n = 1; n <= steps; ++n) {
    const double t = n * kH;
    drive.observe(wheelsAt(model, 0.7 + wl * t, -0.2 + wr * t), kH);
  }
  const double T = steps * kH;
  const PlanarOdometry& o = drive.odometry();
  EXPECT_NEAR(o.x, R * std::sin(w * T), 1e-12);
  EXPECT_NEAR(o.y, R * (1.0 - std::cos(w * T)), 1e-12);
  EXPECT_NEAR(o.heading, w * T, 1e-12);
  EXPECT_NEAR(o.linear, v, 1e-12);
  EXPECT_NEAR(o.angular, w, 1e-12);
}

TEST(DiffDriveOdometry, AveragesItsVelocityOverTheWindow) {
  const ArticulationModel model = twoWheels();
  DiffDriveSpec s = spec();
  s.settings.velocity_rolling_window_size = 4;
  DiffDrive drive(model, s);
  drive.restart(wheelsAt(model, 0.0, 0.0), true);
  // One step of 1 mm on each rim (0.01 rad), then three still: the mean of 1, 0, 0, 0 m/s.
  drive.observe(wheelsAt(model, 0.01, 0.01), kH);
  EXPECT_NEAR(drive.odometry().linear, 1.0, 1e-12);
  for (int n = 2; n <= 4; ++n) drive.observe(wheelsAt(model, 0.01, 0.01), kH);
  EXPECT_NEAR(drive.odometry().linear, 0.25, 1e-12);
  drive.observe(wheelsAt(model, 0.01, 0.01), kH);  // the 1 m/s sample leaves the window
  EXPECT_NEAR(drive.odometry().linear, 0.0, 1e-15);
  EXPECT_NEAR(drive.odometry().x, 1e-3, 1e-15);
}

TEST(DiffDrive, AsksEachWheelForTheSpeedOfItsSide) {
  const ArticulationModel model = twoWheels();
  DiffDriveSpec s = spec();
  s.gains = {{0.5, 0.0, 0.0, 0.0}, {0.5, 0.0, 0.0, 0.0}};  // effort = 0.5 × the speed error
  s.settings.wheel_separation_multiplier = 1.5;            // 0.6 m
  s.settings.right_wheel_radius_multiplier = 0.5;          // 0.05 m
  DiffDrive drive(model, s);
  drive.restart(wheelsAt(model, 0.0, 0.0), true);
  ASSERT_TRUE(drive.command(0.2, 1.0, 0.0));
  Eigen::VectorXd effort = Eigen::VectorXd::Zero(2);
  drive.efforts(wheelsAt(model, 0.0, 0.0, 1.0, 0.0), kH, kH, effort);
  // Left (0.2 − 1 · 0.6 / 2) / 0.1 = −1 rad/s against 1 rad/s turning; right (0.2 + 0.3) / 0.05 = 10 rad/s.
  // Each PID's effort as the servo takes it, implicit in its p.
  EXPECT_NEAR(effort(0), 0.5 * (-1.0 - 1.0) / implicitBy(0.5), 1e-12);
  EXPECT_NEAR(effort(1), 0.5 * 10.0 / implicitBy(0.5), 1e-12);
  EXPECT_DOUBLE_EQ(drive.limitedLinear(), 0.2);
  EXPECT_DOUBLE_EQ(drive.limitedAngular(), 1.0);
  // A command fast enough to pass the effort limit is held to it (5 N m).
  ASSERT_TRUE(drive.command(0.0, 100.0, 2 * kH));
  drive.efforts(wheelsAt(model, 0.0, 0.0), 2 * kH, kH, effort);
  EXPECT_DOUBLE_EQ(effort(0), -5.0);
  EXPECT_DOUBLE_EQ(effort(1), 5.0);
}

TEST(DiffDrive, BrakesWhenTheCommandIsOlderThanItsTimeout) {
  const ArticulationModel model = twoWheels();
  DiffDriveSpec s = spec();
  s.gains = {{1.0, 0.0, 0.0, 0.0}, {1.0, 0.0, 0.0, 0.0}};
  s.settings.cmd_vel_timeout = 0.25;
  DiffDrive drive(model, s);
  drive.restart(wheelsAt(model, 0.0, 0.0), true);
  ASSERT_TRUE(drive.command(0.5, 0.0, 1.0));  // received at t = 1 s
  Eigen::VectorXd effort = Eigen::VectorXd::Zero(2);
  drive.efforts(wheelsAt(model, 0.0, 0.0), 1.25, kH, effort);
  EXPECT_NEAR(effort(0), 5.0 / implicitBy(1.0), 1e-12);  // 0.5 / 0.1 = 5 rad/s: still in time
  drive.efforts(wheelsAt(model, 0.0, 0.0), 1.2501, kH, effort);
  EXPECT_DOUBLE_EQ(effort(0), 0.0);
  EXPECT_DOUBLE_EQ(drive.limitedLinear(), 0.0);
  // Not finite: refused, the last command kept.
  EXPECT_FALSE(drive.command(std::nan(""), 0.0, 1.3));
  EXPECT_FALSE(drive.command(0.1, std::numeric_limits<double>::infinity(), 1.3));
}

// gazebo_ros_diff_drive's way: an infinite timeout holds the last command.
TEST(DiffDrive, AnInfiniteTimeoutHoldsTheLastCommand) {
  const ArticulationModel model = twoWheels();
  DiffDriveSpec s = spec();
  s.gains = {{1.0, 0.0, 0.0, 0.0}, {1.0, 0.0, 0.0, 0.0}};
  s.settings.cmd_vel_timeout = std::numeric_limits<double>::infinity();
  DiffDrive drive(model, s);
  drive.restart(wheelsAt(model, 0.0, 0.0), true);
  ASSERT_TRUE(drive.command(0.5, 0.0, 1.0));
  Eigen::VectorXd effort = Eigen::VectorXd::Zero(2);
  drive.efforts(wheelsAt(model, 0.0, 0.0), 1.0e4, kH, effort);
  EXPECT_NEAR(effort(0), 5.0 / implicitBy(1.0), 1e-12);  // 0.5 / 0.1 = 5 rad/s, a day later
  s.settings.cmd_vel_timeout = std::nan("");
  EXPECT_THROW(DiffDrive(model, s), std::invalid_argument);
}

TEST(DiffDrive, ItsServosAreImplicitInHowFastTheFreeWheelAnswers) {
  const ArticulationModel model = twoWheels();
  const ArticulationKinematics rest = kinematics(model, restState(model));
  EXPECT_NEAR(jointResponse(model, rest, 1), kResponse, 1e-12 * kResponse);
  EXPECT_NEAR(jointResponse(model, rest, 2), kResponse, 1e-12 * kResponse);
}

TEST(DiffDrive, DefaultGainsPlaceBothPolesOfTheWheelLoopAt20Ms) {
  const ArticulationModel model = twoWheels();
  // J = 0.02 + 12 kg · 0.1² / 2 = 0.08 kg m²: p = 2 J / 0.02 = 8, i = J / 0.02² = 200.
  const PidGains g = defaultWheelGains(model, 1, 0.1, 2);
  EXPECT_DOUBLE_EQ(g.p, 8.0);
  EXPECT_DOUBLE_EQ(g.i, 200.0);
  EXPECT_DOUBLE_EQ(g.d, 0.0);
  EXPECT_DOUBLE_EQ(g.i_clamp, 5.0);
  // The closed loop J ω' = p (ω* − ω) + i ∫(ω* − ω) is critically damped: p² = 4 J i.
  EXPECT_DOUBLE_EQ(g.p * g.p, 4.0 * 0.08 * g.i);
}

TEST(DiffDrive, RefusesWhatCannotDrive) {
  const ArticulationModel model = twoWheels();
  const auto refused = [&](DiffDriveSpec s, const std::string& what) {
    try {
      DiffDrive drive(model, s);
      ADD_FAILURE() << "accepted; expected: " << what;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("base_controller"), std::string::npos) << e.what();
    }
  };
  DiffDriveSpec s = spec();
  s.right = {};
  refused(s, "left and right wheels");
  s = spec();
  s.right = {2, 1};
  refused(s, "as many on each side");
  s = spec();
  s.right = {1};
  refused(s, "'left_wheel_joint' twice");
  s = spec(0.0);
  refused(s, "wheel_radius must be finite and > 0");
  s = spec();
  s.wheel_separation = std::numeric_limits<double>::infinity();
  refused(s, "wheel_separation must be");
  s = spec();
  s.settings.velocity_rolling_window_size = 0;
  refused(s, "velocity_rolling_window_size");
  s = spec();
  s.settings.linear.has_velocity_limits = true;
  s.settings.linear.min_velocity = 1.0;
  refused(s, "linear/x: min_velocity and max_velocity");
  s = spec();
  s.gains = {{1.0, 0.0, 0.0, 0.0}};
  refused(s, "one set of PID gains per wheel");
}

// Settings under which a zero command drives the base are refused: a torque
// cap <= 0 (std::clamp(u, 5, -5) is undefined, and drove a base at 1.8 m/s),
// a limit pair wholly above or below 0 (the limiter holds a stopped base to
// it, and drove one 2.5-5.3 m with no command).
TEST(DiffDrive, RefusesSettingsUnderWhichAZeroCommandDrives) {
  const ArticulationModel model = twoWheels();
  const auto refused = [&](const DiffDriveSpec& s, const std::string& what) {
    try {
      DiffDrive drive(model, s);
      ADD_FAILURE() << "accepted; expected: " << what;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
  };
  for (const double torque : {-5.0, 0.0, std::nan("")}) {
    DiffDriveSpec s = spec();
    s.settings.max_wheel_torque = torque;
    refused(s, "max_wheel_torque must be > 0");
  }
  const struct { double lo, hi; } pairs[] = {{-1.0, -0.5}, {1.0, 2.0}, {-2.0, -1.0}};
  for (const auto& p : pairs) {
    for (const char* which : {"velocity", "acceleration", "jerk"}) {
      DiffDriveSpec s = spec();
      TwistLimiter& l = std::string(which) == "jerk" ? s.settings.angular : s.settings.linear;
      const std::string w = which;
      bool& has = w == "velocity"       ? l.has_velocity_limits
                  : w == "acceleration" ? l.has_acceleration_limits
                                        : l.has_jerk_limits;
      double& lo = w == "velocity" ? l.min_velocity : w == "acceleration" ? l.min_acceleration : l.min_jerk;
      double& hi = w == "velocity" ? l.max_velocity : w == "acceleration" ? l.max_acceleration : l.max_jerk;
      has = true;
      lo = p.lo;
      hi = p.hi;
      refused(s, "min_" + w + " and max_" + w + " must be finite, min <= 0 <= max");
    }
  }
  // A pair holding 0, even at a bound, is taken, and a zero command gives zero effort.
  DiffDriveSpec s = spec();
  s.gains = {{1.0, 0.0, 0.0, 0.0}, {1.0, 0.0, 0.0, 0.0}};
  s.settings.linear.has_velocity_limits = true;
  s.settings.linear.min_velocity = 0.0;
  s.settings.linear.max_velocity = 1.0;
  DiffDrive drive(model, s);
  drive.restart(wheelsAt(model, 0.0, 0.0), true);
  Eigen::VectorXd effort = Eigen::VectorXd::Zero(2);
  drive.efforts(wheelsAt(model, 0.0, 0.0), kH, kH, effort);
  EXPECT_EQ(effort(0), 0.0);
  EXPECT_EQ(effort(1), 0.0);
}

// Wheels without a <limit> (legal URDF: no effort or speed limit) and a
// finite cmd_vel of 1e308: the wheel speeds overflowed to inf, the PID's rate
// to NaN, and NaN efforts were published. Such a command is refused; the
// largest one taken gives finite efforts.
TEST(DiffDrive, AnAbsurdCommandIsRefusedAndUnlimitedWheelsStayFinite) {
  ArticulationModel model = twoWheels();
  for (int j : {1, 2}) model.links[j].limits = JointLimits{};
  ASSERT_TRUE(std::isinf(model.links[1].limits.effort));
  DiffDriveSpec s = spec();
  s.settings.max_wheel_torque = std::numeric_limits<double>::infinity();  // a DiffDriveController's
  DiffDrive drive(model, s);
  drive.restart(wheelsAt(model, 0.0, 0.0), true);
  EXPECT_FALSE(drive.command(1e308, -1e308, 0.0));
  EXPECT_FALSE(drive.command(0.0, 1e5, 0.0));
  ASSERT_TRUE(drive.command(1e4, -1e4, 0.0));
  Eigen::VectorXd effort = Eigen::VectorXd::Zero(2);
  for (int k = 1; k <= 100; ++k) {
    drive.efforts(wheelsAt(model, 0.0, 0.0), k * kH, kH, effort);
    ASSERT_TRUE(effort.allFinite()) << "step " << k << ": " << effort.transpose();
  }
}

TEST(DiffDrive, ARestartReadsTheWheelsAfreshAndForgetsTheCommand) {
  const ArticulationModel model = twoWheels();
  DiffDriveSpec s = spec();
  s.gains = {{1.0, 0.0, 0.0, 0.0}, {1.0, 0.0, 0.0, 0.0}};
  DiffDrive drive(model, s);
  drive.restart(wheelsAt(model, 0.0, 0.0), true);
  Eigen::VectorXd effort = Eigen::VectorXd::Zero(2);
  drive.observe(wheelsAt(model, 10.0, 10.0), kH);  // 1 m on each side
  ASSERT_NEAR(drive.odometry().x, 1.0, 1e-12);
  ASSERT_TRUE(drive.command(1.0, 0.0, kH));
  // The joints were moved (set_model_configuration): the odometry does not jump, the command is gone.
  drive.restart(wheelsAt(model, -3.0, 4.0), false);
  drive.observe(wheelsAt(model, -3.0, 4.0), kH);
  drive.efforts(wheelsAt(model, -3.0, 4.0), 2 * kH, kH, effort);
  EXPECT_NEAR(drive.odometry().x, 1.0, 1e-12);
  EXPECT_DOUBLE_EQ(effort(0), 0.0);
  drive.restart(wheelsAt(model, 0.0, 0.0), true);  // a world reset: the odometry starts again
  EXPECT_EQ(drive.odometry().x, 0.0);
}

// A mecanum base (§11.13), as mecanum_drive_controller drives one: four
// wheels 0.3 m ahead or behind and 0.25 m aside of the centre (k = 0.55 m),
// radius 0.1 m, the left front and right back rolling it along x − y.

/// A 20 kg base on four wheels about y at (±0.3, ±0.25): left front, left
/// back, right front, right back (joints 1 to 4).
ArticulationModel fourWheels() {
  ArticulationModel model;
  model.name = "omni";
  ArticulatedLink base;
  base.name = "base_link";
  base.mass = test::boxMass(20.0, Vec3(0.8, 0.6, 0.2));
  model.links.push_back(base);
  for (const auto& [name, x, y] : {std::tuple<const char*, double, double>{"front_left", 0.3, 0.25},
                                   {"back_left", -0.3, 0.25},
                                   {"front_right", 0.3, -0.25},
                                   {"back_right", -0.3, -0.25}}) {
    ArticulatedLink wheel;
    wheel.name = std::string(name) + "_wheel";
    wheel.joint = std::string(name) + "_wheel_joint";
    wheel.parent = 0;
    wheel.type = JointType::Continuous;
    wheel.X_PJ.translation = Vec3(x, y, 0.0);
    wheel.axis_J = Vec3::UnitY();
    wheel.limits.effort = 50.0;
    wheel.limits.velocity = 100.0;
    wheel.mass.mass = 1.0;
    wheel.mass.I_C_F = Vec3(0.01, 0.02, 0.01).asDiagonal();
    model.links.push_back(wheel);
  }
  checkArticulation(model);
  return model;
}

DiffDriveSpec mecanumSpec() {
  DiffDriveSpec s;
  s.name = "omni_controller";
  s.left = {1, 2};
  s.right = {3, 4};
  s.wheel_separation = 2.0 * 0.55;  // twice k, each wheel's |x| + |y|
  s.wheel_radius = 0.1;
  s.mecanum = true;
  return s;
}

/// The rims' speeds of a body twist, as mecanum_drive_controller's inverse
/// kinematics writes them: v_x ∓ v_y ∓ k ω (left front, left back, right front, right back).
Eigen::Vector4d mecanumRims(double vx, double vy, double w) {
  const double k = 0.55;
  return {vx - vy - k * w, vx + vy - k * w, vx + vy + k * w, vx - vy + k * w};
}

TEST(MecanumDrive, ItsOdometryFollowsTheWheelsOfASteadyBodyTwist) {
  const ArticulationModel model = fourWheels();
  DiffDrive drive(model, mecanumSpec());
  const double vx = 0.3, vy = 0.2, w = 0.5;
  const Eigen::Vector4d speed = mecanumRims(vx, vy, w) / 0.1;  // rad/s
  ArticulationState s = restState(model);
  drive.restart(s, true);
  const int steps = 4000;
  for (int n = 1; n <= steps; ++n) {
    s.q = speed * (n * kH);
    drive.observe(s, kH);
  }
  // A constant body twist: the body's (v_x, v_y) turned with the heading.
  const double T = steps * kH, a = w * T;
  const PlanarOdometry& o = drive.odometry();
  EXPECT_NEAR(o.heading, a, 1e-12);
  EXPECT_NEAR(o.x, (vx * std::sin(a) + vy * (std::cos(a) - 1.0)) / w, 1e-12);
  EXPECT_NEAR(o.y, (vx * (1.0 - std::cos(a)) + vy * std::sin(a)) / w, 1e-12);
  EXPECT_NEAR(o.linear, vx, 1e-12);
  EXPECT_NEAR(o.lateral, vy, 1e-12);
  EXPECT_NEAR(o.angular, w, 1e-12);
}

TEST(MecanumDrive, AsksEachWheelForItsRollersSpeedAndADifferentialBaseIgnoresVy) {
  const ArticulationModel model = fourWheels();
  DiffDriveSpec s = mecanumSpec();
  s.gains.assign(4, PidGains{0.5, 0.0, 0.0, 0.0});
  DiffDrive drive(model, s);
  drive.restart(restState(model), true);
  ASSERT_TRUE(drive.command(0.2, 0.4, 0.0, -0.1));
  Eigen::VectorXd effort = Eigen::VectorXd::Zero(4);
  drive.efforts(restState(model), kH, kH, effort);
  const Eigen::Vector4d target = mecanumRims(0.2, -0.1, 0.4) / 0.1;
  // Each wheel's servo: its P on the speed error, implicit in how fast it answers (§11.12).
  const ArticulationKinematics rest = kinematics(model, restState(model));
  for (int n = 0; n < 4; ++n) {
    const double implicit = 1.0 + 0.5 * kH * jointResponse(model, rest, n + 1);
    EXPECT_NEAR(effort(n), 0.5 * target(n) / implicit, 1e-12) << n;
  }
  EXPECT_DOUBLE_EQ(drive.limitedLateral(), -0.1);
  // A differential base takes no sideways command, as DiffDriveController reads none.
  const ArticulationModel two = twoWheels();
  DiffDrive diff(two, spec());
  diff.restart(wheelsAt(two, 0.0, 0.0), true);
  ASSERT_TRUE(diff.command(0.2, 0.0, 0.0, 0.5));
  Eigen::VectorXd e2 = Eigen::VectorXd::Zero(2);
  diff.efforts(wheelsAt(two, 0.0, 0.0), kH, kH, e2);
  EXPECT_EQ(diff.limitedLateral(), 0.0);
  EXPECT_DOUBLE_EQ(e2(0), e2(1));  // straight ahead
  // A mecanum base has two wheels a side.
  DiffDriveSpec three = mecanumSpec();
  three.left = {1};
  three.right = {3};
  EXPECT_THROW(DiffDrive(model, three), std::invalid_argument);
}

}  // namespace
}  // namespace rigid_body_sim::core
