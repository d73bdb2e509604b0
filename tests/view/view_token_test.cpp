// The view's token (PROTOCOL.md "Who may connect"): with --token-file a page must prove a token
// by challenge-response before anything else; a wrong proof, or any other message first, is a
// close with 1008. Beyond loopback a token file is required.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <fstream>

#include "robot/debug/auth.hpp"
#include "tests/view/view_client.hpp"

namespace stride::view_test {
namespace {

const std::string kToken = "view-test-token-0123456789";
const std::string kReadOnly = "view-read-only-0123456789";

std::string hex(std::string_view bytes) {
  static constexpr char digits[] = "0123456789abcdef";
  std::string out;
  for (unsigned char c : bytes) out += {digits[c >> 4], digits[c & 15]};
  return out;
}

class ViewToken : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = test_support::fresh_path("view", "token_file");
    std::filesystem::create_directories(dir_);
    const auto file = dir_ / "tokens";
    std::ofstream(file) << "# the view test's\n" << kToken << "\nread-only " << kReadOnly << "\n";
    ::chmod(file.c_str(), 0600);
    view_ = std::make_unique<ViewProcess>(
        std::vector<std::string>{scene_path("nao_stand.xml"), "--token-file", file.string()},
        "127.0.0.1", "token");
    ASSERT_NE(view_->port(), 0) << view_->out() << view_->err();
  }
  std::filesystem::path dir_;
  // A clean end: exit code 0 on SIGTERM (under the sanitizers: no leak, no error report).
  void TearDown() override {
    if (view_) {
      EXPECT_EQ(view_->stop(), 0) << view_->err();
    }
  }
  std::unique_ptr<ViewProcess> view_;
};

// Proves `token` on a fresh page; returns the auth_ok message (null if none came).
Json prove(WsClient& page, const std::string& token) {
  const Json auth = page.read_type("auth");
  if (!auth.is_object()) return nullptr;
  const std::string server_nonce = auth["nonce"];
  EXPECT_EQ(server_nonce.size(), 64u);
  const std::string client_nonce = hex(debug::random_nonce());
  const std::string proof =
      hex(debug::keyed_hash(token, "stride-view-1 client" + server_nonce + client_nonce));
  page.send(Json{{"op", "auth"}, {"nonce", client_nonce}, {"proof", proof}}.dump());
  Json ok = page.read_type("auth_ok");
  if (ok.is_object())
    EXPECT_EQ(ok["proof"],
              hex(debug::keyed_hash(token, "stride-view-1 server" + server_nonce + client_nonce)));
  return ok;
}

TEST_F(ViewToken, TheRightProofJoinsAndTheServerProvesItKnowsTheToken) {
  WsClient page(view_->port());
  const Json ok = prove(page, kToken);
  ASSERT_TRUE(ok.is_object());
  EXPECT_EQ(ok["read_only"], false);
  EXPECT_TRUE(page.read_type("hello").is_object());
  EXPECT_EQ(command(page, 1, "step 5")["ok"], true);
}

TEST_F(ViewToken, AReadOnlyTokenGetsButDoesNotCommand) {
  WsClient page(view_->port());
  const Json ok = prove(page, kReadOnly);
  ASSERT_TRUE(ok.is_object());
  EXPECT_EQ(ok["read_only"], true);
  const Json step = command(page, 1, "step 5");
  EXPECT_EQ(step["ok"], false);
  EXPECT_EQ(step["error"], "step: this page's token is read-only");
  const Json get = command(page, 2, "get sim.time");
  EXPECT_EQ(get["ok"], true) << get.dump();
  EXPECT_NE(get["output"].get<std::string>().find("0"), std::string::npos) << get.dump();
  page.send(R"({"op":"get","id":3,"key":"sim.time"})");
  const Json value = page.read_type("value");
  EXPECT_EQ(value["id"], 3);
  EXPECT_EQ(value["text"], "0");
}

TEST_F(ViewToken, AWrongProofOrAnotherMessageFirstIsClosedWith1008) {
  {
    WsClient page(view_->port());
    const Json auth = page.read_type("auth");
    ASSERT_TRUE(auth.is_object());
    const std::string client_nonce(64, '1');
    const std::string wrong = hex(debug::keyed_hash(
        "another-token-0123456789",
        "stride-view-1 client" + auth["nonce"].get<std::string>() + client_nonce));
    page.send(Json{{"op", "auth"}, {"nonce", client_nonce}, {"proof", wrong}}.dump());
    std::optional<std::string> next;
    while ((next = page.read(10s))) EXPECT_EQ(next->find("hello"), std::string::npos) << *next;
    EXPECT_EQ(page.close_code(), 1008);
  }
  {
    WsClient page(view_->port());
    ASSERT_TRUE(page.read_type("auth").is_object());
    page.send(R"({"op":"cmd","id":1,"line":"step 1"})");
    std::optional<std::string> next;
    while ((next = page.read(10s))) EXPECT_EQ(next->find("reply"), std::string::npos) << *next;
    EXPECT_EQ(page.close_code(), 1008);
  }
}

TEST(ViewListen, BeyondLoopbackWithoutATokenIsAUsageError) {
  const auto dir = test_support::fresh_path("view", "listen");
  std::filesystem::create_directories(dir);
  const pid_t pid = test_support::start_process(
      {"/usr/bin/env", "-u", "STRIDE_TOKEN", stride_binary(), "view", scene_path("nao_stand.xml"),
       "--listen", "0.0.0.0:0", "--seconds", "5"},
      dir / "out.txt", dir / "err.txt");
  EXPECT_EQ(test_support::finish_process(pid), 2);
  EXPECT_NE(test_support::read_text(dir / "err.txt").find("not a loopback address"),
            std::string::npos);
  EXPECT_EQ(test_support::read_text(dir / "out.txt").find("view:"), std::string::npos);
}

TEST(ViewListen, AnotherLoopbackAddressNeedsNoToken) {
  ViewProcess view({scene_path("nao_stand.xml")}, "127.0.0.2", "loopback2");
  ASSERT_NE(view.port(), 0) << view.out() << view.err();
  WsClient page(view.port(), "127.0.0.2");
  EXPECT_TRUE(page.read_type("hello").is_object());
}

}  // namespace
}  // namespace stride::view_test
