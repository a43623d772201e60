// Meshes through assimp, URI resolution, collision shapes from URDF, and the
// shipped bunny dropping onto the ground.
#include "rigid_body_sim/io/mesh_loader.h"

#include <assimp/scene.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <assimp/Exporter.hpp>
#include <assimp/Importer.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "../scratch_dir.h"
#include "../test_util.h"
#include "rigid_body_sim/core/contacts/contact.h"
#include "rigid_body_sim/core/step/step.h"
#include "rigid_body_sim/io/config.h"
#include "rigid_body_sim/io/input_bounds.h"
#include "rigid_body_sim/io/urdf_loader.h"
#include "rigid_body_sim/io/world.h"

namespace rigid_body_sim::test {
namespace {

namespace fs = std::filesystem;

/// A fresh folder for one test, inside the process's scratch folder.
fs::path tempDir(const std::string& name) {
  const fs::path dir = scratch().path() / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

const Vec3 kTet[4] = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};

void writeTetrahedronStl(const fs::path& path) {
  // ASCII STL repeats every vertex in each facet that uses it.
  const int faces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  std::ofstream out(path);
  out << "solid tet\n";
  for (const auto& f : faces) {
    out << "facet normal 0 0 0\n outer loop\n";
    for (int v : f) out << "  vertex " << kTet[v].x() << " " << kTet[v].y() << " " << kTet[v].z() << "\n";
    out << " endloop\nendfacet\n";
  }
  out << "endsolid tet\n";
}

void writeTetrahedronObj(const fs::path& path) {
  std::ofstream out(path);
  for (const Vec3& v : kTet) out << "v " << v.x() << " " << v.y() << " " << v.z() << "\n";
  out << "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
}

TEST(MeshLoader, ReadsStlAndObjVerticesOnceEachAndScales) {
  const fs::path dir = tempDir("formats");
  writeTetrahedronStl(dir / "tet.stl");
  writeTetrahedronObj(dir / "tet.obj");
  for (const char* file : {"tet.stl", "tet.obj"}) {
    const auto v = io::loadMesh((dir / file).string(), Vec3(2, 3, 4)).vertices;
    ASSERT_EQ(v.size(), 4u) << file;
    for (const Vec3& t : kTet) {
      const Vec3 scaled = t.cwiseProduct(Vec3(2, 3, 4));
      EXPECT_TRUE(std::any_of(v.begin(), v.end(), [&](const Vec3& x) { return (x - scaled).norm() < 1e-6; }))
          << file << ": " << scaled.transpose();
    }
  }
  EXPECT_THROW(io::loadMesh((dir / "missing.stl").string(), Vec3::Ones()), io::MeshError);
  std::ofstream(dir / "garbage.obj") << "this is not a mesh\n";
  EXPECT_THROW(io::loadMesh((dir / "garbage.obj").string(), Vec3::Ones()), io::MeshError);
}

TEST(MeshLoader, AHeaderThatDeclaresMoreThanTheFileHoldsIsRefusedBeforeAnyReaderAllocates) {
  const fs::path dir = tempDir("lying_headers");
  // A Collada float_array of 4,000,000,000 in a file of a hundred bytes:
  // assimp reserves by the count before it reads the numbers.
  std::ofstream(dir / "lie.dae") << "<COLLADA><library_geometries><float_array count=\"4000000000\">0 0 0"
                                    "</float_array></library_geometries></COLLADA>";
  expectThrowsWith<io::MeshError>([&] { io::loadMesh((dir / "lie.dae").string(), Vec3::Ones()); },
                                  {"lie.dae", "count=4e+09", "readers allocate by that count"});
  EXPECT_EQ(io::meshProblem("<float_array count='3'>0 0 0</float_array>", "DAE"), "");  // any case
  // A 169-byte PLY that declared 4,000,000,000 vertices made assimp ask for
  // 48 GB, and its PLY reader hangs on a malformed header (mesh_fuzzer,
  // fuzz/seeds/mesh/ply_reader_hang.ply): PLY is refused by name, as every
  // format outside STL, OBJ and DAE is.
  std::ofstream(dir / "lie.ply") << "ply\nformat ascii 1.0\nelement vertex 4000000000\nproperty float x\n"
                                    "property float y\nproperty float z\nend_header\n0 0 0\n";
  expectThrowsWith<io::MeshError>([&] { io::loadMesh((dir / "lie.ply").string(), Vec3::Ones()); },
                                  {"lie.ply", "the format 'ply' is not read here"});
  std::ofstream(dir / "tet.off") << "OFF\n4000000000 1 0\n0 0 0\n";
  expectThrowsWith<io::MeshError>([&] { io::loadMesh((dir / "tet.off").string(), Vec3::Ones()); },
                                  {"tet.off", "the format 'off' is not read here"});
}

// The files a mesh names are checked as the mesh is, or not read: an OBJ's
// mtllib on a FIFO blocked ~spawn_body for good (and every spawn after it),
// a 79-byte OBJ naming a 1.5 GB .mtl took 1.58 GB. Such a mesh is refused,
// naming the file and why; one beside it is read; a missing one is gone
// without, as assimp goes.
TEST(MeshLoader, AFileTheMeshNamesIsCheckedAsTheMeshIsOrNotRead) {
  const fs::path dir = tempDir("named_files");
  fs::create_directories(dir / "sub");
  const auto obj = [&](const std::string& name, const std::string& mtllib) {
    writeTetrahedronObj(dir / "sub" / name);
    std::ofstream(dir / "sub" / name, std::ios::app) << "mtllib " << mtllib << "\n";
    return (dir / "sub" / name).string();
  };
  std::ofstream(dir / "sub" / "fine.mtl") << "newmtl red\nKd 1 0 0\n";
  EXPECT_EQ(io::loadMesh(obj("beside.obj", "fine.mtl"), Vec3::Ones()).vertices.size(), 4u);
  EXPECT_EQ(io::loadMesh(obj("missing.obj", "nowhere.mtl"), Vec3::Ones()).vertices.size(), 4u);
  ASSERT_EQ(::mkfifo((dir / "sub" / "pipe.mtl").c_str(), 0600), 0);
  expectThrowsWith<io::MeshError>([&] { io::loadMesh(obj("fifo.obj", "pipe.mtl"), Vec3::Ones()); },
                                  {"fifo.obj", "names a file", "pipe.mtl", "not a regular file"});
  // Over the mesh's cap (a sparse file: nothing is written, nothing read).
  std::ofstream(dir / "sub" / "huge.mtl").close();
  fs::resize_file(dir / "sub" / "huge.mtl", io::InputCaps::kMeshBytes + 1);
  expectThrowsWith<io::MeshError>([&] { io::loadMesh(obj("huge.obj", "huge.mtl"), Vec3::Ones()); },
                                  {"huge.obj", "names a file ('huge.mtl') that holds more than the 256 MiB"});
  std::ofstream(dir / "outside.mtl") << "newmtl red\nKd 1 0 0\n";
  expectThrowsWith<io::MeshError>([&] { io::loadMesh(obj("up.obj", "../outside.mtl"), Vec3::Ones()); },
                                  {"up.obj", "outside its own folder and package"});
  // In a package, a sibling folder's file is its own (meshes/x.obj naming ../materials/x.mtl).
  std::ofstream(dir / "package.xml") << "<package><name>named</name></package>";
  EXPECT_EQ(io::loadMesh(obj("sibling.obj", "../outside.mtl"), Vec3::Ones()).vertices.size(), 4u);
}

TEST(MeshLoader, ReadsColladaAsRosDoesWhateverItsUpAxis) {
  // A Collada copy of the tetrahedron (assimp's exporter), then the same file
  // declaring Z_UP: ROS tools read the coordinates as they are, and so do we.
  const fs::path dir = tempDir("collada");
  writeTetrahedronObj(dir / "tet.obj");
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile((dir / "tet.obj").string(), 0);
  ASSERT_NE(scene, nullptr);
  Assimp::Exporter exporter;
  ASSERT_EQ(exporter.Export(scene, "collada", (dir / "tet.dae").string()), AI_SUCCESS);
  std::ifstream in(dir / "tet.dae");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto at = text.find("Y_UP");
  ASSERT_NE(at, std::string::npos);
  std::ofstream(dir / "tet_z_up.dae") << text.replace(at, 4, "Z_UP");
  for (const char* file : {"tet.dae", "tet_z_up.dae"}) {
    const auto v = io::loadMesh((dir / file).string(), Vec3::Ones()).vertices;
    ASSERT_EQ(v.size(), 4u) << file;
    for (const Vec3& t : kTet) {
      EXPECT_TRUE(std::any_of(v.begin(), v.end(), [&](const Vec3& x) { return (x - t).norm() < 1e-6; }))
          << file << ": " << t.transpose();
    }
  }
}

TEST(MeshLoader, ResolvesFilePackageAndRelativeUris) {
  const fs::path dir = tempDir("uris");
  fs::create_directories(dir / "ws" / "my_pkg" / "meshes");
  std::ofstream(dir / "ws" / "my_pkg" / "package.xml") << "<package><name>my_pkg</name></package>";
  EXPECT_EQ(io::resolveMeshUri("file:///abs/a.stl", "/x"), "/abs/a.stl");
  EXPECT_EQ(io::resolveMeshUri("meshes/a.stl", "/base"), "/base/meshes/a.stl");
  EXPECT_EQ(io::resolveMeshUri("/abs/a.stl", "/base"), "/abs/a.stl");
  // Through ROS_PACKAGE_PATH ...
  ::setenv("ROS_PACKAGE_PATH", (dir / "ws").c_str(), 1);
  EXPECT_EQ(io::resolveMeshUri("package://my_pkg/meshes/a.stl", ""), (dir / "ws" / "my_pkg" / "meshes/a.stl").string());
  ::unsetenv("ROS_PACKAGE_PATH");
  // ... or upward from the URDF's folder, without ROS.
  EXPECT_EQ(io::resolveMeshUri("package://my_pkg/meshes/a.stl", (dir / "ws" / "my_pkg" / "urdf").string()),
            (dir / "ws" / "my_pkg" / "meshes/a.stl").string());
  expectThrowsWith<io::MeshError>([] { io::resolveMeshUri("package://nobody/a.stl", "/tmp"); },
                                  {"package://nobody/a.stl", "package 'nobody' not found"});
  // Not out of the package: a refusal of package://rigid_body_sim/../x.obj
  // told a spawn's caller where the package is installed.
  for (const char* uri : {"package://my_pkg/../x.obj", "package://my_pkg/meshes/../../x.obj"}) {
    try {
      io::resolveMeshUri(uri, (dir / "ws" / "my_pkg" / "urdf").string());
      ADD_FAILURE() << uri << " resolved";
    } catch (const io::MeshError& e) {
      EXPECT_NE(std::string(e.what()).find("may not leave the package ('..')"), std::string::npos) << e.what();
      EXPECT_EQ(std::string(e.what()).find(dir.string()), std::string::npos) << e.what();
    }
  }
}

TEST(MeshLoader, FindsAPackageAtAnyDepthAsRospackCrawls) {
  const fs::path dir = tempDir("crawl");
  const auto package = [&](const fs::path& at, const std::string& name) {
    fs::create_directories(dir / at);
    std::ofstream(dir / at / "package.xml") << "<package><name>" << name << "</name></package>";
  };
  // Husky's and Jackal's layout: a clone of the repository in a workspace.
  package("ws/src/husky/husky_description", "husky_description");
  // Copies rospack does not see: ignored, hidden, inside another package.
  package("ws/src/a_ignored/robot_description", "robot_description");
  std::ofstream(dir / "ws/src/a_ignored/CATKIN_IGNORE");
  package("ws/src/.git/robot_description", "robot_description");
  package("ws/src/husky/husky_description/robot_description", "robot_description");
  package("ws/src/z_kept/deeper/still/robot_description", "robot_description");
  fs::create_directory_symlink(dir / "ws", dir / "ws/src/loop");  // a cycle ends
  ::setenv("ROS_PACKAGE_PATH", (dir / "ws").c_str(), 1);
  EXPECT_EQ(io::resolveMeshUri("package://husky_description/meshes/base.stl", ""),
            (dir / "ws/src/husky/husky_description/meshes/base.stl").string());
  EXPECT_EQ(io::resolveMeshUri("package://robot_description/a.dae", ""),
            (dir / "ws/src/z_kept/deeper/still/robot_description/a.dae").string());
  // The first entry of ROS_PACKAGE_PATH that has it.
  package("other/robot_description", "robot_description");
  ::setenv("ROS_PACKAGE_PATH", ((dir / "other").string() + ":" + (dir / "ws").string()).c_str(), 1);
  EXPECT_EQ(io::resolveMeshUri("package://robot_description/a.dae", ""),
            (dir / "other/robot_description/a.dae").string());
  ::unsetenv("ROS_PACKAGE_PATH");
}

TEST(UrdfCollision, ShapesArePosedInTheRootLinkFrame) {
  const std::string xml = R"(<robot name="r">
    <link name="base">
      <inertial><mass value="1"/><inertia ixx="0.1" iyy="0.1" izz="0.1" ixy="0" ixz="0" iyz="0"/></inertial>
      <collision><origin xyz="0 0 0.5"/><geometry><box size="0.2 0.4 0.6"/></geometry></collision>
      <collision><geometry><sphere radius="0.3"/></geometry></collision>
    </link>
    <joint name="j" type="fixed"><parent link="base"/><child link="arm"/><origin xyz="1 0 0" rpy="0 0 1.5707963267948966"/></joint>
    <link name="arm">
      <inertial><mass value="1"/><inertia ixx="0.1" iyy="0.1" izz="0.1" ixy="0" ixz="0" iyz="0"/></inertial>
      <collision><origin xyz="0.5 0 0"/><geometry><cylinder radius="0.1" length="0.8"/></geometry></collision>
    </link>
  </robot>)";
  const core::BodySpec b = io::loadUrdfString(xml, "test.urdf");
  ASSERT_EQ(b.collision.size(), 3u);
  EXPECT_EQ(b.collision[0].kind, core::CollisionShape::Kind::kBox);
  EXPECT_EQ(b.collision[0].size, Vec3(0.2, 0.4, 0.6));
  EXPECT_LT((b.collision[0].X_LS.translation - Vec3(0, 0, 0.5)).norm(), 1e-15);
  EXPECT_EQ(b.collision[1].kind, core::CollisionShape::Kind::kSphere);
  EXPECT_EQ(b.collision[1].radius, 0.3);
  EXPECT_EQ(b.collision[2].kind, core::CollisionShape::Kind::kCylinder);
  EXPECT_EQ(b.collision[2].radius, 0.1);
  EXPECT_EQ(b.collision[2].length, 0.8);
  // The arm is 1 m along x, turned 90° about z: its 0.5 m along x is world +y.
  EXPECT_LT((b.collision[2].X_LS.translation - Vec3(1, 0.5, 0)).norm(), 1e-15);
}

TEST(UrdfCollision, BadGeometryIsRefusedNamingTheLink) {
  const std::string head = R"(<robot name="r"><link name="base">
      <inertial><mass value="1"/><inertia ixx="0.1" iyy="0.1" izz="0.1" ixy="0" ixz="0" iyz="0"/></inertial>)";
  expectThrowsWith<io::UrdfError>(
      [&] {
        io::loadUrdfString(
            head + R"(<collision><geometry><sphere radius="-0.1"/></geometry></collision></link></robot>)", "t");
      },
      {"link 'base' <collision> 0", "sphere radius = -0.1"});
  // A size of 0 is a placeholder: dropped, and said (strictly, refused).
  std::vector<std::string> notes;
  const std::string zero = head + R"(<collision><geometry><sphere radius="0"/></geometry></collision></link></robot>)";
  EXPECT_TRUE(io::loadUrdfString(zero, "t", "", io::UrdfOptions{true, &notes}).collision.empty());
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].find("1 <collision> of size 0 has no volume and was dropped: 'base' <collision> 0"),
            std::string::npos)
      << notes[0];
  expectThrowsWith<io::UrdfError>(
      [&] {
        io::loadUrdfString(zero, "t", "", io::UrdfOptions{false, nullptr});
      },
      {"link 'base' <collision> 0", "sphere radius = 0"});
  expectThrowsWith<io::UrdfError>(
      [&] {
        io::loadUrdfString(
            head +
                R"(<collision><geometry><mesh filename="file:///nope/x.stl"/></geometry></collision></link></robot>)",
            "t");
      },
      {"link 'base' <collision> 0", "/nope/x.stl"});
}

TEST(Bunny, LoadsWithoutRosAndRestsOnTheGround) {
  ::unsetenv("ROS_PACKAGE_PATH");
  const core::BodySpec bunny = io::loadUrdfFile(std::string(RBS_SOURCE_DIR) + "/urdf/bunny.urdf");
  ASSERT_EQ(bunny.collision.size(), 1u);
  EXPECT_EQ(bunny.collision[0].mesh.vertices.size(), 162u);
  io::SimConfig config = io::parseConfig(YAML::Load("initial: {position: [0, 0, 0.5], rpy: [0.5, 0.2, 0]}"));
  const core::Model model = io::buildModel(config, bunny);
  EXPECT_FALSE(model.body(0).q_LB.isApprox(Quat::Identity()));  // ixz ≠ 0: turned principal axes
  core::State s;
  s.bodies = {core::bodyStateFromLink(model.body(0), config.initial)};
  core::Workspace ws;
  double deepest = 0.0;
  for (int n = 0; n < 10000; ++n) {  // a rounded body rocks for a while
    core::step(model, s, {}, &ws);
    deepest = std::max(deepest, ws.deepest_penetration);
  }
  EXPECT_TRUE(core::atRest(model, s.bodies[0]));
  EXPECT_LT(deepest, 1e-3);
  // Resting: its lowest vertex is on the ground.
  EXPECT_NEAR(core::minSeparation(model, s.bodies[0], 0, 1.0), 0.0, 2e-4);
}

}  // namespace
}  // namespace rigid_body_sim::test
