// The progress line: its text, when it is drawn in each mode, and how the mode is chosen.
#include <gtest/gtest.h>

#include <sstream>
#include <thread>
#include <vector>

#include "console/progress/progress_line.hpp"
#include "tests/error_text.hpp"

namespace stride::console {
namespace {

using test_support::error_of;

ProgressSpec walks(double total) {
  return {.label = "posture", .total = total, .unit = "walks"};
}

// A clock the test moves by hand.
struct FakeClock {
  double t = 100;
  ProgressLine::Clock clock() {
    return [this] { return t; };
  }
};

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

TEST(ProgressText, CountsPercentageFailuresRateAndEta) {
  // 12 of 90 in 34 s: 0.353 walks/s, 78 left take 221 s.
  EXPECT_EQ(format_progress(walks(90), {.done = 12, .failed = 1, .elapsed = 34}),
            "posture: 12/90 walks (13 %), 1 failed, 34 s, 0.35 walks/s, ETA 3 min 41 s");
  EXPECT_EQ(format_progress(walks(90), {.done = 90, .elapsed = 180}),
            "posture: 90/90 walks (100 %), 3 min 00 s, 0.50 walks/s");
  // Nothing done yet: no rate, the ETA unknown.
  EXPECT_EQ(format_progress(walks(90), {.done = 0, .elapsed = 3}),
            "posture: 0/90 walks (0 %), 3 s, ETA ?");
}

TEST(ProgressText, SimulatedSecondsAsSpeedupAndUnknownTotal) {
  const ProgressSpec run{
      .label = "run", .total = 60, .unit = "s", .decimals = 1, .rate_as_speedup = true};
  EXPECT_EQ(format_progress(run, {.done = 12.5, .elapsed = 5}),
            "run: 12.5/60.0 s (20 %), 5 s, 2.5x real time, ETA 19 s");
  const ProgressSpec open{.label = "sweep", .unit = "points", .failure = "lost"};
  EXPECT_EQ(format_progress(open, {.done = 40, .failed = 2, .elapsed = 4}),
            "sweep: 40 points, 2 lost, 4 s, 10 points/s");
}

TEST(ProgressText, Durations) {
  EXPECT_EQ(format_duration(0.4), "0 s");
  EXPECT_EQ(format_duration(59.4), "59 s");
  EXPECT_EQ(format_duration(65), "1 min 05 s");
  EXPECT_EQ(format_duration(7440), "2 h 04 min");
  EXPECT_EQ(format_duration(-1), "?");
}

TEST(ProgressLine, PlainModeWritesOneLinePerPeriodAndALastOne) {
  FakeClock fake;
  std::ostringstream out;
  {
    ProgressLine line(out, walks(10), {ProgressMode::Plain, 5.0}, fake.clock());
    for (int i = 0; i < 10; ++i) {
      fake.t += 2;  // a walk every 2 s: lines at 6 s (3 done) and 12 s (6 done) and 18 s (9 done)
      line.advance(1, i == 4 ? 1 : 0);
    }
    line.finish();
    line.finish();  // only once
  }
  const auto lines = lines_of(out.str());
  ASSERT_EQ(lines.size(), 4u) << out.str();
  EXPECT_EQ(lines[0], "posture: 3/10 walks (30 %), 6 s, 0.50 walks/s, ETA 14 s");
  EXPECT_EQ(lines[1], "posture: 6/10 walks (60 %), 1 failed, 12 s, 0.50 walks/s, ETA 8 s");
  EXPECT_EQ(lines[2], "posture: 9/10 walks (90 %), 1 failed, 18 s, 0.50 walks/s, ETA 2 s");
  EXPECT_EQ(lines[3], "posture: 10/10 walks (100 %), 1 failed, 20 s, 0.50 walks/s");
  EXPECT_EQ(out.str().find('\r'), std::string::npos);
}

TEST(ProgressLine, ACommandShorterThanAPeriodPrintsNothing) {
  FakeClock fake;
  std::ostringstream out;
  ProgressLine line(out, walks(3), {ProgressMode::Plain, 10.0}, fake.clock());
  for (int i = 0; i < 3; ++i) fake.t += 1, line.advance();
  line.finish();
  EXPECT_EQ(out.str(), "");
}

TEST(ProgressLine, TickDrawsDuringALongItem) {
  FakeClock fake;
  std::ostringstream out;
  ProgressLine line(out, walks(2), {ProgressMode::Plain, 5.0}, fake.clock());
  fake.t += 4;
  line.tick();
  EXPECT_EQ(out.str(), "");
  fake.t += 2;
  line.tick();
  EXPECT_EQ(out.str(), "posture: 0/2 walks (0 %), 6 s, ETA ?\n");
}

TEST(ProgressLine, TerminalModeRedrawsInPlaceAtMostTenTimesASecond) {
  FakeClock fake;
  std::ostringstream out;
  ProgressLine line(out, walks(100), {ProgressMode::Terminal}, fake.clock());
  for (int i = 0; i < 100; ++i) {
    fake.t += 0.01;  // 100 items in 1 s: about ten redraws
    line.advance();
  }
  line.finish();
  const std::string text = out.str();
  const auto redraws = std::count(text.begin(), text.end(), '\r');
  EXPECT_GE(redraws, 9);
  EXPECT_LE(redraws, 11);
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1);
  EXPECT_TRUE(text.ends_with("\rposture: 100/100 walks (100 %), 1 s, 100 walks/s\033[K\n")) << text;
}

TEST(ProgressLine, TerminalClearErasesTheLineAndTheNextAdvanceRedraws) {
  FakeClock fake;
  std::ostringstream out;
  ProgressLine line(out, walks(4), {ProgressMode::Terminal}, fake.clock());
  fake.t += 1;
  line.advance();
  line.clear();
  EXPECT_TRUE(out.str().ends_with("\r\033[K"));
  out.str("");
  fake.t += 0.01;
  line.advance();
  EXPECT_EQ(out.str(), "\rposture: 2/4 walks (50 %), 1 s, 2.0 walks/s, ETA 1 s\033[K");
}

TEST(ProgressLine, QuietModeWritesNothing) {
  FakeClock fake;
  std::ostringstream out;
  ProgressLine line(out, walks(2), {ProgressMode::Quiet}, fake.clock());
  fake.t += 100;
  line.advance(2);
  line.finish();
  EXPECT_EQ(out.str(), "");
}

TEST(ProgressLine, WorkersReportingAtOnceCountEveryItem) {
  std::ostringstream out;
  ProgressLine line(out, walks(4000), {ProgressMode::Quiet});
  std::vector<std::thread> workers;
  for (int w = 0; w < 4; ++w)
    workers.emplace_back([&] {
      for (int i = 0; i < 1000; ++i) line.advance(1, i % 100 == 0);
    });
  for (auto& w : workers) w.join();
  EXPECT_EQ(line.counts().done, 4000);
  EXPECT_EQ(line.counts().failed, 40u);
}

TEST(ProgressSettings, FromTheEnvironmentOrTheTerminal) {
  EXPECT_EQ(progress_settings_from(nullptr, true).mode, ProgressMode::Terminal);
  EXPECT_EQ(progress_settings_from("", false).mode, ProgressMode::Plain);
  EXPECT_EQ(progress_settings_from("off", true).mode, ProgressMode::Quiet);
  EXPECT_EQ(progress_settings_from("tty", false).mode, ProgressMode::Terminal);
  const ProgressSettings every = progress_settings_from("plain:2.5", true);
  EXPECT_EQ(every.mode, ProgressMode::Plain);
  EXPECT_EQ(every.plain_every, 2.5);
  EXPECT_EQ(error_of([] { progress_settings_from("loud", false); }),
            "STRIDE_PROGRESS: expected tty, plain, plain:<seconds> or off, got 'loud'");
  EXPECT_EQ(error_of([] { progress_settings_from("plain:x", false); }),
            "STRIDE_PROGRESS=plain:<seconds>: expected a number, got 'x'");
  EXPECT_EQ(error_of([] { progress_settings_from("plain:0", false); }),
            "STRIDE_PROGRESS=plain:<seconds>: expected seconds > 0");
}

}  // namespace
}  // namespace stride::console
