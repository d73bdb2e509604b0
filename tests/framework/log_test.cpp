// Logs: record every frame, survive truncation, replay bit for bit, step through, export CSV.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "robot/runtime/log_format.hpp"
#include "robot/runtime/replay.hpp"
#include "tests/framework/fake_link.hpp"

namespace stride {
namespace {

std::string temp_path(const std::string& name) {
  return (std::filesystem::path(::testing::TempDir()) / name).string();
}

// Records `frames` frames of the test configuration into `path`.
void record(const std::string& path, int frames, const RuntimeConfig& config) {
  const auto registry = test::test_registry();
  test::FakeLink link(0.01);
  Runtime rt(registry, config, link);
  rt.start_log(path);
  for (int i = 0; i < frames; ++i) rt.step();
}

TEST(Log, RecordsEveryRepresentationEveryFrame) {
  const auto path = temp_path("stride_log_all.log");
  record(path, 20, test::test_config());
  LogReader log(path);
  EXPECT_EQ(log.frame_count(), 20u);
  EXPECT_FALSE(log.truncated());
  for (const char* name :
       {"SensorFrame", "FrameInfo", "ModuleTimes", "Counter", "Doubled", "JointSensorData",
        "InertialSensorData", "FsrSensorData", "JointRequest", "ActuatorFrame"})
    EXPECT_GE(log.index_of(name), 0) << name;
  for (std::size_t f = 0; f < 20; ++f) {
    EXPECT_EQ(log.read<FrameInfo>(f).frame, static_cast<std::int64_t>(f));
    EXPECT_EQ(log.read<test::Doubled>(f).n, 2 * static_cast<std::int64_t>(f));
  }
  EXPECT_EQ(log.text(3, "Counter"), "{n=3}");
}

TEST(Log, TruncatedInTheMiddleOfAFrameOpensWithEveryCompleteFrame) {
  const auto path = temp_path("stride_log_cut.log");
  record(path, 10, test::test_config());
  const auto full = std::filesystem::file_size(path);
  // Cut half-way through the last frame (its frame header plus each part's prefix and bytes).
  LogReader whole(path);
  const auto last_frame_bytes = [&] {
    std::size_t n = log_format::kFrameHeaderBytes;
    for (std::size_t i = 0; i < whole.types().size(); ++i) n += 4 + whole.bytes(9, int(i)).size();
    return n;
  }();
  std::filesystem::resize_file(path, full - last_frame_bytes / 2);
  LogReader cut(path);
  EXPECT_EQ(cut.frame_count(), 9u);
  EXPECT_TRUE(cut.truncated());
  for (std::size_t f = 0; f < 9; ++f)
    EXPECT_EQ(cut.bytes(f, "JointRequest"), whole.bytes(f, "JointRequest"));
  EXPECT_THROW(cut.bytes(9, "JointRequest"), Error);
  // A cut inside the header is an error that says so.
  std::filesystem::resize_file(path, 20);
  try {
    LogReader bad(path);
    FAIL() << "a log without a complete header opened";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("bad header"), std::string::npos) << e.what();
  }
}

TEST(Log, ReplayReproducesEveryRepresentationBitForBit) {
  const auto path = temp_path("stride_log_replay.log");
  record(path, 40, test::test_config());
  LogReader log(path);
  const auto registry = test::test_registry();
  const auto result = replay_and_compare(log, registry, test::test_config());
  EXPECT_EQ(result.frames, 40u);
  EXPECT_EQ(result.compared.size(), log.types().size() - 1);  // all but ModuleTimes
  EXPECT_TRUE(result.mismatches.empty()) << result.mismatches.front().representation;

  // The comparison does detect a different controller: another knee angle.
  auto changed = test::test_config();
  changed.parameters = {{"Stand.knee_pitch", "0.7"}};
  const auto differs = replay_and_compare(log, registry, changed);
  ASSERT_FALSE(differs.mismatches.empty());
  EXPECT_EQ(differs.mismatches.front().frame, 0u);
  EXPECT_EQ(differs.mismatches.front().representation, "JointRequest");
}

TEST(Log, GotoFramePutsALoggedFrameOnTheBlackboard) {
  const auto path = temp_path("stride_log_goto.log");
  record(path, 15, test::test_config());
  LogReader log(path);
  const auto registry = test::test_registry();
  test::FakeLink link;
  Runtime rt(registry, test::test_config(), link);
  EXPECT_TRUE(rt.load_frame(log, 12).empty());
  EXPECT_EQ(rt.get("representation:FrameInfo.frame"), "12");
  EXPECT_EQ(rt.get("representation:Doubled"), "{n=24}");
  EXPECT_EQ(rt.get("representation:JointRequest"), log.text(12, "JointRequest"));
}

TEST(Log, ExportsChosenFieldsToCsv) {
  const auto path = temp_path("stride_log_csv.log");
  record(path, 3, test::test_config());
  LogReader log(path);
  std::ostringstream out;
  export_csv(log, {"FrameInfo.time", "Doubled", "FsrSensorData.cop_left"}, out);
  std::istringstream lines(out.str());
  std::string line;
  std::getline(lines, line);
  EXPECT_EQ(line,
            "frame,FrameInfo.time,Doubled.n,FsrSensorData.cop_left[0],FsrSensorData.cop_left[1]");
  std::getline(lines, line);
  const auto fsr = log.read<FsrSensorData>(0);
  EXPECT_EQ(line, "0,0,0," + print_value(*describe<double>(), Value{fsr.cop_left.x()}) + "," +
                      print_value(*describe<double>(), Value{fsr.cop_left.y()}));
  std::getline(lines, line);
  EXPECT_EQ(line.substr(0, 9), "1,0.01,2,");
  EXPECT_THROW(export_csv(log, {"Ball.x"}, out), Error);
}

}  // namespace
}  // namespace stride
