// Logs you can trust: every frame carries a CRC-32; a damaged frame is reported by its number,
// the frames around it stay readable, a replay never reads it, and the old format still loads.
#include <sys/resource.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "robot/runtime/log_format.hpp"
#include "robot/runtime/replay.hpp"
#include "tests/error_text.hpp"
#include "tests/framework/fake_link.hpp"

namespace stride {
namespace {

namespace fs = std::filesystem;
using test_support::error_of;

std::string temp_path(const std::string& name) {
  return (fs::path(::testing::TempDir()) / name).string();
}

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Records `frames` frames of the test configuration; returns the file's bytes.
std::string record(const std::string& path, int frames, const LogMetadata& metadata = {}) {
  const auto registry = test::test_registry();
  test::FakeLink link(0.01);
  Runtime rt(registry, test::test_config(), link);
  rt.start_log(path, metadata);
  for (int i = 0; i < frames; ++i) rt.step();
  rt.stop_log();
  return slurp(path);
}

// Byte offset at which frame `n` starts (its marker), found by walking the frame headers.
std::size_t frame_offset(const std::string& bytes, std::size_t n) {
  std::uint32_t header = 0;
  std::memcpy(&header, bytes.data() + 8, 4);
  std::size_t pos = 16 + header;
  for (std::size_t k = 0; k < n; ++k) {
    std::uint32_t size = 0;
    std::memcpy(&size, bytes.data() + pos + 12, 4);
    pos += log_format::kFrameHeaderBytes + size;
  }
  return pos;
}

LogReader reader_of(const std::string& bytes) {
  return LogReader::from_bytes(bytes, "damaged.log");
}

TEST(LogIntegrity, AFlippedPayloadByteDamagesOnlyThatFrame) {
  const std::string good = record(temp_path("stride_integrity_a.log"), 10);
  const LogReader whole = reader_of(good);
  std::string bad = good;
  bad[frame_offset(bad, 5) + log_format::kFrameHeaderBytes + 30] ^= 0x40;
  const LogReader log = reader_of(bad);
  EXPECT_EQ(log.frame_count(), 10u);
  EXPECT_EQ(log.integrity().complete, 9u);
  EXPECT_EQ(log.integrity().damaged, 1u);
  EXPECT_EQ(log.integrity().damaged_frames, std::vector<std::size_t>{5});
  EXPECT_EQ(log.integrity().truncated, 0u);
  EXPECT_EQ(log.summary(), "10 frames: 9 complete, 1 damaged (5), 0 truncated");
  EXPECT_EQ(error_of([&] { log.bytes(5, "JointRequest"); }),
            "log: frame 5 is damaged (checksum mismatch)");
  for (std::size_t f : {0u, 4u, 6u, 9u})
    EXPECT_EQ(log.bytes(f, "JointRequest"), whole.bytes(f, "JointRequest")) << f;
  EXPECT_EQ(log.readable_prefix(), 5u);
}

TEST(LogIntegrity, ADamagedSizeOrMarkerStillFindsTheNextFrames) {
  const std::string good = record(temp_path("stride_integrity_b.log"), 8);
  for (std::size_t at : {0u, 12u, 13u}) {  // the marker, the size's low and high bytes
    std::string bad = good;
    bad[frame_offset(bad, 3) + at] ^= 0x7f;
    const LogReader log = reader_of(bad);
    EXPECT_EQ(log.frame_count(), 8u) << at;
    EXPECT_EQ(log.integrity().damaged_frames, std::vector<std::size_t>{3}) << at;
    EXPECT_EQ(log.read<FrameInfo>(4).frame, 4) << at;
    EXPECT_EQ(log.read<FrameInfo>(7).frame, 7) << at;
  }
}

TEST(LogIntegrity, TwoNeighbouringDamagedFramesAreCountedByTheirNumbers) {
  const std::string good = record(temp_path("stride_integrity_c.log"), 8);
  std::string bad = good;
  // The size of 2 and the payload of 3, both found in the undamaged bytes.
  bad[frame_offset(good, 2) + 12] ^= 0x55;
  bad[frame_offset(good, 3) + log_format::kFrameHeaderBytes + 8] ^= 0x55;
  const LogReader log = reader_of(bad);
  EXPECT_EQ(log.integrity().damaged_frames, (std::vector<std::size_t>{2, 3}));
  EXPECT_EQ(log.integrity().complete, 6u);
}

TEST(LogIntegrity, EndsCutShortAreTruncatedAndDamagedLastFramesDamaged) {
  const std::string good = record(temp_path("stride_integrity_d.log"), 6);
  const std::size_t last = frame_offset(good, 5);
  const LogReader cut = reader_of(good.substr(0, last + 25));
  EXPECT_EQ(cut.summary(), "5 frames: 5 complete, 0 damaged, 1 truncated");
  EXPECT_EQ(reader_of(good.substr(0, last + 7)).integrity().truncated, 1u);  // inside the header
  std::string bad = good;
  bad.back() ^= 1;
  EXPECT_EQ(reader_of(bad).summary(), "6 frames: 5 complete, 1 damaged (5), 0 truncated");
}

TEST(LogIntegrity, ReplayStopsBeforeTheFirstDamagedFrame) {
  const std::string path = temp_path("stride_integrity_e.log");
  std::string bad = record(path, 12);
  bad[frame_offset(bad, 7) + log_format::kFrameHeaderBytes + 40] ^= 0x10;
  const LogReader log = reader_of(bad);
  const auto registry = test::test_registry();
  const ReplayResult r = replay_and_compare(log, registry, test::test_config());
  EXPECT_EQ(r.frames, 7u);
  EXPECT_TRUE(r.stopped_before_damaged);
  EXPECT_TRUE(r.mismatches.empty());
  std::ostringstream csv;
  export_csv(log, {"Counter"}, csv);
  EXPECT_EQ(csv.str().find("\n7,"), std::string::npos);  // no row for the damaged frame
  EXPECT_NE(csv.str().find("\n8,8\n"), std::string::npos) << csv.str();
}

TEST(LogIntegrity, HeaderChecksumAndMetadata) {
  const std::string path = temp_path("stride_integrity_f.log");
  const std::string good = record(path, 2, {{"providers", "JointRequest=Stand"}, {"robot", "nao"}});
  const LogReader log = reader_of(good);
  EXPECT_EQ(log.metadata().at("providers"), "JointRequest=Stand");
  EXPECT_EQ(log.metadata().at("robot"), "nao");
  EXPECT_EQ(log.frame_count(), 2u);
  std::string bad = good;
  bad[30] ^= 1;
  EXPECT_EQ(error_of([&] { reader_of(bad); }), "log 'damaged.log': bad header: checksum mismatch");
  EXPECT_EQ(error_of([&] { reader_of("STRDLOG9" + good.substr(8)); }),
            "log 'damaged.log': not a stride log (bad magic)");
}

// STRDLOG1, recorded by the previous revision (3 frames of scenes/nao_stand_controlled.xml).
TEST(LogIntegrity, PreviousFormatStillLoads) {
  const LogReader log(std::string(STRIDE_SOURCE_DIR) + "/tests/data/strdlog1_nao_stand.log");
  EXPECT_EQ(log.integrity().version, 1);
  EXPECT_EQ(log.frame_count(), 3u);
  EXPECT_EQ(log.summary(),
            "3 frames: 3 complete, 0 damaged, 0 truncated (old format STRDLOG1: frames carry no "
            "checksums)");
  EXPECT_EQ(log.read<FrameInfo>(2).frame, 2);
  EXPECT_DOUBLE_EQ(log.read<FrameInfo>(2).time, 0.03);
  EXPECT_TRUE(log.metadata().empty());
}

TEST(LogIntegrity, AnUnwritableLogIsAnErrorNamingThePath) {
  const auto registry = test::test_registry();
  test::FakeLink link(0.01);
  Runtime rt(registry, test::test_config(), link);
  EXPECT_EQ(error_of([&] { rt.start_log("/dev/full"); }),
            "cannot write '/dev/full': No space left on device");
  EXPECT_FALSE(rt.logging());
}

// A disk that fills during the run (a file size limit stands in for it): the step that could not
// write its frame fails naming the path, recording stops, and every frame written before loads.
TEST(LogIntegrity, DiskFullDuringARunKeepsEveryFrameWrittenBefore) {
  const std::string path = temp_path("stride_integrity_full.log");
  const auto registry = test::test_registry();
  test::FakeLink link(0.01);
  Runtime rt(registry, test::test_config(), link);
  rt.start_log(path);
  for (int i = 0; i < 3; ++i) rt.step();
  const auto size_after_3 = fs::file_size(path);
  struct rlimit old {};
  getrlimit(RLIMIT_FSIZE, &old);
  const auto old_handler = std::signal(SIGXFSZ, SIG_IGN);
  struct rlimit limit = old;
  limit.rlim_cur = size_after_3 + (size_after_3 - 16) / 3 * 2 + 10;  // room for 2 frames and a bit
  setrlimit(RLIMIT_FSIZE, &limit);
  std::string msg;
  int steps = 0;
  for (; steps < 10 && msg.empty(); ++steps) msg = error_of([&] { rt.step(); });
  setrlimit(RLIMIT_FSIZE, &old);
  std::signal(SIGXFSZ, old_handler);
  EXPECT_EQ(msg, "cannot write '" + path + "': File too large");
  EXPECT_FALSE(rt.logging());
  const LogReader log(path);
  EXPECT_EQ(log.integrity().complete, static_cast<std::size_t>(3 + steps - 1));
  EXPECT_EQ(log.integrity().damaged, 0u);
  for (std::size_t f = 0; f < log.frame_count(); ++f) EXPECT_EQ(log.read<FrameInfo>(f).frame, f);
}

}  // namespace
}  // namespace stride
