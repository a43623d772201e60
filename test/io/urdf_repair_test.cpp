// The URDFs users have, loaded as Gazebo and KDL load them (docs/physics.md
// §2.1): one test per class of description a strict reading refused,
// each with a robot written here (the public descriptions these classes
// come from are in bench/README.md, "Robots users have").
#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "../core/articulations/lone_robot.h"
#include "../test_util.h"
#include "rigid_body_sim/core/articulations/articulation_dynamics.h"
#include "rigid_body_sim/io/articulation_loader.h"
#include "rigid_body_sim/io/joint_start.h"

namespace rigid_body_sim::test {
namespace {

using core::ArticulationModel;
using core::ArticulationState;

const Vec3 kG(0, 0, -9.81);

std::string inertial(double mass, const std::string& xyz = "0 0 0",
                     const std::string& inertia = "ixx='0.02' iyy='0.02' izz='0.001' ixy='0' ixz='0' iyz='0'") {
  return "<inertial><origin xyz='" + xyz + "'/><mass value='" + std::to_string(mass) + "'/><inertia " + inertia +
         "/></inertial>";
}

std::string link(const std::string& name, const std::string& inside = "") {
  return "<link name='" + name + "'>" + inside + "</link>";
}

std::string joint(const std::string& name, const std::string& type, const std::string& parent, const std::string& child,
                  const std::string& xyz, const std::string& inside = "<axis xyz='0 1 0'/>") {
  return "<joint name='" + name + "' type='" + type + "'><parent link='" + parent + "'/><child link='" + child +
         "'/><origin xyz='" + xyz + "'/>" + (type == "fixed" ? "" : inside) + "</joint>";
}

/// A double pendulum hanging from the world: rods of 1 kg, 0.5 m apart.
std::string doublePendulum(const std::string& extra = "") {
  return "<robot name='double'>" + link("world") + joint("shoulder", "continuous", "world", "upper", "0 0 2") +
         link("upper", inertial(1.0, "0 0 -0.25")) + joint("elbow", "continuous", "upper", "lower", "0 0 -0.5") +
         link("lower", inertial(1.0, "0 0 -0.25")) + extra + "</robot>";
}

ArticulationModel load(const std::string& xml, std::vector<std::string>* notes = nullptr, bool repair = true) {
  return io::loadArticulationString(xml, "robot.urdf", "", io::UrdfOptions{repair, notes});
}

/// q and v after `steps` steps of 1 ms from the rest state with q(0) = 1 rad.
ArticulationState swing(const ArticulationModel& model, int steps) {
  ArticulationState state = core::restState(model);
  state.q(0) = 1.0;
  LoneRobot alone(model, kG, 1e-3);
  for (int n = 0; n < steps; ++n) alone.step(state);
  return state;
}

double energy(const ArticulationModel& model, const ArticulationState& state) {
  const core::ArticulationKinematics kin = core::kinematics(model, state);
  return core::kineticEnergy(model, kin) + core::potentialEnergy(model, kin, kG);
}

TEST(MasslessFrames, MoveAsTheRobotWithoutThemBitForBit) {
  // A tool frame fixed to the lower rod, a sensor on a joint of its own
  // (nothing hangs from it but massless frames: held), both without
  // <inertial>, as force_torque_sensor and camera frames come.
  const std::string frames = joint("tool_mount", "fixed", "lower", "tool", "0 0 -0.5") + link("tool") +
                             joint("pan", "revolute", "tool", "camera", "0 0 -0.1",
                                   "<axis xyz='0 0 1'/><limit lower='0.3' upper='1' effort='1' velocity='1'/>") +
                             link("camera") + joint("optical", "fixed", "camera", "optical_frame", "0.05 0 0") +
                             link("optical_frame");
  std::vector<std::string> notes;
  const ArticulationModel with = load(doublePendulum(frames), &notes);
  const ArticulationModel without = load(doublePendulum());
  ASSERT_EQ(with.jointCount(), 2);
  ASSERT_EQ(with.held.size(), 1u);
  EXPECT_EQ(with.held[0].name, "pan");
  EXPECT_EQ(with.held[0].position, 0.3);  // its rest position: the limit nearest 0
  // The held link is a fixed frame of the lower rod, turned by 0.3 rad about z.
  const core::FixedLink* camera = nullptr;
  for (const core::FixedLink& f : with.links[2].fixed_links) camera = f.name == "camera" ? &f : camera;
  ASSERT_NE(camera, nullptr);
  EXPECT_EQ(camera->parent, "lower");
  EXPECT_LT((camera->X_PK.translation - Vec3(0, 0, -0.6)).norm(), 1e-15);
  EXPECT_NEAR(camera->X_PK.rotation.angularDistance(Quat(Eigen::AngleAxisd(0.3, Vec3::UnitZ()))), 0.0, 1e-15);
  const ArticulationState a = swing(with, 3000), b = swing(without, 3000);
  EXPECT_TRUE((a.q.array() == b.q.array()).all() && (a.v.array() == b.v.array()).all());
  ASSERT_EQ(notes.size(), 1u);  // everything repaired, in one message
  expectContains(
      notes[0], {"robot.urdf", "3 links without <inertial> are massless frames", "'tool', 'camera' and 'optical_frame'",
                 "1 joint moves only massless links", "'pan' at 0.3", "joint_states"});
  // Set at the start, it is refused, saying why.
  io::InitialJoints start;
  start.positions = {{"pan", 0.5}};
  expectThrowsWith<io::ConfigError>(
      [&] {
        ArticulationState s = core::restState(with);
        io::startJoints(with, start, core::SpeedLimits{}, "initial", s);
      },
      {"initial.joint_positions.pan", "joint 'pan' is held: it moves only massless links"});
  // Strictly, every one of them is refused, in one message.
  expectThrowsWith<io::UrdfError>(
      [&] { load(doublePendulum(frames), nullptr, false); },
      {"link 'tool' has no <inertial>", "link 'camera' has no <inertial>", "joint 'pan' moves only massless links"});
}

TEST(MasslessFrames, AMasslessLinkBetweenTwoJointsIsAGimbal) {
  // A spherical pendulum built as URDFs build it: two revolute joints, the
  // link between them massless. KDL reads it so; it swings keeping energy.
  const std::string gimbal = "<robot name='gimbal'>" + link("world") +
                             joint("pitch", "continuous", "world", "ring", "0 0 2") + link("ring") +
                             joint("roll", "continuous", "ring", "bob", "0 0 0", "<axis xyz='1 0 0'/>") +
                             link("bob", inertial(2.0, "0 0 -0.8",
                                                  "ixx='0.01' iyy='0.01' izz='0.01' ixy='0' ixz='0' "
                                                  "iyz='0'")) +
                             "</robot>";
  const ArticulationModel model = load(gimbal);
  ASSERT_EQ(model.jointCount(), 2);
  EXPECT_EQ(model.links[1].mass.mass, 0.0);
  ArticulationState state = core::restState(model);
  state.q << 0.6, 0.4;
  state.v << 0.0, 1.5;
  const double start = energy(model, state);
  double worst = 0.0;
  LoneRobot alone(model, kG, 1e-3);
  for (int n = 0; n < 5000; ++n) {
    ASSERT_TRUE(alone.step(state));
    worst = std::max(worst, std::abs(energy(model, state) - start));
  }
  EXPECT_LT(worst, 2e-3 * std::abs(start));
}

TEST(MasslessFrames, AJointThatMovesNoMassOrInertiaIsRefusedNamingIt) {
  // Two joints on one axis with a massless link between: the second moves
  // nothing the first does not (the mass matrix is singular).
  const std::string twice =
      "<robot name='twice'>" + link("world") + joint("first", "continuous", "world", "a", "0 0 2") + link("a") +
      joint("second", "continuous", "a", "b", "0 0 0") + link("b", inertial(1.0, "0 0 -0.5")) + "</robot>";
  expectThrowsWith<io::UrdfError>([&] { load(twice); },
                                  {"robot.urdf", "joint 'second' moves no mass or inertia", "singular mass matrix"});
}

TEST(PointMassLinks, AreGivenAWaterSpheresInertiaAndSwing) {
  // icub's head: mass without inertia, on a joint whose axis passes through
  // it (no moment about the axis: a singular mass matrix without the repair).
  const std::string head = "<robot name='neck'>" + link("world") +
                           joint("yaw", "continuous", "world", "head", "0 0 1", "<axis xyz='0 0 1'/>") +
                           link("head", inertial(1.3, "0 0 0.1", "ixx='0' iyy='0' izz='0' ixy='0' ixz='0' iyz='0'")) +
                           "</robot>";
  std::vector<std::string> notes;
  const ArticulationModel model = load(head, &notes);
  EXPECT_TRUE((model.links[1].mass.I_C_F.array() == core::waterSphereInertia(1.3).array()).all());
  ASSERT_EQ(notes.size(), 1u);
  expectContains(notes[0], {"'head' 1.3 kg", "solid sphere of water"});
  // Strictly, the point mass on its own axis moves nothing: refused.
  expectThrowsWith<io::UrdfError>([&] { load(head, nullptr, false); }, {"joint 'yaw' moves no mass or inertia"});
}

TEST(MovingLinksWithoutMass, AreGivenTheirShapesFullOfWater) {
  // A kinematic description: the rod has a <collision> but no <inertial>.
  // MuJoCo's compiler gives such a body its geoms' mass at 1000 kg/m³; so
  // does the loader: a 0.04 × 0.04 × 0.5 m box of water, 0.8 kg.
  const std::string rod = "<robot name='kinematic'>" + link("world") +
                          joint("pivot", "continuous", "world", "rod", "0 0 2") +
                          link("rod",
                               "<collision><origin xyz='0 0 -0.25'/><geometry><box size='0.04 0.04 0.5'/>"
                               "</geometry></collision>") +
                          "</robot>";
  std::vector<std::string> notes;
  const ArticulationModel model = load(rod, &notes);
  const core::MassProperties& m = model.links[1].mass;
  EXPECT_NEAR(m.mass, 0.8, 1e-12);
  EXPECT_LT((m.p_FC - Vec3(0, 0, -0.25)).norm(), 1e-15);
  EXPECT_LT((m.I_C_F - boxInertia(0.8, Vec3(0.02, 0.02, 0.25))).norm(), 1e-15);
  ASSERT_EQ(notes.size(), 1u);
  expectContains(notes[0], {"1 moving link without mass was given the mass of its collision shapes filled with water",
                            "'rod' 0.8 kg"});
  expectThrowsWith<io::UrdfError>([&] { load(rod, nullptr, false); }, {"link 'rod' has no <inertial>"});
}

TEST(MasslessFloatingBase, IsFixedToTheWorldAsBulletReadsIt) {
  // pybullet_data's kuka_iiwa: a base of mass 0 (Bullet's static base)
  // under a massive arm. It cannot float: it is fixed where the start puts it.
  const std::string arm =
      "<robot name='iiwa'><link name='link_0'><inertial><mass value='0'/><inertia ixx='0.05' "
      "iyy='0.06' izz='0.03' ixy='0' ixz='0' iyz='0'/></inertial></link>" +
      joint("joint_1", "revolute", "link_0", "link_1", "0 0 0.1575",
            "<axis xyz='0 0 1'/><limit lower='-2.9' upper='2.9' effort='300' velocity='10'/>") +
      link("link_1", inertial(4.0, "0 -0.03 0.12")) + "</robot>";
  std::vector<std::string> notes;
  const ArticulationModel model = load(arm, &notes);
  EXPECT_TRUE(model.fixed_base);
  EXPECT_EQ(model.links[0].name, "link_0");
  ASSERT_EQ(notes.size(), 1u);
  expectContains(notes[0], {"the base 'link_0' has no mass and is fixed to the world", "Bullet"});
  expectThrowsWith<io::UrdfError>([&] { load(arm, nullptr, false); }, {"the base 'link_0' has no mass"});
}

TEST(NearlySingularInertia, IsRaisedToAMillionthOfItsLargestMoment) {
  // Valid (a thin rod) but too thin for a body: the least moment is raised.
  const std::string rod = "<robot name='thin'>" + link("world") +
                          joint("pivot", "continuous", "world", "rod", "0 0 2") +
                          link("rod", inertial(1.0, "0 0 -0.25",
                                               "ixx='1e-13' iyy='0.02' izz='0.02' ixy='0' ixz='0' "
                                               "iyz='0'")) +
                          "</robot>";
  std::vector<std::string> notes;
  const ArticulationModel model = load(rod, &notes);
  EXPECT_NEAR(model.links[1].mass.I_C_F(0, 0), 2e-8, 1e-20);
  EXPECT_EQ(model.links[1].mass.I_C_F(1, 1), 0.02);
  ASSERT_EQ(notes.size(), 1u);
  expectContains(notes[0], {"'rod' [1e-13, 0.02, 0.02] -> [2e-08, 0.02, 0.02]"});
}

TEST(MimicOfNoJoint, IsDroppedAndSaid) {
  const std::string xml = doublePendulum().insert(doublePendulum().find("</joint>", doublePendulum().find("elbow")),
                                                  "<mimic joint='index_q1'/>");
  std::vector<std::string> notes;
  const ArticulationModel model = load(xml, &notes);
  EXPECT_EQ(model.links[2].mimic.joint, -1);
  ASSERT_EQ(notes.size(), 1u);
  expectContains(notes[0], {"1 <mimic> names no joint", "'elbow' -> 'index_q1'"});
  expectThrowsWith<io::UrdfError>([&] { load(xml, nullptr, false); },
                                  {"joint 'elbow' <mimic joint> = 'index_q1'", "no moving joint has that name"});
}

// roboticsgroup's mimic-joint plugin (grippers' fingers: 5 of 55 public
// robots) is the URDF's <mimic>: the elbow follows the shoulder at its
// multiplier and offset as the pendulum swings; one naming no joint is refused.
TEST(MimicJointPlugin, IsTheUrdfsMimic) {
  const std::string xml = doublePendulum(
      "<gazebo><plugin name='mimic_elbow' filename='libroboticsgroup_upatras_gazebo_mimic_joint_plugin.so'>"
      "<joint>shoulder</joint><mimicJoint>elbow</mimicJoint><multiplier>-0.5</multiplier><offset>0.1</offset>"
      "<hasPID/><maxEffort>10</maxEffort></plugin></gazebo>");
  std::vector<std::string> notes;
  const ArticulationModel model = load(xml, &notes);
  EXPECT_TRUE(notes.empty()) << notes.at(0);
  EXPECT_EQ(model.links[2].mimic.joint, 1);
  EXPECT_EQ(model.links[2].mimic.multiplier, -0.5);
  EXPECT_EQ(model.links[2].mimic.offset, 0.1);
  const ArticulationState s = swing(model, 500);
  EXPECT_GT(std::abs(s.q(0) - 1.0), 0.1);  // it swung
  EXPECT_NEAR(s.q(1), -0.5 * s.q(0) + 0.1, 1e-6);
  expectThrowsWith<io::UrdfError>(
      [&] {
        load(
            doublePendulum("<gazebo><plugin name='m' filename='libroboticsgroup_gazebo_mimic_joint_plugin.so'>"
                           "<joint>shoulder</joint><mimicJoint>wrist</mimicJoint></plugin></gazebo>"));
      },
      {"<plugin name=\"m\">: the robot has no joint 'wrist'"});
}

// Gazebo markup's "never slip" (PR2's <mu1 value="100.0"/>, turtlebot3's
// 10000, tiago's 1e15): read as the largest coefficient, 10, and said; the
// smaller of mu1 and mu2 is the link's; refused when not repairing.
TEST(FrictionAboveTheLargest, IsReadAsItAndSaid) {
  const std::string xml = doublePendulum(
      "<gazebo reference='upper'><mu1 value='100.0'/><mu2 value='1e15'/></gazebo>"
      "<gazebo reference='lower'><mu1>0.7</mu1><mu2>1e4</mu2></gazebo>");
  std::vector<std::string> notes;
  const ArticulationModel model = load(xml, &notes);
  EXPECT_EQ(model.links[1].surface_friction, std::optional<double>(10.0));
  EXPECT_EQ(model.links[2].surface_friction, std::optional<double>(0.7));
  ASSERT_EQ(notes.size(), 1u);
  expectContains(notes[0],
                 {"3 friction coefficients of Gazebo markup above 10", "<gazebo reference=\"upper\"> <mu1> = '100.0'",
                  "<mu2> = '1e15'", "<gazebo reference=\"lower\"> <mu2> = '1e4'"});
  expectThrowsWith<io::UrdfError>([&] { load(xml, nullptr, false); },
                                  {"<gazebo reference=\"upper\"> <mu1> = '100.0' is above 10", "urdf.repair: true"});
}

// Markup for Gazebo that nothing here reads (sensors, plugins, contact
// tuning, transmissions) is named in one note, each kind once with its links
// or names, and loads as before, repairing or not; <material> (drawing) and
// <mu1>/<mu2> (read) are not named.
TEST(GazeboMarkupNothingReads, IsNamedInOneNote) {
  const std::string xml = doublePendulum(
      "<gazebo reference='upper'><material>Gazebo/Red</material><kp>1e6</kp>"
      "<sensor type='ray' name='scan'><plugin name='laser' filename='libgazebo_ros_laser.so'/></sensor></gazebo>"
      "<gazebo reference='lower'><kp>1e5</kp><mu1>0.7</mu1></gazebo>"
      "<gazebo><plugin name='gazebo_ros_control' filename='libgazebo_ros_control.so'/></gazebo>"
      "<transmission name='t1'><type>transmission_interface/SimpleTransmission</type></transmission>");
  for (const bool repair : {true, false}) {
    std::vector<std::string> notes;
    const ArticulationModel model = load(xml, &notes, repair);
    EXPECT_EQ(model.links[2].surface_friction, std::optional<double>(0.7));
    ASSERT_EQ(notes.size(), 1u);
    expectContains(notes[0], {"robot.urdf: markup for Gazebo that nothing here simulates", "<kp> ('upper' and 'lower')",
                              "<sensor type=\"ray\"> libgazebo_ros_laser.so ('upper')",
                              "<plugin> libgazebo_ros_control.so ('gazebo_ros_control')", "<transmission> ('t1')"});
    EXPECT_EQ(notes[0].find("material"), std::string::npos) << notes[0];
    EXPECT_EQ(notes[0].find("mu1"), std::string::npos) << notes[0];
  }
  std::vector<std::string> notes;
  load(doublePendulum("<gazebo reference='upper'><material>Gazebo/Red</material><mu1>0.5</mu1></gazebo>"), &notes);
  EXPECT_TRUE(notes.empty()) << notes.front();
}

// A tag that says what Gazebo does anyway (Ridgeback's base_link has
// <gravity>true) told of nothing missing; one that asks for what is not run
// here (gravity off) is still named.
TEST(GazeboMarkupNothingReads, ATagThatSaysGazebosDefaultIsNotNamed) {
  std::vector<std::string> notes;
  load(doublePendulum("<gazebo reference='upper'><gravity>true</gravity><selfCollide>false</selfCollide>"
                      "<static>0</static><provideFeedback>true</provideFeedback></gazebo>"),
       &notes);
  EXPECT_TRUE(notes.empty()) << notes.front();
  load(doublePendulum("<gazebo reference='upper'><gravity>false</gravity><selfCollide>true</selfCollide></gazebo>"),
       &notes);
  ASSERT_EQ(notes.size(), 1u);
  expectContains(notes[0], {"<gravity> ('upper')", "<selfCollide> ('upper')"});
}

TEST(ZeroOutsideTheLimits, StartsAtTheNearestLimitWithoutAnEnergyJump) {
  // Kinova's joint_2, limits [0.82, 5.46]: its zero is no legal pose. The
  // rest state puts it at 0.82 and says so; held there against the limit by
  // gravity, it gains nothing on the first step (it used to be snapped from
  // 0 to the limit by the first step: 3.7 J became 7.2 J).
  const std::string arm = "<robot name='arm'>" + link("world") +
                          joint("joint_2", "revolute", "world", "rod", "0 0 2",
                                "<axis xyz='0 1 0'/><limit lower='0.82' upper='5.46' effort='10' velocity='2'/>") +
                          link("rod", inertial(1.5, "0 0 -0.5")) + "</robot>";
  std::vector<std::string> notes;
  const ArticulationModel model = load(arm, &notes);
  ArticulationState state = core::restState(model);
  EXPECT_EQ(state.q(0), 0.82);
  ASSERT_EQ(notes.size(), 1u);
  expectContains(notes[0], {"robot.urdf: 1 joint has its zero outside the limits", "'joint_2' 0 -> 0.82",
                            "(limits [0.82, 5.46])"});
  const double start = energy(model, state);
  LoneRobot alone(model, kG, 1e-3);
  for (int n = 0; n < 1000; ++n) {
    alone.step(state);
    ASSERT_LE(energy(model, state), start + 1e-9) << "step " << n;
    ASSERT_GE(state.q(0), 0.82 - 1e-6);
  }
}

}  // namespace
}  // namespace rigid_body_sim::test
