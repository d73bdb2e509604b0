// Scenes: a single-instance element given twice is an error naming both places; an include of a
// directory, a device, a FIFO or an oversized file is refused before it is read; scene limits
// and absurd placements are refused at load. The process exits 3 (bad input; 1 for a run that
// diverges) and writes nothing.
#include <sys/stat.h>

#include <fstream>
#include <regex>

#include "tests/hostile/arm_urdf.hpp"
#include "tests/hostile/hostile_support.hpp"

namespace stride::hostile {
namespace {

const std::string kNaoUrdf = source_path("scenes/robots/nao/nao.urdf");
const std::string kNaoDevices = source_path("scenes/robots/nao/nao.devices.xml");

// Runs `scene` (written as s.xml beside an r.urdf arm) and expects a refusal naming `parts`.
void expect_scene_refused(const Scratch& s, const std::string& scene,
                          const std::vector<std::string>& parts, int status = 3) {
  if (!fs::exists(s.path("r.urdf"))) s.write("r.urdf", Arm().text());
  const std::string path = s.write("s.xml", scene);
  const std::string report = s.path("report.json");
  expect_refused(run_stride({"run", path, "--seconds", "0.02", "--report", report}), parts, status);
  EXPECT_FALSE(fs::exists(report));
}

TEST(HostileScene, PhysicsAndGroundGivenTwice) {
  Scratch s;
  expect_scene_refused(s,
                       "<scene>\n<physics iterations=\"10\"/>\n<physics step=\"2ms\"/>\n</scene>",
                       {"s.xml:3: <physics>: given twice (first at " + s.path("s.xml") + ":2;"});
  expect_scene_refused(s, "<scene>\n<ground friction=\"1\"/>\n<box/>\n<ground/>\n</scene>",
                       {"s.xml:4: <ground>: given twice (first at " + s.path("s.xml") + ":2;"});
}

TEST(HostileScene, PhysicsInAnIncludeAndInTheScene) {
  Scratch s;
  s.write("common.xml", "<scene>\n<physics iterations=\"20\"/>\n</scene>\n");
  expect_scene_refused(
      s, "<scene>\n<include file=\"common.xml\"/>\n<physics iterations=\"10\"/>\n</scene>",
      {"s.xml:3: <physics>: given twice (first at " + s.path("common.xml") + ":2;"});
}

TEST(HostileScene, ParameterForOneFieldTwice) {
  Scratch s;
  expect_scene_refused(s,
                       "<scene>\n<robot name=\"nao\" urdf=\"" + kNaoUrdf + "\" devices=\"" +
                           kNaoDevices +
                           "\">\n<controller>\n"
                           "<parameter module=\"Stand\" field=\"knee_pitch\" value=\"0.5\"/>\n"
                           "<parameter module=\"Stand\" field=\"knee_pitch\" value=\"0.6\"/>\n"
                           "</controller>\n</robot>\n</scene>",
                       {"s.xml:5: <parameter>: parameter Stand.knee_pitch given twice (first at " +
                        s.path("s.xml") + ":4)"});
}

TEST(HostileScene, DeviceFileServoForOneJointTwice) {
  Scratch s;
  std::ifstream in(kNaoDevices);
  std::string devices((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto end = devices.rfind("</devices>");
  const int line = static_cast<int>(std::count(devices.begin(), devices.begin() + end, '\n')) + 1;
  devices.insert(end, "<servo joint=\"LKneePitch\" motor=\"pitch\"/>\n");
  s.write("d.xml", devices);
  std::smatch first;
  std::regex_search(devices, first, std::regex("<servo joint=\"LKneePitch\""));
  const int first_line =
      static_cast<int>(std::count(devices.begin(), devices.begin() + first.position(0), '\n')) + 1;
  expect_scene_refused(
      s, "<scene>\n<robot name=\"nao\" urdf=\"" + kNaoUrdf + "\" devices=\"d.xml\"/>\n</scene>",
      {"d.xml:" + std::to_string(line) +
       ": <servo>: joint 'LKneePitch' given "
       "twice (first at " +
       s.path("d.xml") + ":" + std::to_string(first_line) + ")"});
}

TEST(HostileScene, IncludesOfDirectoriesDevicesFifosAndHugeFilesAreRefusedBeforeReading) {
  Scratch s;
  ASSERT_EQ(mkfifo(s.path("pipe.xml").c_str(), 0600), 0);
  { std::ofstream big(s.path("big.xml")); }
  fs::resize_file(s.path("big.xml"), (64ull << 20) + 1);  // sparse: no disk used
  const std::pair<std::string, std::string> cases[] = {
      {s.dir.string(), "not a regular file (a directory)"},
      {"/dev/zero", "not a regular file (a character device)"},
      {"/dev/urandom", "not a regular file (a character device)"},
      {s.path("pipe.xml"), "not a regular file (a FIFO)"},
      {s.path("big.xml"), "67108865 bytes, over the limit of 64 MiB"}};
  for (const auto& [file, reason] : cases)
    expect_scene_refused(s, "<scene>\n<include file=\"" + file + "\"/>\n</scene>",
                         {"s.xml:2: <include>: included file '" + file + "': " + reason});
  // The scene named on the command line itself, too.
  expect_refused(run_stride({"run", "/dev/zero", "--seconds", "1"}),
                 {"scene '/dev/zero': not a regular file (a character device)"});
}

TEST(HostileScene, AbsurdPlacementsAndPushes) {
  Scratch s;
  expect_scene_refused(s,
                       "<scene>\n<robot name=\"r\" urdf=\"r.urdf\" xyz=\"1e300 0 0\"/>\n</scene>",
                       {"s.xml:2: <robot>: attribute 'xyz': 1e+300 m outside [-10000, 10000]"});
  expect_scene_refused(
      s,
      "<scene>\n<robot name=\"r\" urdf=\"r.urdf\"/>\n"
      "<push robot=\"r\" body=\"arm\" force=\"1e300 0 0\" duration=\"0.1\"/>\n</scene>",
      {"s.xml:3: <push>: attribute 'force': 1e+300 N outside [-1e+07, 1e+07]"});
  expect_scene_refused(s, "<scene>\n<box size=\"1 1 1\" xyz=\"0 0 -1e20\"/>\n</scene>",
                       {"s.xml:2: <box>: attribute 'xyz': -1e+20 m outside [-10000, 10000]"});
  expect_scene_refused(s, "<scene>\n<physics gravity=\"0 0 -1e9\"/>\n</scene>",
                       {"s.xml:2: <physics>: attribute 'gravity': -1e+09 outside [-1000, 1000]"});
}

// Within the limits a push can still make the state run away: the divergence check stops the run
// before ODE sees it (exit 1, no report), where ODE used to abort the process.
TEST(HostileScene, DivergingPushIsCaughtBeforeOde) {
  Scratch s;
  Arm light;
  light.mass = "2e-6";  // just over a frame link's mass, so it may touch the ground
  light.inertia = R"(ixx="1e-12" iyy="1e-12" izz="1e-12" ixy="0" ixz="0" iyz="0")";
  s.write("r.urdf", light.text());
  expect_scene_refused(
      s,
      "<scene>\n<robot name=\"r\" urdf=\"r.urdf\"/>\n"
      "<push robot=\"r\" body=\"base\" force=\"1e7 0 0\" at=\"0 0 0.05\" duration=\"1\"/>\n"
      "</scene>",
      {"physics diverged at t=0.001 s: robot 'r' link "}, 1);  // it ran and failed
}

TEST(HostileScene, SceneLimits) {
  Scratch s;
  std::string robots = "<scene>\n";
  for (int i = 0; i < 65; ++i)
    robots += "<robot name=\"r" + std::to_string(i) + "\" urdf=\"r.urdf\"/>\n";
  expect_scene_refused(s, robots + "</scene>", {"s.xml:66: <robot>: more than 64 robots"});
  const std::string patch = "<uneven size=\"20 20\" cell=\"0.045\"/>\n";  // 444 x 444 tiles
  expect_scene_refused(s, "<scene>\n" + patch + patch + patch + "</scene>",
                       {"s.xml:4: <uneven>: the scene's static shapes would number 591408 "
                        "(boxes, ramps and uneven tiles; at most 500000)"});
  // A robot with more collision shapes than the scene holds.
  std::string many =
      "<?xml version=\"1.0\"?>\n<robot name=\"many\"><link name=\"l\"><inertial><mass "
      "value=\"1\"/><inertia ixx=\"0.01\" iyy=\"0.01\" izz=\"0.01\" ixy=\"0\" ixz=\"0\" "
      "iyz=\"0\"/></inertial>\n";
  for (int i = 0; i < 20001; ++i)
    many += "<collision><geometry><sphere radius=\"0.01\"/></geometry></collision>\n";
  s.write("many.urdf", many + "</link></robot>\n");
  expect_scene_refused(s, "<scene>\n<robot name=\"m\" urdf=\"many.urdf\"/>\n</scene>",
                       {"s.xml:2: <robot name=\"m\">: the scene's robots have 20001 collision "
                        "shapes so far (at most 20000)"});
}

// A robot piled onto a fine floor finds more contact points than a step may hold.
TEST(HostileScene, TooManyContactsInOneStep) {
  Scratch s;
  Arm wide;
  wide.box = "12 12 0.1";
  s.write("r.urdf", wide.text());
  expect_scene_refused(s,
                       "<scene>\n<physics max_contacts=\"4\"/>\n<uneven size=\"12 12\" "
                       "cell=\"0.05\" height=\"0\"/>\n<robot name=\"r\" urdf=\"r.urdf\"/>\n"
                       "</scene>",
                       {"physics: ", " contact points in one step (at most 20000;"}, 1);
}

}  // namespace
}  // namespace stride::hostile
