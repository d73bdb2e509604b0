// Checked outputs: every write and the close are checked, an error names the path, and a failed
// output leaves nothing behind (an older file of that name stays as it was).
#include <signal.h>
#include <sys/resource.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "robot/core/error.hpp"
#include "robot/core/output_file.hpp"
#include "tests/error_text.hpp"

namespace stride {
namespace {

namespace fs = std::filesystem;
using test_support::error_of;

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

struct ScratchDir {
  fs::path dir;
  ScratchDir() {
    dir = fs::temp_directory_path() /
          ("stride_output_file_" + std::to_string(::getpid()) + "_" +
           ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  ~ScratchDir() { fs::remove_all(dir); }
  // Everything in the directory, to show no temporary was left behind.
  int entries() const {
    int n = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
    return n;
  }
};

TEST(OutputFile, WritesAndReplacesOnCommitOnly) {
  ScratchDir s;
  const std::string path = (s.dir / "report.json").string();
  write_file(path, "old");
  {
    OutputFile f(path);
    f.write("new contents");
    EXPECT_EQ(slurp(path), "old");  // the target changes only at commit
    f.commit();
  }
  EXPECT_EQ(slurp(path), "new contents");
  EXPECT_EQ(s.entries(), 1);
}

TEST(OutputFile, WithoutCommitNothingChanges) {
  ScratchDir s;
  const std::string path = (s.dir / "out.csv").string();
  write_file(path, "kept");
  {
    OutputFile f(path);
    f.write("lost");
  }
  EXPECT_EQ(slurp(path), "kept");
  EXPECT_EQ(s.entries(), 1);
}

TEST(OutputFile, DevFullIsAnErrorNamingThePath) {
  const std::string msg = error_of([] { write_file("/dev/full", std::string(100000, 'x')); });
  EXPECT_EQ(msg, "cannot write '/dev/full': No space left on device");
  // A small write reaches the device only at the flush: still caught.
  EXPECT_EQ(error_of([] { write_file("/dev/full", "x"); }),
            "cannot write '/dev/full': No space left on device");
}

TEST(OutputFile, DevNullIsWrittenAsItStands) {
  EXPECT_EQ(error_of([] { write_file("/dev/null", "anything"); }), "");
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
}

TEST(OutputFile, MissingDirectoryAndDirectoryTargetsAreErrors) {
  ScratchDir s;
  const std::string missing = (s.dir / "no/such/dir/x.csv").string();
  EXPECT_EQ(error_of([&] { write_file(missing, "x"); }),
            "cannot write '" + missing + "': No such file or directory");
  EXPECT_EQ(error_of([&] { write_file(s.dir.string(), "x"); }),
            "cannot write '" + s.dir.string() + "': is a directory");
}

// A file size limit stands in for a full disk: the write fails with EFBIG instead of ENOSPC.
TEST(OutputFile, FullDiskLeavesNoPartialFile) {
  ScratchDir s;
  const std::string path = (s.dir / "big.csv").string();
  write_file(path, "previous run");
  struct rlimit old {};
  ASSERT_EQ(getrlimit(RLIMIT_FSIZE, &old), 0);
  const auto old_handler = signal(SIGXFSZ, SIG_IGN);
  struct rlimit small = old;
  small.rlim_cur = 4096;
  ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &small), 0);
  const std::string msg = error_of([&] { write_file(path, std::string(1 << 20, 'x')); });
  setrlimit(RLIMIT_FSIZE, &old);
  signal(SIGXFSZ, old_handler);
  EXPECT_EQ(msg, "cannot write '" + path + "': File too large");
  EXPECT_EQ(slurp(path), "previous run");
  EXPECT_EQ(s.entries(), 1);
}

TEST(OutputFile, StreamWritesInPlaceAndKeepsFlushedBytes) {
  ScratchDir s;
  const std::string path = (s.dir / "run.log").string();
  OutputFile f(path, OutputFile::Mode::Stream);
  f.write("frame 0;");
  f.flush();
  EXPECT_EQ(slurp(path), "frame 0;");  // readable while still open, as a killed run leaves it
  f.write("frame 1;");
  f.commit();
  EXPECT_EQ(slurp(path), "frame 0;frame 1;");
  EXPECT_TRUE(f.committed());
}

TEST(OutputFile, StreamToDevFullFailsAtTheFlush) {
  OutputFile f("/dev/full", OutputFile::Mode::Stream);
  f.write("header");
  EXPECT_EQ(error_of([&] { f.flush(); }), "cannot write '/dev/full': No space left on device");
  EXPECT_FALSE(f.committed());
  EXPECT_NE(error_of([&] { f.write("more"); }), "");  // closed after the failure
}

}  // namespace
}  // namespace stride
