// A scene whose name is not UTF-8 (bytes 0xff 0xfe): `stride run --report` still writes valid
// JSON, each byte that is not UTF-8 as U+FFFD, and the real UTF-8 around it unchanged.
#include <gtest/gtest.h>

#include "tests/hostile/hostile_support.hpp"
#include "tests/json_reader.hpp"
#include "tests/lola/lola_test_support.hpp"

namespace stride::hostile {
namespace {

// RFC 3629 by hand, independent of the writer's own check.
bool valid_utf8(const std::string& s) {
  for (std::size_t i = 0; i < s.size();) {
    const auto c = static_cast<unsigned char>(s[i]);
    const std::size_t n = c < 0x80                 ? 1
                          : c >= 0xc2 && c <= 0xdf ? 2
                          : c >= 0xe0 && c <= 0xef ? 3
                          : c >= 0xf0 && c <= 0xf4 ? 4
                                                   : 0;
    if (n == 0 || i + n > s.size()) return false;
    for (std::size_t k = 1; k < n; ++k)
      if ((static_cast<unsigned char>(s[i + k]) & 0xc0) != 0x80) return false;
    i += n;
  }
  return true;
}

TEST(SceneNameJson, NameThatIsNotUtf8GivesValidJson) {
  Scratch s;
  const std::string scene =
      s.write("s.xml", "<scene name=\"\xff\xfe nao \xc3\xa9\">\n<include file=\"" +
                           source_path("scenes/nao_stand.xml") + "\"/>\n</scene>\n");
  const std::string report = s.path("report.json");
  const auto r = run_stride({"run", scene, "--seconds", "0.02", "--report", report});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  const std::string json = test::read_file(report);
  EXPECT_TRUE(valid_utf8(json)) << json.substr(0, 200);
  const auto parsed = test_support::JsonReader::parse(json);
  EXPECT_EQ(parsed["scene"].text(), "\xef\xbf\xbd\xef\xbf\xbd nao \xc3\xa9");
}

}  // namespace
}  // namespace stride::hostile
