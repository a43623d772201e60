// A robot's link sensors (docs/physics.md §10.11): link_sensors.h.
#include "rigid_body_sim/core/devices/link_sensors.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace rigid_body_sim::core {

SampleClock::SampleClock(double rate, double dt)
    : every_(rate > 0.0 ? std::max(1LL, std::llround(1.0 / (rate * dt))) : 1), dt_(dt) {}

double SampleClock::elapsed(double t) {
  const double e = last_ < 0.0 ? static_cast<double>(every_) * dt_ : t - last_;
  last_ = t;
  return e;
}

LinkState linkStateOf(const ArticulationKinematics& kin, int link) {
  const Placement& X_WL = kin.X_WL[static_cast<std::size_t>(link)];
  const Vec6& V_L = kin.V_L[static_cast<std::size_t>(link)];  // [ω; v] in the link's axes
  LinkState s;
  s.p_WL = X_WL.p_PC;
  s.q_WL = Quat(X_WL.R_PC).normalized();
  s.w_W = X_WL.R_PC * V_L.head<3>();
  s.v_WL = X_WL.R_PC * V_L.tail<3>();
  return s;
}

void LinkSensors::addImu(const ImuSettings& settings, int link, const ArticulationModel& model,
                         const ArticulationState& now) {
  kinematics(model, now, kin_);
  imus_.push_back({Imu(settings, linkStateOf(kin_, link)), link, SampleClock(settings.rate, dt_), {}});
  fresh_[static_cast<std::size_t>(Kind::kImu)].push_back(0);
}

void LinkSensors::addOdometry(const std::optional<OdomNoiseSettings>& noise, const LinkMount& at, double rate) {
  OdometryChannel& c = odometry_.emplace_back(OdometryChannel{std::nullopt, at, SampleClock(rate, dt_), {}, {}});
  if (noise) c.noise.emplace(*noise);
  fresh_[static_cast<std::size_t>(Kind::kOdometry)].push_back(0);
}

void LinkSensors::addGnss(const GnssSettings& settings, const LinkMount& at, double rate) {
  gnss_.push_back({Gnss(settings), at, SampleClock(rate, dt_), {}});
  fresh_[static_cast<std::size_t>(Kind::kGnss)].push_back(0);
}

void LinkSensors::addMagnetometer(const MagnetometerSettings& settings, const LinkMount& at, double rate) {
  magnetometers_.push_back({Magnetometer(settings), at, SampleClock(rate, dt_), Vec3::Zero()});
  fresh_[static_cast<std::size_t>(Kind::kMagnetometer)].push_back(0);
}

void LinkSensors::addLidar(const LidarSettings& settings, const std::optional<RangeFinderSettings>& finder,
                           const LinkMount& at, double rate) {
  LidarChannel& c = lidars_.emplace_back(LidarChannel{Lidar(settings), std::nullopt, at, SampleClock(rate, dt_), {}});
  if (finder) c.finder.emplace(*finder);
  fresh_[static_cast<std::size_t>(Kind::kLidar)].push_back(0);
  wanted_[static_cast<std::size_t>(Kind::kLidar)].push_back(1);
}

void LinkSensors::addDepthCamera(const DepthCameraSettings& settings, const LinkMount& at, double rate) {
  depth_cameras_.push_back({DepthCamera(settings), at, SampleClock(rate, dt_), {}});
  fresh_[static_cast<std::size_t>(Kind::kDepthCamera)].push_back(0);
  wanted_[static_cast<std::size_t>(Kind::kDepthCamera)].push_back(1);
}

void LinkSensors::addForceTorque(const ForceTorqueSettings& settings, int link, double rate) {
  force_torques_.push_back({ForceTorqueSensor(link, settings), SampleClock(rate, dt_), Vec6::Zero()});
  fresh_[static_cast<std::size_t>(Kind::kForceTorque)].push_back(0);
  wanted_[static_cast<std::size_t>(Kind::kForceTorque)].push_back(1);
}

void LinkSensors::addContactSensor(const LinkMount& at, bool in_world, double rate) {
  contact_sensors_.push_back({at, in_world, SampleClock(rate, dt_), {}});
  fresh_[static_cast<std::size_t>(Kind::kContacts)].push_back(0);
  wanted_[static_cast<std::size_t>(Kind::kContacts)].push_back(1);
}

void LinkSensors::before(const ArticulationModel& model, const ArticulationState& state) {
  if (!force_torques_.empty()) u_before_ = generalizedVelocity(model, state);
}

bool LinkSensors::sample(const Scene& scene, std::size_t r, const State& bodies, const ArticulationState& state,
                         long long steps, double t, const StepForces& forces) {
  const SceneRobot& robot = scene.robots().at(r);
  const ArticulationModel& model = robot.model;
  const Vec3& gravity_W = scene.model().gravity();
  bool placed = false;  // the robot's links, once for all its sensors
  const auto place = [&] {
    if (!placed) kinematics(model, state, kin_);
    placed = true;
  };
  const auto frame = [&](const LinkMount& at) {
    place();
    return frameState(linkStateOf(kin_, at.link), at.X_LS);
  };
  for (std::size_t i = 0; i < imus_.size(); ++i) {
    ImuChannel& c = imus_[i];
    fresh_[static_cast<std::size_t>(Kind::kImu)][i] = c.clock.due(steps);
    if (!c.clock.due(steps)) continue;
    place();
    c.reading = c.imu.sample(linkStateOf(kin_, c.link), gravity_W, static_cast<double>(c.clock.every()) * dt_);
  }
  for (std::size_t i = 0; i < odometry_.size(); ++i) {
    OdometryChannel& c = odometry_[i];
    fresh_[static_cast<std::size_t>(Kind::kOdometry)][i] = c.clock.due(steps);
    if (!c.clock.due(steps)) continue;
    const LinkState link = frame(c.at);
    const double elapsed = c.clock.elapsed(t);
    c.truth = exactOdom(link);
    c.report = c.noise ? c.noise->report(link, elapsed) : c.truth;
  }
  for (std::size_t i = 0; i < gnss_.size(); ++i) {
    GnssChannel& c = gnss_[i];
    fresh_[static_cast<std::size_t>(Kind::kGnss)][i] = c.clock.due(steps);
    if (!c.clock.due(steps)) continue;
    const LinkState link = frame(c.at);
    c.fix = c.gnss.report(link.p_WL, link.v_WL, c.clock.elapsed(t));
  }
  for (std::size_t i = 0; i < magnetometers_.size(); ++i) {
    MagnetometerChannel& c = magnetometers_[i];
    fresh_[static_cast<std::size_t>(Kind::kMagnetometer)][i] = c.clock.due(steps);
    if (!c.clock.due(steps)) continue;
    c.field_S = c.magnetometer.report(frame(c.at).q_WL, c.clock.elapsed(t));
  }
  bool seen = false;  // the robot's own links marked unseen, once for all its ray devices
  const auto pose = [&](const LinkMount& at) {
    place();
    if (!seen) {
      skip_.assign(scene.model().bodyCount(), 0);
      for (std::size_t k = 0; k < robot.link.size(); ++k) skip_.at(static_cast<std::size_t>(robot.first_body) + k) = 1;
      seen = true;
    }
    const Placement X_WS = kin_.X_WL[static_cast<std::size_t>(at.link)] * Placement::of(at.X_LS);
    return Pose{Quat(X_WS.R_PC), X_WS.p_PC};
  };
  const auto due = [&](Kind kind, std::size_t i, const SampleClock& clock) {
    fresh_[static_cast<std::size_t>(kind)][i] = clock.due(steps);
    return clock.due(steps);
  };
  for (std::size_t i = 0; i < lidars_.size(); ++i) {
    LidarChannel& c = lidars_[i];
    if (!due(Kind::kLidar, i, c.clock)) continue;
    if (!wanted(Kind::kLidar, i)) {
      c.lidar.pass();
      if (c.finder) c.finder->pass();
      continue;
    }
    c.lidar.scan(scene.model(), bodies, pose(c.at), skip_, c.ranges);
    const LidarSettings& s = c.lidar.settings();
    if (c.finder) c.reading = c.finder->reading(c.ranges, s.min_range, s.max_range);
  }
  for (std::size_t i = 0; i < depth_cameras_.size(); ++i) {
    DepthCameraChannel& c = depth_cameras_[i];
    if (!due(Kind::kDepthCamera, i, c.clock)) continue;
    if (wanted(Kind::kDepthCamera, i)) {
      c.camera.capture(scene.model(), bodies, pose(c.at), skip_, c.depth);
    } else {
      c.camera.pass();
    }
  }
  sampleForces(scene, r, bodies, state, steps, forces, placed);
  bool any = placed;
  for (const std::vector<char>& f : fresh_) any = any || std::find(f.begin(), f.end(), 1) != f.end();
  return any;
}

void LinkSensors::sampleForces(const Scene& scene, std::size_t r, const State& bodies, const ArticulationState& state,
                               long long steps, const StepForces& forces, bool& placed) {
  const SceneRobot& robot = scene.robots().at(r);
  const auto due = [&](Kind kind, std::size_t i, const SampleClock& clock) {
    fresh_[static_cast<std::size_t>(kind)][i] = clock.due(steps);
    return clock.due(steps);
  };
  const auto contacts = [&]() -> StepContacts& {
    if (forces.contacts == nullptr)
      throw std::invalid_argument("a force sensor is due: sample() needs the step's contacts");
    return *forces.contacts;
  };
  const auto place = [&] {
    if (!placed) kinematics(robot.model, state, kin_);
    placed = true;
  };
  std::vector<Vec6> wrench_L;  // the links' loads of the step, once for every force-torque sensor
  Eigen::VectorXd u;
  for (std::size_t i = 0; i < force_torques_.size(); ++i) {
    ForceTorqueChannel& c = force_torques_[i];
    if (!due(Kind::kForceTorque, i, c.clock)) continue;
    if (!wanted(Kind::kForceTorque, i)) {
      c.sensor.pass();
      continue;
    }
    if (u.size() == 0) {  // its contacts' and those given
      place();
      wrench_L = contactWrenches_L(robot, kin_, bodies.bodies, contacts().touching(), dt_);
      if (forces.loads != nullptr) {
        const ArticulationLoads& l = *forces.loads;
        for (std::size_t k = 0; k < wrench_L.size(); ++k) {
          if (k < l.wrench_L.size()) wrench_L[k] += l.wrench_L[k];
          if (k < l.impulse_L.size()) wrench_L[k] += l.impulse_L[k] / dt_;
        }
      }
      u = generalizedVelocity(robot.model, state);
      if (u_before_.size() != u.size()) u_before_ = u;  // no step yet: as if steady
    }
    c.wrench = c.sensor.reading(robot.model, kin_, u, u_before_, dt_, scene.model().gravity(), wrench_L);
  }
  // The link's body, if it has a collision shape (one without never touches).
  const auto bodyOf = [&](int link) {
    const auto at = std::find(robot.link.begin(), robot.link.end(), link);
    return at == robot.link.end() ? -1 : robot.first_body + static_cast<int>(at - robot.link.begin());
  };
  for (std::size_t i = 0; i < contact_sensors_.size(); ++i) {
    ContactChannel& c = contact_sensors_[i];
    if (!due(Kind::kContacts, i, c.clock) || !wanted(Kind::kContacts, i)) continue;
    const int body = bodyOf(c.at.link);
    c.pairs.clear();
    if (body < 0) continue;  // nothing touches it (and -1 is the scene's `other`: not its pairs)
    for (const ContactPairReport& p : contacts().pairs()) {
      if (p.body == body) c.pairs.push_back(p);
      if (p.other == body) {  // seen from the link: the other side of the same pair
        ContactPairReport& flipped = c.pairs.emplace_back(p);
        std::swap(flipped.body, flipped.other);
        flipped.normal_W = -p.normal_W;
        flipped.normal_force_W = -p.normal_force_W;
        flipped.friction_force_W = -p.friction_force_W;
      }
    }
    if (c.in_world) continue;
    place();  // into the frame fixed to the link
    const LinkState F = frameState(linkStateOf(kin_, c.at.link), c.at.X_LS);
    const Quat q_FW = F.q_WL.conjugate();
    for (ContactPairReport& p : c.pairs) {
      for (Vec3& q : p.points_W) q = q_FW * (q - F.p_WL);
      p.normal_W = q_FW * p.normal_W;
      p.normal_force_W = q_FW * p.normal_force_W;
      p.friction_force_W = q_FW * p.friction_force_W;
    }
  }
}

void LinkSensors::restartImus(const ArticulationModel& model, const ArticulationState& now) {
  if (imus_.empty()) return;
  kinematics(model, now, kin_);
  for (ImuChannel& c : imus_) c.imu.restart(linkStateOf(kin_, c.link));
}

void LinkSensors::restartNoise() {
  for (OdometryChannel& c : odometry_) {
    if (c.noise) c.noise->restart();
  }
  for (GnssChannel& c : gnss_) c.gnss.restart();
  for (MagnetometerChannel& c : magnetometers_) c.magnetometer.restart();
  for (LidarChannel& c : lidars_) {
    c.lidar.restart();
    if (c.finder) c.finder->restart();
  }
  for (DepthCameraChannel& c : depth_cameras_) c.camera.restart();
  for (ForceTorqueChannel& c : force_torques_) c.sensor.restart();
  u_before_.resize(0);
}

}  // namespace rigid_body_sim::core
