// Console commands with absurd values (push and mv near the double range, runs of 1e300 s, NaN
// into a representation) and unsafe files for call, --script, load and log load: each refused
// with one line (exit 1 in a script, never a signal), and the simulation exactly as before.
#include <sys/stat.h>

#include <sstream>

#include "console/interpreter/interpreter.hpp"
#include "console/target/local_target.hpp"
#include "tests/hostile/hostile_support.hpp"

namespace stride::hostile {
namespace {

const std::string kStand = source_path("scenes/nao_stand_controlled.xml");

void expect_command_refused(const std::string& commands, const std::vector<std::string>& parts) {
  expect_refused(run_stride({"-c", commands, kStand}), parts);
}

TEST(HostileConsole, PushAndMoveNearTheDoubleRange) {
  expect_command_refused("push torso 1e308 0 0 0.1; run 0.05",
                         {"-c:1: push: fx: 1e+308 N outside [-1e+07, 1e+07]"});
  expect_command_refused("push torso 0 0 1e12 0.1",
                         {"-c:1: push: fz: 1e+12 N outside [-1e+07, 1e+07]"});
  expect_command_refused("push torso 10 0 0 1e300",
                         {"-c:1: push: seconds: 1e+300 s outside [0, 1e+06]"});
  expect_command_refused("mv 1e308 0 0.3; run 0.02",
                         {"-c:1: mv: x: 1e+308 m outside [-10000, 10000]"});
  expect_command_refused("mv 0 0 1e300", {"-c:1: mv: z: 1e+300 m outside [-10000, 10000]"});
  expect_command_refused("mv 0 0 0.3 1e300", {"-c:1: mv: yaw: 1e+300 rad outside [-1000, 1000]"});
}

TEST(HostileConsole, RunsAndTimeoutsAreCapped) {
  expect_command_refused("run 1e300", {"-c:1: run: seconds: 1e+300 s outside [0, 1e+06]"});
  expect_command_refused("wait until sim.time > 1 timeout 1e20",
                         {"-c:1: wait: timeout: 1e+20 s outside [0, 1e+06]"});
  expect_refused(run_stride({"run", kStand, "--seconds", "1e300"}),
                 {"stride run: --seconds: 1e+300 s outside [0, 1e+06]"}, 2);
}

TEST(HostileConsole, SetRejectsNanAndInfinityInARepresentation) {
  expect_command_refused("set representation:JointRequest position[3]=nan",
                         {"-c:1: JointRequest.position[3]: expected a finite number, got 'nan'"});
  expect_command_refused("set representation:JointRequest position[3]=-inf",
                         {"expected a finite number, got '-inf'"});
  expect_command_refused("set representation:JointRequest position[3]=1e400",
                         {"expected a number, got '1e400'"});  // beyond the double range
}

// In one process: the refused commands leave the simulation bit for bit where it was.
TEST(HostileConsole, RefusedCommandsChangeNothing) {
  const auto hash_after = [](const std::vector<std::string>& lines) {
    console::LocalTarget target;
    std::ostringstream out;
    console::Interpreter in(target, out);
    in.execute("load " + kStand);
    for (const auto& l : lines) in.execute_reporting(l);
    return target.get("sim.hash") + " t=" + target.get("sim.time");
  };
  const std::string clean = hash_after({"run 0.05", "run 0.05"});
  EXPECT_EQ(hash_after({"run 0.05", "push torso 1e308 0 0 0.1", "mv 1e308 0 0.3", "run 1e300",
                        "set representation:JointRequest position[3]=nan",
                        "push torso 1e7 0 0 1e300", "run 0.05"}),
            clean);
}

TEST(HostileConsole, UnsafeFilesForScriptCallLoadAndLogLoad) {
  Scratch s;
  ASSERT_EQ(mkfifo(s.path("pipe").c_str(), 0600), 0);
  { std::ofstream big(s.path("big.log")); }
  fs::resize_file(s.path("big.log"), (8ull << 30) + 1);  // sparse
  expect_refused(run_stride({"--script", "/dev/zero"}),
                 {"script '/dev/zero': not a regular file (a character device)"});
  expect_refused(run_stride({"--script", s.path("pipe")}),
                 {"script '" + s.path("pipe") + "': not a regular file (a FIFO)"});
  expect_command_refused("call /dev/urandom",
                         {"-c:1: script '/dev/urandom': not a regular file (a character device)"});
  expect_command_refused("load " + s.dir.string(), {"-c:1: scene '" + s.dir.string() +
                                                    "': not a regular file (a directory)"});
  expect_command_refused("log load " + s.path("pipe"),
                         {"-c:1: log '" + s.path("pipe") + "': not a regular file (a FIFO)"});
  expect_command_refused("log load /dev/urandom",
                         {"-c:1: log '/dev/urandom': not a regular file (a character device)"});
  expect_command_refused(
      "log load " + s.path("big.log"),
      {"-c:1: log '" + s.path("big.log") + "': 8589934593 bytes, over the limit of 8 GiB"});
}

// A name longer than the system's limit (255 bytes a component) made std::filesystem throw past
// every handler (a call in a script, a --physics setting naming itself as the file): SIGABRT.
TEST(HostileConsole, NamesLongerThanTheSystemAllows) {
  const std::string name(300, 'a');
  expect_command_refused("call " + name,
                         {"-c:1: script '" + name + "': cannot open: File name too long"});
  expect_refused(run_stride({"sweep", source_path("scenes/experiments/posture.sweep.xml"),
                             "--physics", "solver=" + name}),
                 {"--physics: physics setting 'solver=", "(300 characters)",
                  "(expected one of exact, iterative, cg)"},
                 2);
}

}  // namespace
}  // namespace stride::hostile
