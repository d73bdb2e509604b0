// `stride push-sweep` end to end on three pushes, and its one-line argument errors.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "console/cli/subcommand.hpp"

namespace stride::cli {
int push_sweep_main(Args args, std::ostream& out, std::ostream& err);

namespace {

struct Result {
  int code;
  std::string out, err;
};

Result run(std::vector<std::string> args) {
  std::ostringstream out, err;
  const int code = push_sweep_main(args, out, err);
  return {code, out.str(), err.str()};
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream s(text);
  for (std::string l; std::getline(s, l);) lines.push_back(l);
  return lines;
}

TEST(PushSweepCommand, PrintsOneRowPerPushAndTheAgreement) {
  const std::string scene = std::string(STRIDE_SOURCE_DIR) + "/scenes/push/stand_balance.xml";
  const Result r = run({"--scene", scene, "--strategy", "ankle", "--impulses", "0.2,0.4,8.0",
                        "--directions", "0", "--settle", "1.0", "--observe", "2.0"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto lines = lines_of(r.out);
  ASSERT_EQ(lines.size(), 7u) << r.out;  // title, header, 3 rows, two agreement lines
  EXPECT_NE(lines[1].find("predicted"), std::string::npos);
  int rows_agreeing = 0;
  for (int i = 2; i < 5; ++i) {
    std::istringstream row(lines[i]);
    double impulse, dir, x, v, xt, vt;
    std::string predicted, predicted_true, expected, observed, agree;
    ASSERT_TRUE(row >> impulse >> dir >> x >> v >> xt >> vt >> predicted >> predicted_true >>
                expected >> observed >> agree)
        << lines[i];
    // agree = the strategy's predicted outcome is what happened.
    EXPECT_EQ(agree == "yes", (expected == "recover") == (observed == "recovered")) << lines[i];
    rows_agreeing += agree == "yes";
    EXPECT_EQ(dir, 0);
    EXPECT_GT(vt, 0.1 * impulse) << lines[i];  // the forward push moved the CoM forward
    EXPECT_GT(v, 0) << lines[i];
    if (impulse > 3) {  // far beyond every region: predicted none and observed as a fall
      EXPECT_EQ(predicted, "none");
      EXPECT_EQ(predicted_true, "none");
      EXPECT_EQ(observed, "fell");
    } else {  // small pushes: inside the ankle region, and absorbed
      EXPECT_EQ(predicted, "ankle");
      EXPECT_EQ(expected, "recover");
      EXPECT_EQ(observed, "recovered");
    }
  }
  EXPECT_NE(lines[5].find("agreement: " + std::to_string(rows_agreeing) + "/3"), std::string::npos)
      << lines[5];
  EXPECT_EQ(lines[6].rfind("agreement from the simulator's CoM state: ", 0), 0u) << lines[6];
}

TEST(PushSweepCommand, RejectsBadArgumentsInOneLine) {
  const std::string scene = std::string(STRIDE_SOURCE_DIR) + "/scenes/push/stand_balance.xml";
  Result r = run({"--scene", scene, "--strategy", "step", "--impulses", "1"});
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err,
            "stride push-sweep: --strategy: expected ankle, hip, combined or lqr, got "
            "'step'\n");
  r = run({"--scene", scene, "--impulses", "1:0.5:0.1"});
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err, "stride push-sweep: --impulses: expected first <= last and step > 0\n");
  r = run({"--scene", scene, "--impulses", "0.5,x"});
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err, "stride push-sweep: --impulses: expected a number, got 'x'\n");
  r = run({"--scene", scene});
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err, "stride push-sweep: missing --impulses\n");
}

}  // namespace
}  // namespace stride::cli
