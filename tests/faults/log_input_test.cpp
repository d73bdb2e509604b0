// A file that is not a Stride log given to `log load`: one line naming it and exit 3, the code
// docs/console.md "Exit codes" gives for a file that cannot be read or parsed (a missing file gave 3, an
// unparsable one 1).
#include <gtest/gtest.h>

#include "tests/hostile/hostile_support.hpp"

namespace stride::hostile {
namespace {

const std::string kStand = source_path("scenes/nao_stand.xml");

TEST(LogInput, UnparsableLogExits3LikeAMissingOne) {
  Scratch s;
  const std::string bad = s.write("bad.log", "garbage, not a stride log\n");
  const auto r = run_stride({"-c", "log load " + bad, kStand});
  EXPECT_EQ(r.exit_status, 3) << r.err;
  EXPECT_NE(r.err.find("log '" + bad + "': not a stride log (bad magic)"), std::string::npos)
      << r.err;
  const auto missing = run_stride({"-c", "log load " + s.path("none.log"), kStand});
  EXPECT_EQ(missing.exit_status, 3) << missing.err;
  // A STRDLOG2 magic with a header that breaks off: "bad header", also 3.
  const std::string cut = s.write("cut.log", std::string("STRDLOG2\x10\x00\x00", 11));
  const auto header = run_stride({"-c", "log load " + cut, kStand});
  EXPECT_EQ(header.exit_status, 3) << header.err;
  EXPECT_NE(header.err.find("bad header"), std::string::npos) << header.err;
}

}  // namespace
}  // namespace stride::hostile
