// Bounded reads: the kind and size of an input are checked before a byte is read.
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "robot/core/error.hpp"
#include "robot/core/input_file.hpp"
#include "tests/error_text.hpp"

namespace stride {
namespace {

namespace fs = std::filesystem;
using test_support::error_of;

TEST(InputFile, ReadsARegularFile) {
  const fs::path p = fs::temp_directory_path() / ("stride_input_" + std::to_string(getpid()));
  std::ofstream(p) << "<scene/>";
  EXPECT_EQ(read_input_file(p.string(), 100, "scene file"), "<scene/>");
  EXPECT_EQ(input_file_problem(p.string(), 100), "");
  EXPECT_EQ(error_of([&] { read_input_file(p.string(), 4, "scene file"); }),
            "scene file '" + p.string() + "': 8 bytes, over the limit of 4 bytes");
  fs::remove(p);
}

TEST(InputFile, DevicesDirectoriesAndFifosAreRefusedBeforeReading) {
  EXPECT_EQ(error_of([] { read_input_file("/dev/zero", kMaxTextInputBytes, "scene file"); }),
            "scene file '/dev/zero': not a regular file (a character device)");
  EXPECT_EQ(error_of([] { read_input_file("/dev/urandom", kMaxLogBytes, "log"); }),
            "log '/dev/urandom': not a regular file (a character device)");
  const std::string dir = fs::temp_directory_path().string();
  EXPECT_EQ(error_of([&] { read_input_file(dir, kMaxScriptBytes, "script"); }),
            "script '" + dir + "': not a regular file (a directory)");
  // A FIFO with no writer: refused at once, not a wait for a writer that never comes.
  const fs::path fifo = fs::temp_directory_path() / ("stride_fifo_" + std::to_string(getpid()));
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_EQ(error_of([&] { read_input_file(fifo.string(), kMaxScriptBytes, "script"); }),
            "script '" + fifo.string() + "': not a regular file (a FIFO)");
  EXPECT_EQ(input_file_problem(fifo.string(), kMaxScriptBytes), "not a regular file (a FIFO)");
  fs::remove(fifo);
}

TEST(InputFile, MissingFileNamesThePath) {
  EXPECT_EQ(error_of([] { read_input_file("/no/such.xml", 100, "scene file"); }),
            "scene file '/no/such.xml': cannot open: No such file or directory");
}

}  // namespace
}  // namespace stride
