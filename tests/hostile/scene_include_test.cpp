// Scene includes walked without recursion and within limits (simulator/scene/include_walk.hpp):
// a chain deeper than 64, an include bomb (each file including the next twice) and includes
// holding more than 64 MiB are refused in one line naming the <include> that broke the limit,
// in bounded time and memory; a chain of exactly 64 still loads.
#include <chrono>

#include "simulator/scene/include_walk.hpp"
#include "simulator/scene/scene_parser.hpp"
#include "tests/hostile/hostile_support.hpp"

namespace stride::hostile {
namespace {

// c0.xml includes c1.xml ... c<n-1>.xml, the last holds a ground.
std::string include_chain(const Scratch& s, int n) {
  for (int i = 0; i < n; ++i)
    s.write("c" + std::to_string(i) + ".xml",
            i + 1 < n
                ? "<scene>\n<include file=\"c" + std::to_string(i + 1) + ".xml\"/>\n</scene>\n"
                : std::string("<scene>\n<ground friction=\"0.7\"/>\n</scene>\n"));
  return s.path("c0.xml");
}

// b0.xml includes b1.xml twice, ... b<n-1>.xml: 2^n - 2 includes of ~120-byte files.
std::string include_bomb(const Scratch& s, int n) {
  for (int i = 0; i < n; ++i) {
    const std::string next = "b" + std::to_string(i + 1) + ".xml";
    s.write("b" + std::to_string(i) + ".xml", i + 1 < n ? "<scene>\n<include file=\"" + next +
                                                              "\"/>\n<include file=\"" + next +
                                                              "\"/>\n</scene>\n"
                                                        : std::string("<scene/>\n"));
  }
  return s.path("b0.xml");
}

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

TEST(HostileSceneInclude, ChainOf8000IsRefusedAtDepth65) {
  Scratch s;
  const std::string root = include_chain(s, 8000);
  expect_refused(run_stride({"run", root, "--seconds", "0.01"}),
                 {s.path("c64.xml") + ":2: <include>: includes nested 65 deep (at most 64)"});
}

TEST(HostileSceneInclude, ChainOf64Loads) {
  Scratch s;
  const auto scene = sim::parse_scene_file(include_chain(s, sim::include_limits::kMaxDepth + 1));
  EXPECT_DOUBLE_EQ(scene.ground.friction, 0.7);
}

TEST(HostileSceneInclude, SmallBombIsRefusedAtTheThousandAndFirstInclude) {
  Scratch s;  // 2046 includes: within memory, beyond the count
  expect_refused(run_stride({"run", include_bomb(s, 11), "--seconds", "0.01"}),
                 {"<include>: the scene would include more than 1000 files (at most 1000 "
                  "includes per scene)"});
}

TEST(HostileSceneInclude, BombOf2To20IncludesEndsInBoundedTime) {
  Scratch s;
  const auto start = std::chrono::steady_clock::now();
  const auto r = run_stride({"run", include_bomb(s, 21), "--seconds", "0.01"});
  // Depth first, the 1001st include is b19.xml's first one.
  expect_refused(r, {s.path("b19.xml") + ":2: <include>: the scene would include more than 1000"});
  EXPECT_LT(seconds_since(start), 20.0);
}

TEST(HostileSceneInclude, IncludedBytesBeyond64MiBAreRefused) {
  Scratch s;  // 17 includes of one 4 MiB file (a comment): 68 MiB
  s.write("big.xml", "<scene>\n<!--" + std::string(4u << 20, 'x') + "-->\n</scene>\n");
  std::string root = "<scene>\n";
  for (int i = 0; i < 17; ++i) root += "<include file=\"big.xml\"/>\n";
  const auto r = run_stride({"run", s.write("root.xml", root + "</scene>\n"), "--seconds", "0.01"});
  expect_refused(r, {s.path("root.xml") + ":17: <include>: the scene's included files would hold ",
                     " bytes (at most 67108864 in all)"});
}

}  // namespace
}  // namespace stride::hostile
