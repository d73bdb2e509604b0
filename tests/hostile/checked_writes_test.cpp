// Every output checks its writes and its close: /dev/full or a full disk (a file size limit
// stands in for one) is an error naming the path and a non-zero exit, never "wrote ..." with
// exit 0, and no partial file is left where the output should be.
#include "tests/hostile/hostile_support.hpp"

namespace stride::hostile {
namespace {

const std::string kStand = source_path("scenes/nao_stand_controlled.xml");
const char* kFull = "cannot write '/dev/full': No space left on device";

TEST(CheckedWrites, RunOutputsToDevFull) {
  expect_refused(run_stride({"run", kStand, "--seconds", "0.02", "--report", "/dev/full"}), {kFull},
                 1);
  expect_refused(run_stride({"run", kStand, "--seconds", "0.02", "--log", "/dev/full"}), {kFull},
                 1);
  expect_refused(run_stride({"run", kStand, "--seconds", "0.02", "--snapshot", "/dev/full"}),
                 {kFull}, 1);
  expect_refused(run_stride({"pattern", "--csv", "/dev/full"}), {kFull}, 1);
}

TEST(CheckedWrites, StandardOutputToDevFull) {
  const auto r = console::run_child(
      {"sh", "-c", "exec \"$0\" run \"$1\" --seconds 0.02 > /dev/full", stride_binary(), kStand},
      "");
  EXPECT_EQ(r.signal, 0);
  EXPECT_EQ(r.exit_status, 1);
  EXPECT_EQ(r.err, "stride: cannot write standard output: No space left on device\n");
}

TEST(CheckedWrites, ConsoleOutputsToDevFull) {
  Scratch s;
  for (const std::string& c : {std::string("report /dev/full"),
                               "log start " + s.path("a.log") + "; run 0.03; log stop; log load " +
                                   s.path("a.log") + "; log export /dev/full FrameInfo.time",
                               "log start " + s.path("b.log") + "; run 0.03; log save /dev/full",
                               std::string("plot sim.time to /dev/full; run 0.02; plot stop")}) {
    const auto r = run_stride({"-c", c, kStand});
    expect_refused(r, {"cannot write '/dev/full"}, 1);
  }
}

// A disk that fills up: the process's file size limit makes every write past 64 KiB (a log header
// with its recorded configuration takes ~16 KiB) fail (EFBIG) as ENOSPC would; SIGXFSZ is ignored
// so the write returns the error.
console::ChildResult run_with_full_disk(const std::vector<std::string>& args) {
  std::vector<std::string> argv = {"sh", "-c", "trap '' XFSZ; ulimit -f 64; exec \"$@\"", "sh",
                                   stride_binary()};
  argv.insert(argv.end(), args.begin(), args.end());
  return console::run_child(argv, "");
}

TEST(CheckedWrites, FullDiskLeavesNoPartialOutput) {
  Scratch s;
  const std::string report = s.path("report.json"), csv = s.path("pattern.csv");
  expect_refused(run_with_full_disk({"pattern", "--csv", csv}),
                 {"cannot write '" + csv + "': File too large"}, 1);
  EXPECT_TRUE(fs::is_empty(s.dir)) << "no file, no temporary";
  // A log keeps every frame written before the disk filled: the rest is refused loudly.
  const std::string log = s.path("run.log");
  const auto r = run_with_full_disk({"run", kStand, "--seconds", "1", "--log", log});
  expect_refused(r, {"cannot write '" + log + "': File too large"}, 1);
  const auto load = run_stride({"-c", "log load " + log, kStand});
  EXPECT_EQ(load.exit_status, 0) << load.err;
  EXPECT_NE(load.out.find(" complete, 0 damaged"), std::string::npos) << load.out;
}

}  // namespace
}  // namespace stride::hostile
