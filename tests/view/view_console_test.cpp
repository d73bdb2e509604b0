// The console's `view`: a REPL (here on a pipe) serves the page beside its own commands. The
// page's commands run between the console's; the console's steps reach the page as frames;
// `view stop` closes the page's connection.
#include <fcntl.h>
#include <gtest/gtest.h>

#include "simulator/simulation.hpp"
#include "tests/view/view_client.hpp"

namespace stride::view_test {
namespace {

// `stride <scene>` reading commands from a pipe this test writes.
class PipedConsole {
 public:
  explicit PipedConsole(const std::string& scene) {
    dir_ = test_support::fresh_path("view", "console");
    std::filesystem::create_directories(dir_);
    int fds[2];
    EXPECT_EQ(::pipe(fds), 0);
    pid_ = ::fork();
    if (pid_ == 0) {
      ::setpgid(0, 0);
      ::dup2(fds[0], 0);
      ::close(fds[1]);
      const int o = ::open((dir_ / "out.txt").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      ::dup2(o, 1), ::dup2(o, 2);
      const std::string binary = stride_binary();
      ::execl(binary.c_str(), binary.c_str(), scene.c_str(), static_cast<char*>(nullptr));
      std::_Exit(127);
    }
    ::close(fds[0]);
    in_ = fds[1];
  }
  ~PipedConsole() { finish(); }
  void type(const std::string& line) {
    const std::string text = line + "\n";
    EXPECT_EQ(::write(in_, text.data(), text.size()), static_cast<ssize_t>(text.size()));
  }
  std::string out() const { return test_support::read_text(dir_ / "out.txt"); }
  // The first match of `pattern` in the output within 60 s, or "".
  std::string wait_for(const std::regex& pattern, int group = 0) const {
    for (int i = 0; i < 600; ++i) {
      std::smatch m;
      const std::string text = out();
      if (std::regex_search(text, m, pattern)) return m[group];
      std::this_thread::sleep_for(100ms);
    }
    return "";
  }
  int finish() {
    if (pid_ <= 0) return code_;
    ::close(in_);  // end of input ends the console
    code_ = test_support::finish_process(pid_);
    pid_ = 0;
    return code_;
  }

 private:
  std::filesystem::path dir_;
  pid_t pid_ = 0;
  int in_ = -1;
  int code_ = -1;
};

TEST(ViewConsole, TheReplServesThePageBesideItsOwnCommands) {
  const auto sim = sim::Simulation::from_file(scene_path("nao_stand_controlled.xml"));
  const double dt = sim->scene().physics.step;
  PipedConsole console(scene_path("nao_stand_controlled.xml"));
  console.type("view 0");
  const std::string port =
      console.wait_for(std::regex("view: http://127\\.0\\.0\\.1:([0-9]+)/ \\(open it"), 1);
  ASSERT_FALSE(port.empty()) << console.out();
  WsClient page(static_cast<unsigned short>(std::stoi(port)));
  const Json hello = page.read_type("hello");
  ASSERT_TRUE(hello.is_object());
  EXPECT_EQ(hello["mode"], "sim");
  ASSERT_TRUE(page.read_type("frame").is_object());
  const Json reply = command(page, 1, "step 10");
  EXPECT_EQ(reply["ok"], true) << reply.dump();
  Json f = page.read_type("frame");
  ASSERT_TRUE(f.is_object());
  EXPECT_NEAR(f["t"].get<double>(), 10 * dt, 1e-12);
  console.type("step 20");  // the console's own step: the page sees it
  do f = page.read_type("frame");
  while (f.is_object() && f["t"].get<double>() < 30 * dt - 1e-12);
  ASSERT_TRUE(f.is_object());
  EXPECT_NEAR(f["t"].get<double>(), 30 * dt, 1e-12);
  console.type("view 0");  // one view at a time
  EXPECT_FALSE(console.wait_for(std::regex("error: view: already open")).empty());
  console.type("view stop");
  EXPECT_FALSE(console.wait_for(std::regex("view stopped")).empty());
  while (page.read(10s)) {
  }
  EXPECT_FALSE(page.connected());
  EXPECT_EQ(console.finish(), 0) << console.out();
}

}  // namespace
}  // namespace stride::view_test
