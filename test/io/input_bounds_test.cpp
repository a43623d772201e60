// Bounds on input, checked before parsing (src/io/input_bounds.cpp): each
// case here once crashed, hung or read without end.
#include "rigid_body_sim/io/input_bounds.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <chrono>
#include <fstream>

#include "../scratch_dir.h"
#include "../test_util.h"
#include "rigid_body_sim/io/config.h"
#include "rigid_body_sim/io/mesh_loader.h"
#include "rigid_body_sim/io/urdf_loader.h"

namespace rigid_body_sim::test {
namespace {

std::string write(const std::string& name, const std::string& text) {
  const std::string path = (scratch().path() / name).string();
  std::ofstream(path) << text;
  return path;
}

std::string link(int i) {
  return "<link name=\"l" + std::to_string(i) +
         "\"><inertial><mass value=\"1\"/><inertia ixx=\"1\" iyy=\"1\" izz=\"1\" ixy=\"0\" ixz=\"0\" "
         "iyz=\"0\"/></inertial></link>";
}

/// A URDF of `n` links in one chain of fixed joints.
std::string chain(int n) {
  std::string xml = "<robot name=\"chain\">";
  for (int i = 0; i < n; ++i) xml += link(i);
  for (int i = 1; i < n; ++i) {
    xml += "<joint name=\"j" + std::to_string(i) + "\" type=\"fixed\"><parent link=\"l" + std::to_string(i - 1) +
           "\"/><child link=\"l" + std::to_string(i) + "\"/><origin xyz=\"0.001 0 0\"/></joint>";
  }
  return xml + "</robot>";
}

TEST(InputBounds, OnlyRegularFilesOfBoundedSizeAreRead) {
  EXPECT_NE(io::fileProblem("/nonexistent.yaml", 100).find("no such file"), std::string::npos);
  EXPECT_NE(io::fileProblem(scratch().path().string(), 100).find("is a directory"), std::string::npos);
  EXPECT_NE(io::fileProblem("/dev/zero", 100).find("not a regular file"), std::string::npos);
  const std::string eleven = write("eleven.txt", "01234567890");
  EXPECT_EQ(io::fileProblem(eleven, 11), "");
  // Over the cap, it says the cap, never the file's size (a caller of
  // ~spawn_body once learnt a file's exact size from the refusal).
  EXPECT_NE(io::fileProblem(eleven, 10).find("holds more than the 10 bytes this input may have"), std::string::npos);
  // The path is the scratch folder's, which holds the test's PID: look past it.
  const std::string over = io::fileProblem(eleven, 10);
  ASSERT_EQ(over.rfind("'" + eleven + "'", 0), 0u) << over;
  EXPECT_EQ(over.find("11", eleven.size() + 2), std::string::npos) << over;
  EXPECT_EQ(io::readFile(eleven, 11), "01234567890");
  EXPECT_THROW(io::readFile(eleven, 10), std::runtime_error);
  // Read in chunks, not into a buffer of the cap's size: longer than one
  // chunk (64 KiB), and cut at the cap whatever the chunk.
  std::string long_text(200000, 'x');
  for (std::size_t i = 0; i < long_text.size(); i += 997) long_text[i] = static_cast<char>('a' + i % 26);
  const std::string long_file = write("long.txt", long_text);
  EXPECT_EQ(io::readFile(long_file, 16u << 20), long_text);
  EXPECT_EQ(io::readFile(long_file, 200000), long_text);
  EXPECT_THROW(io::readFile(long_file, 199999), std::runtime_error);
  EXPECT_THROW(io::readFile(long_file, 65536), std::runtime_error);
  // Each loader says so in its own words (/dev/zero was read until memory ran out).
  expectThrowsWith<io::UrdfError>([] { io::loadUrdfFile("/dev/zero"); }, {"URDF '/dev/zero'", "not a regular file"});
  expectThrowsWith<io::ConfigError>([] { io::loadYamlFile(scratch().path().string()); },
                                    {"config '", "is a directory"});
  expectThrowsWith<io::MeshError>([] { io::loadMesh(scratch().path().string(), Vec3::Ones()); },
                                  {"mesh '", "is a directory"});
}

TEST(InputBounds, YamlAnchorsAliasesAndMergeKeysReadAsRoslaunchReadsThem) {
  // UR5's ur5_controllers.yaml names its joints and its rate once.
  const YAML::Node ur = io::loadYamlText(R"(js:
  publish_rate: &loop_hz 125
traj:
  joints: &robot_joints [shoulder_pan_joint, elbow_joint]
  state_publish_rate: *loop_hz
group:
  joints: *robot_joints
gains: &g {p: 10, i: 1}
wrist:
  <<: *g
  i: 2
both:
  <<: [{d: 3}, *g]
)",
                                         "ur");
  EXPECT_EQ(ur["traj"]["state_publish_rate"].as<int>(), 125);
  ASSERT_EQ(ur["group"]["joints"].size(), 2u);
  EXPECT_EQ(ur["group"]["joints"][1].as<std::string>(), "elbow_joint");
  // A merge gives the keys the map lacks; its own win.
  EXPECT_EQ(ur["wrist"]["p"].as<int>(), 10);
  EXPECT_EQ(ur["wrist"]["i"].as<int>(), 2);
  EXPECT_FALSE(ur["wrist"]["<<"]);
  EXPECT_EQ(ur["wrist"].size(), 2u);
  EXPECT_EQ(ur["both"]["d"].as<int>(), 3);
  EXPECT_EQ(ur["both"]["p"].as<int>(), 10);
  // An alias is a copy: changing one place leaves the other.
  YAML::Node group_joints = ur["group"]["joints"];
  group_joints[0] = "other";
  EXPECT_EQ(ur["group"]["joints"][0].as<std::string>(), "other");
  EXPECT_EQ(ur["traj"]["joints"][0].as<std::string>(), "shoulder_pan_joint");
  expectThrowsWith<io::ConfigError>([] { io::loadYamlText("a: &m [1]\nb: {<<: *m}\n", "m"); },
                                    {"m is not valid YAML", "merge key (<<) takes maps"});
}

TEST(InputBounds, YamlAliasBombsSecondDocumentsAndDeepNestingAreRefused) {
  // 9 levels of 10 aliases: 10⁹ nodes once expanded (it hung).
  std::string bomb = "a0: &a0 [x, x, x, x, x, x, x, x, x, x]\n";
  for (int i = 1; i < 9; ++i) {
    bomb += "a" + std::to_string(i) + ": &a" + std::to_string(i) + " [";
    for (int k = 0; k < 10; ++k) bomb += std::string(k ? ", " : "") + "*a" + std::to_string(i - 1);
    bomb += "]\n";
  }
  bomb += "scene: *a8\n";
  const auto t0 = std::chrono::steady_clock::now();
  expectThrowsWith<io::ConfigError>([&] { io::loadYamlText(bomb, "bomb"); },
                                    {"bomb: line 5", "more than 100000 nodes", "alias bomb"});
  EXPECT_LT(std::chrono::steady_clock::now() - t0, std::chrono::seconds(5));  // a hang guard, not a benchmark
  EXPECT_NE(io::yamlProblem("a: &x k\n*x : 1\n").find("alias (*name) as a key"), std::string::npos);
  EXPECT_NE(io::yamlProblem("dt: 0.001\n---\ndt: 0.1\n").find("second YAML document"), std::string::npos);
  EXPECT_EQ(io::yamlProblem("dt: 0.001\n"), "");
  EXPECT_EQ(io::yamlProblem("---\ndt: 0.001\n...\n"), "");
  const std::string deep = std::string(100, '[') + std::string(100, ']');
  EXPECT_NE(io::yamlProblem(deep).find("nested more than 64 levels"), std::string::npos);
  EXPECT_EQ(io::yamlProblem(std::string(64, '[') + std::string(64, ']')), "");
  // Repeated keys: yaml-cpp kept one of them without a word.
  EXPECT_NE(io::yamlProblem("{rate: 100, rate: 200}").find("line 1: key 'rate' appears twice in one map"),
            std::string::npos);
  EXPECT_NE(io::yamlProblem("imu:\n  rate: 1\n  pose: {rpy: [0, 0, 0]}\n  rate: 2\n").find("line 4: key 'rate'"),
            std::string::npos);
  EXPECT_EQ(io::yamlProblem("a: {rate: 1}\nb: {rate: 1}\nc: [rate, rate, {rate: 1}, {rate: 2}]\n"), "");
  EXPECT_EQ(io::yamlProblem("a: {b: {rate: 1}, rate: 2}\nrate: 3\n"), "");
  const std::string file = write("two.yaml", "dt: 0.001\n---\ndt: 0.1\n");
  expectThrowsWith<io::ConfigError>([&] { io::loadYamlFile(file); }, {"two.yaml", "second YAML document"});
}

TEST(InputBounds, XmlNestingAndLinkCountAreCappedBeforeParsing) {
  const std::string deep = std::string("<robot name=\"r\">") + [] {
    std::string s;
    for (int i = 0; i < 100000; ++i) s += "<a>";
    for (int i = 0; i < 100000; ++i) s += "</a>";
    return s;
  }() + "</robot>";
  EXPECT_NE(io::xmlProblem(deep).find("nested more than 64 levels"), std::string::npos);
  // 100,000 nested elements overflowed the stack inside TinyXML.
  expectThrowsWith<io::UrdfError>([&] { io::loadUrdfString(deep, "deep.urdf"); },
                                  {"deep.urdf", "refused before parsing", "nested"});
  // A "/>" or ">" inside quotes closes nothing.
  std::string quoted;
  for (int i = 0; i < 100; ++i) quoted += "<a x=\"/>\" y='>'>";
  EXPECT_NE(io::xmlProblem(quoted).find("nested"), std::string::npos);
  EXPECT_EQ(io::xmlProblem("<?xml version=\"1.0\"?><!-- <a><a><a> --><robot><link name=\"a\"/></robot>"), "");
  EXPECT_NE(io::xmlProblem(chain(10001)).find("more than 10000 <link> elements"), std::string::npos);
}

// A file swapped for a FIFO after it was looked at: readFile opens without
// blocking and refuses it (an ifstream waited for a writer for good).
TEST(InputBounds, AFifoIsRefusedWithoutWaitingForAWriter) {
  const std::string fifo = (scratch().path() / "fifo.urdf").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_NE(io::fileProblem(fifo, 100).find("not a regular file"), std::string::npos);
  try {
    io::readFile(fifo, 100);
    ADD_FAILURE() << "a FIFO was read";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("not a regular file"), std::string::npos) << e.what();
  }
}

// TinyXML reads a C string and stops at a NUL byte: what follows one would
// be dropped unread (here a second robot; the first alone was accepted).
TEST(InputBounds, AUrdfWithANulByteIsRefusedNotReadToTheNul) {
  const std::string one = chain(1);
  const std::string cut = one + std::string(1, '\0') + chain(2);
  // Not where it is: /proc/self/environ's first NUL told a caller the length of a variable.
  EXPECT_EQ(io::xmlProblem(cut), "it holds a NUL byte: a URDF is text (the parser would stop there, the rest unread)");
  expectThrowsWith<io::UrdfError>([&] { io::loadUrdfString(cut, "nul.urdf"); }, {"nul.urdf", "a NUL byte"});
  EXPECT_EQ(io::xmlProblem(one), "");
}

// After an XML declaration TinyXML reads UTF-8, a character at a time by
// the length its first byte announces: a text cut inside one (0xd7 starts
// two bytes) took it past the end of the text. CI's urdf_fuzzer found it
// (fuzz/seeds/urdf/cut_utf8_character.urdf is the input, minimised).
TEST(InputBounds, AUrdfThatIsNotUtf8IsRefusedBeforeTheParserReadsIt) {
  const std::string cut = "<?xml version=\"1.0\"?><r e=>\xd7";
  EXPECT_NE(io::xmlProblem(cut).find("bytes that are not UTF-8"), std::string::npos) << io::xmlProblem(cut);
  expectThrowsWith<io::UrdfError>([&] { io::loadUrdfString(cut, "cut.urdf"); }, {"cut.urdf", "not UTF-8"});
  EXPECT_NE(io::xmlProblem("<robot name=\"\xff\"/>").find("not UTF-8"), std::string::npos);
  EXPECT_NE(io::xmlProblem("<robot name=\"\xe2\x82\"/>").find("not UTF-8"), std::string::npos);
  // Whole characters pass: a name with an accent, and a euro sign.
  EXPECT_EQ(io::xmlProblem("<?xml version=\"1.0\"?><robot name=\"caf\xc3\xa9 \xe2\x82\xac\"/>"), "");
}

TEST(InputBounds, AChainOfTenThousandLinksLoadsWithoutRecursion) {
  // The loader's own recursion overflowed the stack at 10,000 links.
  const core::BodySpec body = io::loadUrdfString(chain(10000), "chain.urdf");
  EXPECT_DOUBLE_EQ(body.mass, 10000.0);
  ASSERT_EQ(body.fixed_links.size(), 9999u);
  EXPECT_EQ(body.fixed_links.back().name, "l9999");
  EXPECT_EQ(body.fixed_links.back().parent, "l9998");
  EXPECT_NEAR(body.p_LC.x(), 0.001 * 9999 / 2.0, 1e-9);
}

}  // namespace
}  // namespace rigid_body_sim::test
