// The URDF loader: lumping by fixed joints, the inertial frame, and refusals
// that name the element. Test models are inline, as in MuJoCo's tests.
#include "rigid_body_sim/io/urdf_loader.h"

#include <gtest/gtest.h>

#include "../test_util.h"
#include "rigid_body_sim/core/bodies/inertia.h"
#include "rigid_body_sim/core/bodies/state.h"
#include "rigid_body_sim/io/input_bounds.h"

namespace rigid_body_sim::test {
namespace {

std::string robot(const std::string& body) { return "<robot name='r'>" + body + "</robot>"; }

std::string link(const std::string& name, const std::string& inertial) {
  return "<link name='" + name + "'>" + inertial + "</link>";
}

std::string inertial(double mass, const std::string& origin = "",
                     const std::string& inertia = "ixx='0.1' iyy='0.2' izz='0.25' ixy='0' ixz='0' iyz='0'") {
  return "<inertial>" + origin + "<mass value='" + std::to_string(mass) + "'/><inertia " + inertia + "/></inertial>";
}

std::string joint(const std::string& name, const std::string& type, const std::string& parent, const std::string& child,
                  const std::string& xyz, const std::string& rpy = "0 0 0") {
  return "<joint name='" + name + "' type='" + type + "'><parent link='" + parent + "'/><child link='" + child +
         "'/><origin xyz='" + xyz + "' rpy='" + rpy + "'/>" + (type == "fixed" ? "" : "<axis xyz='0 0 1'/>") +
         "</joint>";
}

core::BodySpec load(const std::string& xml) { return io::loadUrdfString(xml, "test.urdf"); }

/// urdf.repair: false, as before repairs (the config key's strict reading).
core::BodySpec loadStrict(const std::string& xml) {
  return io::loadUrdfString(xml, "test.urdf", "", io::UrdfOptions{false, nullptr});
}

void expectRefused(const std::string& xml, std::initializer_list<std::string> parts) {
  expectThrowsWith<io::UrdfError>([&] { load(xml); }, parts);
}

void expectRefusedStrictly(const std::string& xml, std::initializer_list<std::string> parts) {
  expectThrowsWith<io::UrdfError>([&] { loadStrict(xml); }, parts);
}

TEST(UrdfLoader, ShippedBoxHasItsMassAndInertia) {
  const core::BodySpec b = io::loadUrdfFile(std::string(RBS_SOURCE_DIR) + "/urdf/box.urdf");
  EXPECT_EQ(b.name, "base_link");
  EXPECT_DOUBLE_EQ(b.mass, 1.0);
  EXPECT_LT((b.I_C_L - boxInertia(1.0, Vec3(0.2, 0.1, 0.05))).norm(), 1e-17);
  EXPECT_EQ(b.p_LC, Vec3::Zero());
}

TEST(UrdfLoader, InertialOriginPlacesAndTurnsTheInertia) {
  // The inertia is given in the inertial frame, turned 90° about z: ixx and
  // iyy swap in the link frame; the centre of mass is at the origin's xyz.
  const core::BodySpec b =
      load(robot(link("base", inertial(2.0, "<origin xyz='0.1 0.2 0.3' rpy='0 0 1.5707963267948966'/>"))));
  EXPECT_LT((b.p_LC - Vec3(0.1, 0.2, 0.3)).norm(), 1e-15);
  EXPECT_LT((b.I_C_L - Mat3(Vec3(0.2, 0.1, 0.25).asDiagonal())).norm(), 1e-15);
}

TEST(UrdfLoader, FixedJointsLumpByTheParallelAxisTheorem) {
  const core::BodySpec b = io::loadUrdfFile(std::string(RBS_SOURCE_DIR) + "/urdf/two_boxes.urdf");
  EXPECT_EQ(b.name, "base_link");
  EXPECT_DOUBLE_EQ(b.mass, 2.0);
  EXPECT_LT((b.p_LC - Vec3(0.1, 0.0, 0.0)).norm(), 1e-16);
  // Two 0.2 m cubes side by side are one 0.4 × 0.2 × 0.2 bar.
  EXPECT_LT((b.I_C_L - boxInertia(2.0, Vec3(0.2, 0.1, 0.1))).norm(), 1e-15);
}

TEST(UrdfLoader, ChainsOfFixedJointsComposeTheirTransforms) {
  // base → mid (0.5 m along x, turned 90° about z) → tip (0.5 m along the
  // turned x, i.e. world y). Point masses of 1 kg at mid and tip, base 2 kg.
  const std::string zero = "ixx='0' iyy='0' izz='0' ixy='0' ixz='0' iyz='0'";
  const std::string xml =
      robot(link("base", inertial(2.0)) + link("mid", inertial(1.0, "", zero)) + link("tip", inertial(1.0, "", zero)) +
            joint("j1", "fixed", "base", "mid", "0.5 0 0", "0 0 1.5707963267948966") +
            joint("j2", "fixed", "mid", "tip", "0.5 0 0"));
  const core::BodySpec b = load(xml);
  EXPECT_DOUBLE_EQ(b.mass, 4.0);
  EXPECT_LT((b.p_LC - Vec3(0.25, 0.125, 0.0)).norm(), 1e-15);  // (2·0 + 1·(0.5,0) + 1·(0.5,0.5)) / 4
  const core::MassProperties expected = core::combine({{2.0, Vec3::Zero(), Vec3(0.1, 0.2, 0.25).asDiagonal()},
                                                       {1.0, Vec3(0.5, 0, 0), Mat3::Zero()},
                                                       {1.0, Vec3(0.5, 0.5, 0), Mat3::Zero()}});
  EXPECT_LT((b.I_C_L - expected.I_C_F).norm(), 1e-14);
  // Each lumped link stays a frame, posed in its parent's frame (for tf).
  ASSERT_EQ(b.fixed_links.size(), 2u);
  EXPECT_EQ(b.fixed_links[0].name, "mid");
  EXPECT_EQ(b.fixed_links[0].parent, "base");
  EXPECT_LT((b.fixed_links[0].X_PK.translation - Vec3(0.5, 0, 0)).norm(), 1e-15);
  EXPECT_LT(b.fixed_links[0].X_PK.rotation.angularDistance(Quat(Eigen::AngleAxisd(M_PI / 2, Vec3::UnitZ()))), 1e-15);
  EXPECT_EQ(b.fixed_links[1].name, "tip");
  EXPECT_EQ(b.fixed_links[1].parent, "mid");
  EXPECT_LT((b.fixed_links[1].X_PK.translation - Vec3(0.5, 0, 0)).norm(), 1e-15);
}

TEST(UrdfLoader, ReportsTheLinkFrameNotTheCentreOfMass) {
  const core::BodySpec b = io::loadUrdfFile(std::string(RBS_SOURCE_DIR) + "/urdf/two_boxes.urdf");
  core::ModelSpec ms = spec(b, 1e-3, Vec3::Zero());
  const core::Model model(ms);
  core::LinkState link;
  link.p_WL = Vec3(1.0, 2.0, 3.0);
  link.q_WL = Quat(Eigen::AngleAxisd(M_PI / 2, Vec3::UnitZ()));
  link.w_W = Vec3(0.0, 0.0, 2.0);
  const core::BodyState s = core::bodyStateFromLink(model.body(0), link);
  // The centre of mass is 0.1 m along the link's x, which points along world y.
  EXPECT_LT((s.p_WB - Vec3(1.0, 2.1, 3.0)).norm(), 1e-15);
  EXPECT_LT((s.v_WB - Vec3(-0.2, 0.0, 0.0)).norm(), 1e-15);  // ω × r
  const core::LinkState back = core::linkState(model.body(0), s);
  EXPECT_LT((back.p_WL - link.p_WL).norm(), 1e-15);
  EXPECT_LT((back.v_WL - link.v_WL).norm(), 1e-15);
  EXPECT_LT(back.q_WL.angularDistance(link.q_WL), 1e-15);
}

TEST(UrdfLoader, RefusesAMovableJoint) {
  const std::string continuous = robot(link("base", inertial(1.0)) + link("wheel", inertial(1.0)) +
                                       joint("axle", "continuous", "base", "wheel", "0 0 0.1"));
  expectRefused(continuous, {"test.urdf", "joint 'axle' is continuous", "only fixed joints"});
  const std::string revolute =
      robot(link("base", inertial(1.0)) + link("arm", inertial(1.0)) +
            "<joint name='shoulder' type='revolute'><parent link='base'/><child link='arm'/>"
            "<axis xyz='0 0 1'/><limit lower='-1' upper='1' effort='10' velocity='1'/></joint>");
  expectRefused(revolute, {"joint 'shoulder' is revolute"});
  // Rooted at `world` (no <inertial>), it is still named a robot first.
  const std::string on_world =
      robot(link("world", "") + link("arm", inertial(1.0)) + joint("shoulder", "continuous", "world", "arm", "0 0 1"));
  expectRefused(on_world, {"joint 'shoulder' is continuous", "a URDF with moving joints is a robot"});
}

TEST(UrdfLoader, ALinkWithoutInertialIsAMasslessFrameSaidOnce) {
  const std::string xml =
      robot(link("base", inertial(1.0)) + link("sensor", "") + link("tool", "") +
            joint("mount", "fixed", "base", "sensor", "0 0 0.1") + joint("tip", "fixed", "base", "tool", "0.2 0 0"));
  std::vector<std::string> notes;
  const core::BodySpec b = io::loadUrdfString(xml, "test.urdf", "", io::UrdfOptions{true, &notes});
  // The same body as the URDF without the frames: they add no mass.
  const core::BodySpec alone = load(robot(link("base", inertial(1.0))));
  EXPECT_EQ(b.mass, alone.mass);
  EXPECT_TRUE((b.p_LC.array() == alone.p_LC.array()).all());
  EXPECT_TRUE((b.I_C_L.array() == alone.I_C_L.array()).all());
  ASSERT_EQ(b.fixed_links.size(), 2u);  // still frames of the body, for tf
  ASSERT_EQ(notes.size(), 1u);          // one message for the whole URDF
  expectContains(notes[0], {"test.urdf", "2 links without <inertial> are massless frames", "'sensor' and 'tool'",
                            "urdf.repair: false"});
  expectRefusedStrictly(
      xml, {"2 problems", "link 'sensor' has no <inertial>", "link 'tool' has no <inertial>", "urdf.repair: true"});
}

TEST(UrdfLoader, AnInvalidInertiaIsReplacedByTheNearestValidOne) {
  // PR2's sensor_mount_link, lumped into a body: the repair's closed form
  // (core's NearestValidInertia tests) is what the body gets.
  const std::string cad = robot(link("base", inertial(1.0)) +
                                link("mount", inertial(1.0, "",
                                                       "ixx='0.001' iyy='0.001' izz='0.01' ixy='0' ixz='0' "
                                                       "iyz='0'")) +
                                joint("fix", "fixed", "base", "mount", "0 0 0"));
  std::vector<std::string> notes;
  const core::BodySpec b = io::loadUrdfString(cad, "test.urdf", "", io::UrdfOptions{true, &notes});
  const Mat3 repaired = (Vec3(0.011, 0.011, 0.022) / 3.0).asDiagonal();
  EXPECT_LT((b.I_C_L - (Mat3(Vec3(0.1, 0.2, 0.25).asDiagonal()) + repaired)).norm(), 1e-15);
  ASSERT_EQ(notes.size(), 1u);
  expectContains(notes[0],
                 {"1 inertia no body can have was replaced by the nearest valid one", "'mount'",
                  "[0.001, 0.001, 0.01] -> [0.00367, 0.00367, 0.00733]", "changed by 0.00462", "46.2% of the largest"});
  expectRefusedStrictly(robot(link("base", inertial(1.0, "", "ixx='1' iyy='1' izz='3' ixy='0' ixz='0' iyz='0'"))),
                        {"link 'base'", "<inertia> = (ixx=1, iyy=1, izz=3", "triangle inequality"});
  expectRefusedStrictly(robot(link("base", inertial(1.0, "", "ixx='1' iyy='-1' izz='1' ixy='0' ixz='0' iyz='0'"))),
                        {"link 'base'", "iyy=-1", "positive semi-definite"});
}

TEST(UrdfLoader, MassZeroWithAnInertiaIsAMasslessFrame) {
  std::vector<std::string> notes;
  const core::BodySpec b = io::loadUrdfString(robot(link("base", inertial(1.0)) + link("antenna", inertial(0.0)) +
                                                    joint("fix", "fixed", "base", "antenna", "0 0 0.3")),
                                              "test.urdf", "", io::UrdfOptions{true, &notes});
  EXPECT_EQ(b.mass, 1.0);
  EXPECT_LT((b.I_C_L - Mat3(Vec3(0.1, 0.2, 0.25).asDiagonal())).norm(), 1e-16);  // the antenna's inertia dropped
  ASSERT_EQ(notes.size(), 1u);
  expectContains(notes[0], {"1 link of mass 0 is a massless frame", "'antenna'"});
}

TEST(UrdfLoader, RefusesZeroTotalMass) {
  const std::string zero = "ixx='0' iyy='0' izz='0' ixy='0' ixz='0' iyz='0'";
  expectRefused(robot(link("base", inertial(0.0, "", zero))), {"link 'base'", "total mass of 0 kg"});
  expectRefused(robot(link("base", inertial(0.0))), {"link 'base'", "total mass of 0 kg"});
  expectRefusedStrictly(robot(link("base", inertial(0.0))), {"link 'base': mass is 0 kg but <inertia> is not zero"});
}

TEST(UrdfLoader, APointMassIsGivenAWaterSpheresInertia) {
  std::vector<std::string> notes;
  const core::BodySpec b =
      io::loadUrdfString(robot(link("bob", inertial(2.0, "", "ixx='0' iyy='0' izz='0' ixy='0' ixz='0' iyz='0'"))),
                         "test.urdf", "", io::UrdfOptions{true, &notes});
  EXPECT_TRUE((b.I_C_L.array() == core::waterSphereInertia(2.0).array()).all());
  ASSERT_EQ(notes.size(), 1u);
  expectContains(notes[0], {"point mass", "'bob' 2 kg"});
}

TEST(UrdfLoader, EveryProblemOfAUrdfIsNamedInOneRefusal) {
  const std::string xml = robot(
      link("base", inertial(1.0)) +
      "<link name='a'><inertial><mass value='-1'/><inertia ixx='1' iyy='1' izz='1' "
      "ixy='0' ixz='0' iyz='0'/></inertial></link>" +
      "<link name='b'>" + inertial(1.0) + "<collision><geometry><box size='-1 1 1'/></geometry></collision></link>" +
      joint("ja", "fixed", "base", "a", "0 0 0") + joint("jb", "fixed", "base", "b", "0 0 0"));
  expectRefused(xml,
                {"test.urdf: 2 problems", "link 'a': <mass value> = -1", "link 'b' <collision> 0: box size x = -1"});
}

TEST(UrdfLoader, RefusesNonsenseAndMissingFiles) {
  expectRefused("this is not xml", {"test.urdf", "not a valid URDF"});
  expectThrowsWith<io::UrdfError>([] { io::loadUrdfFile("/nonexistent/robot.urdf"); },
                                  {"URDF '/nonexistent/robot.urdf': no such file"});
}

TEST(UrdfLoader, AnElementUrdfdomCouldNotReadIsRefusedNotSkipped) {
  // urdfdom logs such an element and goes on without it: two_boxes.urdf with
  // "2.0kg" loaded as a 1 kg body, and a "0.2m" box lost its collision.
  const std::string two = io::readFile(std::string(RBS_SOURCE_DIR) + "/urdf/two_boxes.urdf", 1 << 20);
  const auto with = [&](const std::string& from, const std::string& to) {
    std::string xml = two;
    const std::size_t at = xml.rfind(from);  // in the second link
    return xml.replace(at, from.size(), to);
  };
  expectRefused(with("<mass value=\"1.0\"/>", "<mass value=\"2.0kg\"/>"),
                {"test.urdf: link 'second_box' <inertial><mass value=\"2.0kg\">: not a number"});
  expectRefused(
      with("<collision><geometry><box size=\"0.2 0.2 0.2\"/>", "<collision><geometry><box size=\"0.2 0.2 0.2m\"/>"),
      {"link 'second_box' <collision><geometry><box size=\"0.2 0.2 0.2m\">: not a number (or numbers)"});
  expectRefused(with("<visual><geometry><box size=\"0.2 0.2 0.2\"/></geometry></visual>",
                     "<visual><geometry><sphere radius=\"big\"/></geometry></visual>"),
                {"link 'second_box' <visual><geometry><sphere radius=\"big\">"});
  expectRefused(with("<origin xyz=\"0.2 0 0\" rpy=\"0 0 0\"/>", "<origin xyz=\"0.2 0 0\" rpy=\"0 0 90deg\"/>"),
                {"joint 'glue' <origin rpy=\"0 0 90deg\">"});
  // What the numbers check does not cover, urdfdom's own log names: an
  // element it could not read is refused with its words, never skipped.
  expectRefused(with("<visual><geometry><box size=\"0.2 0.2 0.2\"/></geometry></visual>",
                     "<visual><geometry><cone radius=\"1\"/></geometry></visual>"),
                {"link 'second_box' <visual>: urdfdom could not read it: "});
  // One link: the message is the mass's, not the "total mass of 0 kg" that followed from it.
  try {
    load(robot(link("base",
                    "<inertial><mass value='1.0x'/><inertia ixx='1' iyy='1' izz='1' ixy='0' ixz='0' "
                    "iyz='0'/></inertial>")));
    ADD_FAILURE() << "accepted";
  } catch (const io::UrdfError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("<mass value=\"1.0x\">: not a number"), std::string::npos) << what;
    EXPECT_EQ(what.find("total mass"), std::string::npos) << what;
  }
}

TEST(UrdfLoader, JointsThatAreNotATreeAreRefusedBeforeUrdfdomLeaksThem) {
  // urdfdom leaked the links of every such URDF (688 bytes each; LeakSanitizer
  // in the sanitizer run catches one): 10,000 tries, as a client could spawn it.
  const std::string cycle = robot(link("a", inertial(1.0)) + link("b", inertial(1.0)) +
                                  joint("j1", "fixed", "a", "b", "0 0 0") + joint("j2", "fixed", "b", "a", "0 0 0"));
  for (int i = 0; i < 10000; ++i) {
    try {
      load(cycle);
      ADD_FAILURE() << "accepted";
      break;
    } catch (const io::UrdfError& e) {
      if (std::string(e.what()).find("closes a cycle of joints") == std::string::npos) {
        ADD_FAILURE() << e.what();
        break;
      }
    }
  }
  expectRefused(robot(link("a", inertial(1.0)) + link("b", inertial(1.0)) + link("c", inertial(1.0)) +
                      joint("j1", "fixed", "a", "c", "0 0 0") + joint("j2", "fixed", "b", "c", "0 0 0")),
                {"link 'c' is the child of two joints, 'j1' and 'j2'"});
  expectRefused(robot(link("a", inertial(1.0)) + link("b", inertial(1.0)) + link("c", inertial(1.0)) +
                      joint("j1", "fixed", "a", "b", "0 0 0") + joint("j2", "fixed", "b", "c", "0 0 0") +
                      joint("j3", "fixed", "c", "b", "0 0 0")),
                {"link 'b' is the child of two joints"});
  expectRefused(robot(link("a", inertial(1.0)) + joint("self", "fixed", "a", "a", "0 0 0")),
                {"joint 'self' closes a cycle"});
}

TEST(UrdfLoader, ACapsuleIsReadAsSDFormatAndDrakeWriteIt) {
  // <capsule radius length>: the length of its cylinder. Cylinders stay
  // cylinders, visuals may be capsules too, and the second collision of a
  // link is told from the first.
  const std::string geometry =
      "<collision><geometry><cylinder radius='0.05' length='0.2'/></geometry></collision>"
      "<collision><origin xyz='0 0 0.5'/><geometry><capsule radius='0.1' length='0.3'/>"
      "</geometry></collision>"
      "<visual><geometry><capsule radius='0.1' length='0.3'/></geometry></visual>";
  const core::BodySpec b = load(robot("<link name='base'>" + inertial(1.0) + geometry + "</link>"));
  ASSERT_EQ(b.collision.size(), 2u);
  EXPECT_EQ(b.collision[0].kind, core::CollisionShape::Kind::kCylinder);
  EXPECT_EQ(b.collision[1].kind, core::CollisionShape::Kind::kCapsule);
  EXPECT_EQ(b.collision[1].radius, 0.1);
  EXPECT_EQ(b.collision[1].length, 0.3);
  EXPECT_EQ(b.collision[1].X_LS.translation, Vec3(0, 0, 0.5));
  expectRefused(robot("<link name='base'>" + inertial(1.0) +
                      "<collision><geometry><capsule radius='-1' length='0.3'/></geometry></collision></link>"),
                {"link 'base' <collision> 0", "capsule radius", "-1"});
}

}  // namespace
}  // namespace rigid_body_sim::test
