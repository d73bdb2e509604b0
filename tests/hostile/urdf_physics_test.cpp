// URDFs with what ODE would assert on (a bad inertia, absurd sizes and offsets) or a broken tree:
// each refused at load with file:line, the link or joint, the value and the accepted range; the
// process exits 1 (no signal) and writes no report.
#include <sstream>

#include "tests/hostile/arm_urdf.hpp"
#include "tests/hostile/hostile_support.hpp"

namespace stride::hostile {
namespace {

const char* kTip = R"(  <link name="tip"><inertial><mass value="0.1"/>
    <inertia ixx="1e-4" iyy="1e-4" izz="1e-4" ixy="0" ixz="0" iyz="0"/></inertial></link>
)";

// Loads `urdf` in a scene and runs it; expects a refusal naming each of `parts`.
void expect_urdf_refused(const std::string& urdf, const std::vector<std::string>& parts) {
  Scratch s;
  s.write("r.urdf", urdf);
  const std::string scene = s.write(
      "r.xml",
      "<scene>\n<physics iterations=\"10\"/>\n<robot name=\"r\" urdf=\"r.urdf\"/>\n</scene>\n");
  const std::string report = s.path("report.json");
  expect_refused(run_stride({"run", scene, "--seconds", "0.05", "--report", report}), parts);
  EXPECT_FALSE(fs::exists(report));
}

TEST(HostileUrdf, TheArmItselfLoadsAndRuns) {
  Scratch s;
  s.write("r.urdf", Arm().text());
  const std::string scene = s.write("r.xml", "<scene><robot name=\"r\" urdf=\"r.urdf\"/></scene>");
  const auto r = run_stride({"run", scene, "--seconds", "0.05", "--report", s.path("r.json")});
  EXPECT_EQ(r.exit_status, 0) << r.err;
  EXPECT_TRUE(fs::exists(s.path("r.json")));
}

TEST(HostileUrdf, NumbersAreFiniteTokensSplitAtAnyWhitespace) {
  Arm a;
  a.origin = "0 0 nan";
  expect_urdf_refused(
      a.text(), {"r.urdf:10: joint 'j1': attribute 'xyz' = '0 0 nan' (expected finite numbers)"});
  a.origin = "0 0 0.1x";
  expect_urdf_refused(
      a.text(), {"r.urdf:10: joint 'j1': attribute 'xyz' = '0 0 0.1x' (expected finite numbers)"});
  a.origin = "0 0 0.1 0";
  expect_urdf_refused(a.text(),
                      {"r.urdf:10: joint 'j1' origin: attribute 'xyz'", "(expected 3 numbers)"});
  a.origin = " 0  0 0.1 ";  // leading, doubled and trailing spaces separate numbers as one does
  Scratch s;
  s.write("r.urdf", a.text());
  const std::string scene = s.write("r.xml", "<scene><robot name=\"r\" urdf=\"r.urdf\"/></scene>");
  const auto r = run_stride({"run", scene, "--seconds", "0.01"});
  EXPECT_EQ(r.exit_status, 0) << r.err;
}

TEST(HostileUrdf, InertiaNotPositiveDefinite) {
  Arm a;
  a.inertia = R"(ixx="0.01" iyy="0.01" izz="0.01" ixy="0.02" ixz="0" iyz="0")";
  expect_urdf_refused(
      a.text(), {"r.urdf:5: link 'base': inertia not positive definite",
                 "principal moments -0.01, 0.01, 0.03 kg*m^2", "expected each in [1e-12, 100000]"});
}

TEST(HostileUrdf, InertiaViolatesTheTriangleInequality) {
  Arm a;
  a.inertia = R"(ixx="0.01" iyy="0.01" izz="0.05" ixy="0" ixz="0" iyz="0")";
  expect_urdf_refused(a.text(), {"r.urdf:5: link 'base': inertia violates the triangle inequality",
                                 "0.01, 0.01, 0.05 kg*m^2"});
}

TEST(HostileUrdf, DenormalAndHugeInertias) {
  Arm a;
  a.inertia = R"(ixx="1e-310" iyy="1e-310" izz="1e-310" ixy="0" ixz="0" iyz="0")";
  expect_urdf_refused(a.text(), {"r.urdf:5: link 'base': inertia principal moments 1e-310",
                                 "outside [1e-12, 100000]"});
  a.inertia = R"(ixx="1e300" iyy="1e300" izz="1e300" ixy="0" ixz="0" iyz="0")";
  expect_urdf_refused(a.text(), {"r.urdf:5: link 'base': inertia principal moments 1e+300",
                                 "outside [1e-12, 100000]"});
}

// A mass without rotational inertia (the physics fuzzer's find: ODE's step went NaN and aborted);
// a massless frame link may still leave it out.
TEST(HostileUrdf, MassWithoutInertia) {
  Arm a;
  a.inertia = R"(ixx="0" iyy="0" izz="0" ixy="0" ixz="0" iyz="0")";
  expect_urdf_refused(a.text(), {"r.urdf:5: link 'base': zero inertia for a mass of 1 kg",
                                 "expected principal moments in [1e-12, 100000] kg*m^2",
                                 "only a link of at most 1e-06 kg may have none"});
  a.inertia = "zzz=\"0\"";
  std::string text = a.text();
  const std::string element = "      <inertia zzz=\"0\"/>";
  ASSERT_NE(text.find(element), std::string::npos);
  text.erase(text.find(element), element.size());
  expect_urdf_refused(text,
                      {"r.urdf:4: link 'base': <inertial> without <inertia> for a mass of 1 kg"});
  // A massless frame link may touch nothing (the fuzzer's next find: a massless root link with a
  // box, whose ground contact drove ODE's step to NaN).
  a.mass = "0";
  text = a.text();
  text.erase(text.find(element), element.size());
  expect_urdf_refused(text, {"r.urdf:6: link 'base': a collision shape on a link of mass 0 kg",
                             "expected an <inertial> with a mass over 1e-06 kg and its inertia"});
}

TEST(HostileUrdf, HugeMass) {
  Arm a;
  a.mass = "1e300";
  expect_urdf_refused(a.text(),
                      {"r.urdf:4: link 'base' mass: value 1e+300 kg outside [0, 100000]"});
}

TEST(HostileUrdf, AbsurdShapesAndOffsets) {
  Arm a;
  a.cylinder = R"(radius="0.02" length="1e19")";
  expect_urdf_refused(a.text(),
                      {"r.urdf:16: link 'arm' cylinder: length 1e+19 m outside [1e-06, 1000]"});
  a = Arm();
  a.origin = "0 0 1e308";
  expect_urdf_refused(a.text(),
                      {"r.urdf:10: joint 'j1' origin: xyz 1e+308 m outside [-1000, 1000]"});
}

TEST(HostileUrdf, BoxesWithNegativeZeroOrTwoSizes) {
  Arm a;
  a.box = "-0.1 0.1 0.1";
  expect_urdf_refused(a.text(), {"r.urdf:6: link 'base' box: size -0.1 m outside [1e-06, 1000]"});
  a.box = "0.1 0 0.1";
  expect_urdf_refused(a.text(), {"r.urdf:6: link 'base' box: size 0 m outside [1e-06, 1000]"});
  a.box = "0.1 0.1";
  expect_urdf_refused(a.text(),
                      {"r.urdf:6: link 'base' box: size '0.1 0.1' (expected three lengths)"});
}

TEST(HostileUrdf, ZeroJointAxis) {
  Arm a;
  a.axis = "0 0 0";
  expect_urdf_refused(a.text(),
                      {"r.urdf:10: joint 'j1': zero axis '0 0 0' (expected a non-zero direction)"});
  // An <axis> whose xyz is missing (the physics fuzzer's find: ODE aborted normalising it).
  a.axis = "0 1 0";
  std::string text = a.text();
  const std::string with_xyz = "<axis xyz=\"0 1 0\"/>";
  ASSERT_NE(text.find(with_xyz), std::string::npos);
  text.replace(text.find(with_xyz), with_xyz.size(), "<axis/>");
  expect_urdf_refused(text, {"r.urdf:10: joint 'j1': <axis> without attribute 'xyz' (expected a "
                             "direction, e.g. \"0 0 1\")"});
}

TEST(HostileUrdf, LinkWithTwoParents) {
  Arm a;
  a.extra =
      "  <joint name=\"j2\" type=\"fixed\"><parent link=\"base\"/><child link=\"arm\"/>"
      "</joint>\n";
  expect_urdf_refused(a.text(), {"r.urdf:18: link 'arm' has two parents: joint 'j1' (line 8) "
                                 "and joint 'j2' (line 18)"});
}

TEST(HostileUrdf, JointCycle) {
  Arm a;  // tip and tip2 hang from each other, apart from the arm's tree
  a.extra = std::string(kTip) + R"(  <link name="tip2"/>
  <joint name="j2" type="fixed"><parent link="tip"/><child link="tip2"/></joint>
  <joint name="j3" type="fixed"><parent link="tip2"/><child link="tip"/></joint>
)";
  expect_urdf_refused(a.text(), {"r.urdf:22: joint cycle: link 'tip' <- 'tip2' <- 'tip'"});
}

TEST(HostileUrdf, MimicOfItselfAndMimicCycle) {
  Arm a;
  a.extra = std::string(kTip) +
            R"(  <joint name="j2" type="revolute"><parent link="arm"/><child link="tip"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/><mimic joint="j2"/></joint>
)";
  expect_urdf_refused(a.text(), {"r.urdf:20: joint 'j2': mimics itself (expected another joint)"});
  a.extra = std::string(kTip) + R"(  <link name="tip2"/>
  <joint name="j2" type="revolute"><parent link="arm"/><child link="tip"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/><mimic joint="j3"/></joint>
  <joint name="j3" type="revolute"><parent link="tip"/><child link="tip2"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/><mimic joint="j2"/></joint>
)";
  expect_urdf_refused(a.text(), {"r.urdf:21: joint 'j2': mimics 'j3', which itself mimics 'j2' "
                                 "(expected a joint that mimics none)"});
}

// Before: a stack overflow in the recursive loader. The tree walks are iterative now, and a
// robot has at most 1000 links.
TEST(HostileUrdf, FiftyThousandLinkChain) {
  std::ostringstream u;
  u << "<?xml version=\"1.0\"?>\n<robot name=\"chain\">\n";  // lines 1-2
  for (int i = 0; i < 50000; ++i) {
    u << "<link name=\"l" << i << "\"><inertial><mass value=\"0.01\"/><inertia ixx=\"1e-6\" "
      << "iyy=\"1e-6\" izz=\"1e-6\" ixy=\"0\" ixz=\"0\" iyz=\"0\"/></inertial></link>\n";
    if (i > 0)
      u << "<joint name=\"j" << i << "\" type=\"fixed\"><parent link=\"l" << i - 1
        << "\"/><child link=\"l" << i << "\"/><origin xyz=\"0 0 0.001\"/></joint>\n";
  }
  u << "</robot>\n";
  // Link 1000 (the first one too many) is on line 3 + 1000 * 2 - 1.
  expect_urdf_refused(u.str(), {"r.urdf:2002: robot with 50000 links (at most 1000)"});
}

}  // namespace
}  // namespace stride::hostile
