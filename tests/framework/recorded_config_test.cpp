// A log carries the providers and parameters it was recorded with: a log recorded after a
// provider swap and a parameter change replays with them (0 mismatches), `log info` lists them,
// and a log written before logs carried them still opens.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "robot/runtime/recorded_config.hpp"
#include "robot/runtime/replay.hpp"
#include "tests/framework/fake_link.hpp"

namespace stride {
namespace {

std::string temp_path(const std::string& name) {
  return (std::filesystem::path(::testing::TempDir()) / name).string();
}

bool has_line(const std::vector<std::string>& lines, const std::string& line) {
  return std::find(lines.begin(), lines.end(), line) != lines.end();
}

TEST(RecordedConfig, ALogRecordedAfterASwapReplaysWithWhatRan) {
  const auto registry = test::test_registry();
  const std::string path = temp_path("stride_recorded_config.log");
  {
    test::FakeLink link(0.01);
    Runtime rt(registry, test::test_config(), link);
    rt.swap_provider("Counter", "CounterAfterStand");  // the console's `mr`
    rt.set_parameters("Stand", "knee_pitch=0.625");
    rt.start_log(path);
    for (int i = 0; i < 20; ++i) rt.step();
  }
  LogReader log(path);
  ASSERT_EQ(log.frame_count(), 20u);
  EXPECT_EQ(log.read<test::Counter>(3).n, -1003);  // the swapped-in provider ran
  const RuntimeConfig recorded = recorded_config(log.metadata(), test::test_config());
  EXPECT_EQ(recorded.providers.at("Counter"), "CounterAfterStand");
  EXPECT_EQ(recorded.providers.at("JointRequest"), "Stand");
  EXPECT_EQ(recorded.parameters.at("Stand.knee_pitch"), "0.625");
  EXPECT_EQ(recorded.parameters.at("SensorConversion.contact_force"), "2");

  // The scene's configuration says CounterFromFrame: replayed with it, Counter differs at once.
  const ReplayResult scene = replay_and_compare(log, registry, test::test_config());
  ASSERT_FALSE(scene.mismatches.empty());
  EXPECT_EQ(scene.mismatches.front().frame, 0u);
  // With what the log says it ran with, every representation matches.
  const ReplayResult r = replay_and_compare(log, registry, recorded);
  EXPECT_EQ(r.frames, 20u);
  EXPECT_TRUE(std::find(r.compared.begin(), r.compared.end(), "Counter") != r.compared.end());
  EXPECT_TRUE(r.mismatches.empty())
      << r.mismatches.size() << " mismatches, first in frame " << r.mismatches.front().frame << ": "
      << r.mismatches.front().representation;

  const auto info = log_info_lines(log);
  EXPECT_EQ(info.front(), "frames: 20, t = 0 .. 0.19 s");
  EXPECT_TRUE(has_line(info, "  Counter <- CounterAfterStand"));
  EXPECT_TRUE(has_line(info, "  ActuatorFrame <- ActuatorConversion"));
  EXPECT_TRUE(has_line(info, "  Counter, 8 bytes a frame"));
}

TEST(RecordedConfig, ALogWithoutMetadataOpensAndReplaysWithTheGivenConfig) {
  // Bytes of a log written before logs carried metadata: the header ends after the types.
  const std::string path = temp_path("stride_no_metadata.log");
  {
    std::ofstream out(path, std::ios::binary);
    const std::uint32_t header_size = 4, types = 0;
    out << "STRDLOG1";
    out.write(reinterpret_cast<const char*>(&header_size), 4);
    out.write(reinterpret_cast<const char*>(&types), 4);
  }
  LogReader log(path);
  EXPECT_TRUE(log.metadata().empty());
  EXPECT_FALSE(has_recorded_config(log.metadata()));
  EXPECT_EQ(recorded_config(log.metadata(), test::test_config()).providers,
            test::test_config().providers);
  EXPECT_TRUE(has_line(log_info_lines(log),
                       "providers: not recorded (a log written before logs carried them)"));
}

}  // namespace
}  // namespace stride
