// Articulated motion against MuJoCo 2.2.2 and Bullet 3.24's btMultiBody, the
// same models in the same run (issue 33): a 7-joint arm (links 0.3 m, 2 kg,
// 8 cm in radius, joints about z and y in turn) and a 30-link chain (0.1 m,
// 0.1 kg, every joint about y),
// hanging under gravity, no contacts, Δt = 1 ms, undamped. Per engine: ns
// per step (medians of interleaved rounds of `steps` steps each) and the
// energy over 20 s (the change at the end and the largest, in J). MuJoCo
// runs its Euler integrator (velocities, then positions with them), Bullet
// its multibody defaults less damping and velocity clamps. A peer is built
// only where its package is (libmujoco-dev, libbullet-dev).
// "rigid_body_sim scene" steps the base as the one robot of a scene.
// "rigid_body_sim Euler" is our kernels on MuJoCo's algorithm (oursKernels):
// the share of our step that is the corrector's.
// Then contacts: the shipped four-wheeled base (urdf/four_wheeler.urdf) on
// the ground, its wheels spun at 10 rad/s from rest, friction 0.5: ns per
// step over `steps` steps (its wheels slip, then it rolls), and at 2 s its
// speed against ω r (1 = rolling); against MuJoCo on the same model (its
// default soft contacts, condim 3).
// Usage: articulation_bench [rounds] [steps]   (default 7 rounds of 20000)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "median.h"
#include "rigid_body_sim/core/articulations/articulation_dynamics.h"
#include "rigid_body_sim/core/articulations/articulation_step.h"
#include "rigid_body_sim/core/articulations/scene.h"
#include "rigid_body_sim/io/articulation_loader.h"

#ifdef RBS_WITH_MUJOCO
#include <mujoco/mujoco.h>
#endif
#ifdef RBS_WITH_BULLET
#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyConstraintSolver.h>
#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>
#include <btBulletDynamicsCommon.h>
#endif

namespace {

using rigid_body_sim::bench::median;

using namespace rigid_body_sim::core;

constexpr double kDt = 1e-3;
constexpr double kG = 9.81;

/// A hanging serial chain: link i a rod of length L and mass m along −z from
/// its joint, the joint axes given per link (in the link's axes, all links
/// aligned at q = 0), every joint at q0 at the start.
struct ChainSpec {
  const char* name;
  int links;
  double length, mass, radius, q0;
  std::vector<Vec3> axes;  // cycled

  double Ixx() const { return mass * (3 * radius * radius + length * length) / 12.0; }
  double Izz() const { return mass * radius * radius / 2.0; }
  Vec3 axis(int i) const { return axes[i % axes.size()]; }
};

struct Engine {
  std::function<void()> step;
  std::function<double()> energy;  // J
};

std::shared_ptr<ArticulationModel> chainModel(const ChainSpec& c) {
  auto model = std::make_shared<ArticulationModel>();
  model->fixed_base = true;
  model->links.push_back({});
  model->links[0].name = "world";
  for (int i = 0; i < c.links; ++i) {
    ArticulatedLink l;
    l.name = "link" + std::to_string(i);
    l.joint = "joint" + std::to_string(i);
    l.parent = i;
    l.axis_J = c.axis(i);
    if (i > 0) l.X_PJ.translation = Vec3(0, 0, -c.length);
    l.mass.mass = c.mass;
    l.mass.p_FC = Vec3(0, 0, -c.length / 2);
    l.mass.I_C_F = Vec3(c.Ixx(), c.Ixx(), c.Izz()).asDiagonal();
    model->links.push_back(l);
  }
  checkArticulation(*model);
  return model;
}

/// The chain stepped by `step(model, state, workspace, g)`, its energy
/// the articulation's.
template <class Step>
Engine chainEngine(const ChainSpec& c, Step step) {
  const std::shared_ptr<ArticulationModel> model = chainModel(c);
  auto state = std::make_shared<ArticulationState>(restState(*model));
  state->q.setConstant(c.q0);
  auto ws = std::make_shared<ArticulationWorkspace>();
  const Vec3 g(0, 0, -kG);
  return {[model, state, ws, g, step] { step(*model, *state, *ws, g); },
          [model, state, g] {
            const ArticulationKinematics kin = kinematics(*model, *state);
            return kineticEnergy(*model, kin) + potentialEnergy(*model, kin, g);
          }};
}

/// The chain as the one robot of a scene, stepped by the one step (stepScene)
/// as rbsim and the node step it.
Engine ours(const ChainSpec& c) {
  const std::shared_ptr<ArticulationModel> model = chainModel(c);
  ModelSpec spec;
  spec.dt = kDt;
  spec.gravity_W = Vec3(0, 0, -kG);
  ArticulationState start = restState(*model);
  start.q.setConstant(c.q0);
  auto scene = std::make_shared<Scene>(spec, std::vector<Scene::RobotSpec>{{"chain", *model}});
  auto state = std::make_shared<SceneState>(sceneState(*scene, State(), {start}));
  auto ws = std::make_shared<SceneWorkspace>();
  const Vec3 g = spec.gravity_W;
  return {[=] { stepScene(*scene, *state, {}, *ws); },
          [=] {
            const ArticulationKinematics kin = kinematics(*model, state->robots[0]);
            return kineticEnergy(*model, kin) + potentialEnergy(*model, kin, g);
          }};
}

/// Our kernels on MuJoCo's algorithm, from the public dynamics API: the
/// kinematics, M by composite rigid bodies, its factor along the tree, the
/// bias by recursive Newton-Euler, then v += h M⁻¹(−c) and q += h v. What a step
/// of ours costs without the symplectic corrector's passes, the momenta it
/// carries and the rows: the part of the step MuJoCo's Euler also does.
Engine oursKernels(const ChainSpec& c) {
  return chainEngine(c, [](const ArticulationModel& m, ArticulationState& s, ArticulationWorkspace& ws, const Vec3& g) {
    kinematics(m, s, ws.kin);
    massMatrix(m, ws.kin, ws.dynamics, ws.A);
    ws.factor.compute(ws.A, m);
    ws.u = generalizedVelocity(m, s);
    biasForcesAt(m, ws.kin, ws.u, g, {}, ws.dynamics, ws.bias);
    ws.factor.solveInPlace(ws.bias);
    ws.u -= kDt * ws.bias;
    setGeneralizedVelocity(m, ws.u, s);
    s.q += kDt * s.v;
  });
}

#ifdef RBS_WITH_MUJOCO
/// MuJoCo's model of an MJCF text (written to /tmp: MuJoCo 2.2 reads files).
mjModel* loadMjcf(const std::string& xml, const std::string& name) {
  const std::string path = "/tmp/rbs_articulation_bench_" + name + ".xml";
  std::ofstream(path) << xml;
  char error[1000] = "";
  mjModel* m = mj_loadXML(path.c_str(), nullptr, error, sizeof error);
  if (m == nullptr) {
    std::fprintf(stderr, "MuJoCo: %s\n", error);
    std::exit(1);
  }
  return m;
}

Engine mujoco(const ChainSpec& c) {
  std::string xml =
      "<mujoco><option timestep='0.001' integrator='Euler'><flag contact='disable' energy='enable'/>"
      "</option><worldbody>";
  std::string close;
  char buf[512];
  for (int i = 0; i < c.links; ++i) {
    const Vec3 a = c.axis(i);
    std::snprintf(buf, sizeof buf,
                  "<body pos='0 0 %.17g'><joint type='hinge' axis='%g %g %g'/>"
                  "<inertial pos='0 0 %.17g' mass='%.17g' diaginertia='%.17g %.17g %.17g'/>",
                  i == 0 ? 0.0 : -c.length, a.x(), a.y(), a.z(), -c.length / 2, c.mass, c.Ixx(), c.Ixx(), c.Izz());
    xml += buf;
    close += "</body>";
  }
  xml += close + "</worldbody></mujoco>";
  mjModel* m = loadMjcf(xml, c.name);
  mjData* d = mj_makeData(m);
  for (int i = 0; i < c.links; ++i) d->qpos[i] = c.q0;
  mj_forward(m, d);
  return {[m, d] { mj_step(m, d); },
          [m, d] {
            mj_energyPos(m, d);
            mj_energyVel(m, d);
            return d->energy[0] + d->energy[1];
          }};
}
#endif

#ifdef RBS_WITH_BULLET
struct BulletChain {
  btDefaultCollisionConfiguration config;
  btCollisionDispatcher dispatcher{&config};
  btDbvtBroadphase broadphase;
  btMultiBodyConstraintSolver solver;
  btMultiBodyDynamicsWorld world{&dispatcher, &broadphase, &solver, &config};
  std::unique_ptr<btMultiBody> body;
  ChainSpec spec;
};

Engine bullet(const ChainSpec& c) {
  auto b = std::make_shared<BulletChain>();
  b->spec = c;
  b->world.setGravity(btVector3(0, 0, -kG));
  b->body = std::make_unique<btMultiBody>(c.links, 1.0, btVector3(1, 1, 1), true, false);
  const btVector3 inertia(c.Ixx(), c.Ixx(), c.Izz());
  for (int i = 0; i < c.links; ++i) {
    const Vec3 a = c.axis(i);
    b->body->setupRevolute(i, c.mass, inertia, i - 1, btQuaternion::getIdentity(), btVector3(a.x(), a.y(), a.z()),
                           btVector3(0, 0, i == 0 ? 0.0 : -c.length / 2), btVector3(0, 0, -c.length / 2), true);
  }
  b->body->finalizeMultiDof();
  b->body->setLinearDamping(0);
  b->body->setAngularDamping(0);
  b->body->setUseGyroTerm(true);
  b->body->setMaxCoordinateVelocity(1e30);
  b->body->setCanSleep(false);
  for (int i = 0; i < c.links; ++i) b->body->setJointPos(i, c.q0);
  b->world.addMultiBody(b->body.get());
  return {[b] { b->world.stepSimulation(kDt, 0, kDt); },
          [b] {
            const btMultiBody& mb = *b->body;
            const int n = mb.getNumLinks();
            std::vector<btVector3> omega(n + 1), vel(n + 1);
            mb.compTreeLinkVelocities(omega.data(), vel.data());
            double energy = 0.0;
            for (int i = 0; i < n; ++i) {
              const btVector3& I = mb.getLinkInertia(i);
              const btVector3& w = omega[i + 1];
              energy += 0.5 * mb.getLinkMass(i) * vel[i + 1].length2() +
                        0.5 * (I.x() * w.x() * w.x() + I.y() * w.y() * w.y() + I.z() * w.z() * w.z());
              energy += mb.getLinkMass(i) * kG * mb.localPosToWorld(i, btVector3(0, 0, 0)).z();
            }
            return energy;
          }};
}
#endif

/// A wheeled base as an engine runs it: a step, and (base speed, ω r).
struct Roller {
  std::function<void()> step;
  std::function<std::pair<double, double>()> speeds;  // m/s
};

constexpr double kWheelRadius = 0.1, kWheelSpin = 10.0, kFriction = 0.5;

/// The base as the one robot of a scene, stepped by the one step (its
/// contacts in the scene's solve, warm started).
Roller oursRollingInAScene() {
  ArticulationModel model =
      rigid_body_sim::io::loadArticulationFile(std::string(RBS_SOURCE_DIR) + "/urdf/four_wheeler.urdf");
  ModelSpec ground;
  ground.scene = {Sdf::plane(Vec3::UnitZ())};
  ground.contact.friction = kFriction;
  ground.sleep.enabled = false;
  ArticulationState start = restState(model, Pose{Quat::Identity(), Vec3(0, 0, kWheelRadius)});
  start.v.setConstant(kWheelSpin);
  auto scene = std::make_shared<Scene>(ground, std::vector<Scene::RobotSpec>{{"base", std::move(model)}});
  auto state = std::make_shared<SceneState>(sceneState(*scene, State(), {start}));
  auto ws = std::make_shared<SceneWorkspace>();
  return {[=] { stepScene(*scene, *state, {}, *ws); },
          [=] { return std::make_pair(state->robots[0].V_B(3), kWheelRadius * state->robots[0].v.mean()); }};
}

#ifdef RBS_WITH_MUJOCO
Roller mujocoRolling() {
  std::string xml =
      "<mujoco><option timestep='0.001' integrator='Euler'/><worldbody>"
      "<geom type='plane' size='0 0 1' friction='0.5 0.005 0.0001'/>"
      "<body pos='0 0 0.1'><freejoint/>"
      "<inertial pos='0 0 0' mass='5' diaginertia='0.07083333333333333 0.15416666666666667 0.21666666666666667'/>";
  const double xs[4] = {0.2, 0.2, -0.2, -0.2}, ys[4] = {0.25, -0.25, 0.25, -0.25};
  char buf[512];
  for (int i = 0; i < 4; ++i) {
    std::snprintf(buf, sizeof buf,
                  "<body pos='%g %g 0'><joint type='hinge' axis='0 1 0'/>"
                  "<inertial pos='0 0 0' mass='0.5' diaginertia='0.0013541666666666667 0.0025 0.0013541666666666667'/>"
                  "<geom type='cylinder' size='0.1 0.025' euler='90 0 0' friction='0.5 0.005 0.0001'/></body>",
                  xs[i], ys[i]);
    xml += buf;
  }
  xml += "</body></worldbody></mujoco>";
  mjModel* m = loadMjcf(xml, "wheels");
  mjData* d = mj_makeData(m);
  for (int i = 0; i < 4; ++i) d->qvel[6 + i] = kWheelSpin;  // after the free joint's 6
  mj_forward(m, d);
  return {[m, d] { mj_step(m, d); },
          [m, d] {
            const double spin = (d->qvel[6] + d->qvel[7] + d->qvel[8] + d->qvel[9]) / 4.0;
            return std::make_pair(d->qvel[0], kWheelRadius * spin);  // the free joint's linear velocity, world x
          }};
}
#endif

}  // namespace

int main(int argc, char** argv) {
  const int rounds = argc > 1 ? std::atoi(argv[1]) : 7;
  const int steps = argc > 2 ? std::atoi(argv[2]) : 20000;
  const std::vector<ChainSpec> models = {
      {"arm7", 7, 0.3, 2.0, 0.08, 0.3, {Vec3::UnitZ(), Vec3::UnitY()}},
      {"chain30", 30, 0.1, 0.1, 0.01, 0.02, {Vec3::UnitY()}},
  };
  std::vector<std::pair<const char*, std::function<Engine(const ChainSpec&)>>> engines = {
      {"rigid_body_sim", ours}, {"rigid_body_sim Euler", oursKernels}};
#ifdef RBS_WITH_MUJOCO
  engines.push_back({"MuJoCo 2.2.2", mujoco});
#endif
#ifdef RBS_WITH_BULLET
  engines.push_back({"Bullet 3.24 btMultiBody", bullet});
#endif
  std::printf("%-8s %-24s %12s %14s %14s\n", "model", "engine", "ns/step", "ΔE at 20 s", "max |ΔE|");
  for (const ChainSpec& c : models) {
    std::vector<std::vector<double>> times(engines.size());
    for (int r = 0; r < rounds; ++r) {
      for (std::size_t e = 0; e < engines.size(); ++e) {  // interleaved
        Engine engine = engines[e].second(c);
        const auto t0 = std::chrono::steady_clock::now();
        for (int k = 0; k < steps; ++k) engine.step();
        times[e].push_back(std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - t0).count() /
                           steps);
      }
    }
    for (std::size_t e = 0; e < engines.size(); ++e) {
      Engine engine = engines[e].second(c);
      const double e0 = engine.energy();
      double worst = 0.0, last = 0.0;
      for (int k = 0; k < static_cast<int>(20.0 / kDt); ++k) {
        engine.step();
        last = engine.energy() - e0;
        if (std::isfinite(last)) worst = std::max(worst, std::abs(last));
      }
      std::printf("%-8s %-24s %12.0f %14.4g %14.4g\n", c.name, engines[e].first, median(times[e]), last, worst);
    }
  }
  // Contacts: the wheeled base.
  std::vector<std::pair<const char*, std::function<Roller()>>> rollers = {{"rigid_body_sim", oursRollingInAScene}};
#ifdef RBS_WITH_MUJOCO
  rollers.push_back({"MuJoCo 2.2.2", mujocoRolling});
#endif
  std::printf("\n%-8s %-24s %12s %14s %14s\n", "model", "engine", "ns/step", "v at 2 s", "v / (ω r)");
  std::vector<std::vector<double>> times(rollers.size());
  for (int r = 0; r < rounds; ++r) {
    for (std::size_t e = 0; e < rollers.size(); ++e) {  // interleaved
      Roller roller = rollers[e].second();
      const auto t0 = std::chrono::steady_clock::now();
      for (int k = 0; k < steps; ++k) roller.step();
      times[e].push_back(std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - t0).count() /
                         steps);
    }
  }
  for (std::size_t e = 0; e < rollers.size(); ++e) {
    Roller roller = rollers[e].second();
    for (int k = 0; k < static_cast<int>(2.0 / kDt); ++k) roller.step();
    const auto [v, omega_r] = roller.speeds();
    std::printf("%-8s %-24s %12.0f %14.4g %14.6f\n", "wheels4", rollers[e].first, median(times[e]), v, v / omega_r);
  }
  return 0;
}
