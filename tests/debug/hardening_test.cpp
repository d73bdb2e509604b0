// Issue 48 (part A), each case against the real `stride run <scene> --debug` over loopback: the
// token file is never served, a log never overwrites a file, silent peers cannot take the slots
// of a team's console, a remote log on a full disk stops that log and not the run, `mr` with an
// unknown representation is an error, and strings that are not UTF-8 are refused in UTF-8.
#include <filesystem>
#include <fstream>
#include <thread>

#include <gtest/gtest.h>

#include "console/system/child_process.hpp"
#include "robot/debug/debug_client.hpp"
#include "robot/runtime/log.hpp"
#include "tests/debug/raw_peer.hpp"
#include "tests/debug/served_process.hpp"
#include "tests/lola/lola_test_support.hpp"

namespace stride::test {
namespace {

using debug::DebugClient;
using debug::Op;

const std::string kStrideRun = stride_under_test();

// The error a request gets ("" if it succeeded).
std::string refusal(DebugClient& c, debug::Request r) {
  try {
    c.call(std::move(r));
  } catch (const debug::ConnectionLost& e) {
    return std::string("LOST: ") + e.what();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

debug::Request fetch(const std::string& name) {
  debug::Request r = debug::request(Op::LogFetch, name);
  r.length = 4096;
  return r;
}

TEST(DebugHardening, TokenFileAndForeignFilesAreNeverServed) {
  Served robot("served_tokens", true);
  ASSERT_NE(robot.at.port, 0) << robot.process.err();
  std::ofstream(robot.dir + "/old.log") << "STRDLOG2 not recorded by this robot";
  DebugClient reader(robot.at, kReadOnlyToken);
  ASSERT_TRUE(reader.welcome().read_only);
  // The token file by its name, and by a name like a log's (a link to it, as a local user or an
  // earlier bug could leave one), and a log this server did not write.
  std::filesystem::create_hard_link(robot.dir + "/tokens", robot.dir + "/tokens.log");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"tokens", "ending in '.log'"},
      {"tokens.log", "not a log this robot recorded"},
      {"old.log", "not a log this robot recorded"}};
  for (const auto& [name, why] : cases) {
    const std::string fetched = refusal(reader, fetch(name));
    EXPECT_NE(fetched.find(why), std::string::npos) << name << ": " << fetched;
    EXPECT_EQ(fetched.find(kFullToken), std::string::npos);
    const std::string info = refusal(reader, debug::request(Op::LogInfo, name));
    EXPECT_NE(info.find(why), std::string::npos) << name << ": " << info;
  }
  // The read-only client learnt nothing it could log in with: the full token stays unknown to it,
  // and its own token still cannot change the robot.
  const std::string set = refusal(reader, debug::request(Op::Set, "module:Stand", "stiffness=0.5"));
  EXPECT_NE(set.find("read-only"), std::string::npos) << set;

  // What this robot recorded is served, to a read-only client too.
  DebugClient writer(robot.at, kFullToken);
  writer.call(debug::request(Op::LogStart, "mine.log"));
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  writer.call(debug::request(Op::LogStop));
  const auto chunk = reader.call(fetch("mine.log"));
  EXPECT_EQ(chunk->fields().bytes("data").substr(0, 8), "STRDLOG2");
  EXPECT_EQ(chunk->fields().unsigned_integer("size", UINT64_MAX),
            std::filesystem::file_size(robot.dir + "/mine.log"));
}

TEST(DebugHardening, LogStartNeverOverwritesOrFollowsALink) {
  Served robot("served_overwrite", true);
  ASSERT_NE(robot.at.port, 0) << robot.process.err();
  const std::string tokens_before = read_file(robot.dir + "/tokens");
  std::ofstream(robot.dir + "/old.log") << "precious";
  std::ofstream(robot.dir + "/target") << "elsewhere";
  std::filesystem::create_symlink(robot.dir + "/target", robot.dir + "/link.log");
  DebugClient writer(robot.at, kFullToken);
  for (const std::string name : {"old.log", "tokens", "link.log"}) {
    const std::string e = refusal(writer, debug::request(Op::LogStart, name));
    EXPECT_FALSE(e.empty()) << name << " was overwritten";
    EXPECT_EQ(e.find('\n'), std::string::npos) << e;
  }
  EXPECT_EQ(read_file(robot.dir + "/old.log"), "precious");
  EXPECT_EQ(read_file(robot.dir + "/tokens"), tokens_before);
  EXPECT_EQ(read_file(robot.dir + "/target"), "elsewhere");
  // A second log of the same name is refused too: the first one stays as it was recorded.
  writer.call(debug::request(Op::LogStart, "run1.log"));
  writer.call(debug::request(Op::LogStop));
  const std::string first = read_file(robot.dir + "/run1.log");
  EXPECT_NE(refusal(writer, debug::request(Op::LogStart, "run1.log")).find("already exists"),
            std::string::npos);
  EXPECT_EQ(read_file(robot.dir + "/run1.log"), first);
}

TEST(DebugHardening, SilentPeersNeverTakeTheTeamsSlots) {
  Served robot("served_slots", true);
  ASSERT_NE(robot.at.port, 0) << robot.process.err();
  SilentPeers a(robot.at, "127.0.0.2", 9), b(robot.at, "127.0.0.3", 8);  // 17 in all
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  int admitted = 0;
  std::string last_error;
  for (int i = 0; i < 15; ++i) {
    try {
      DebugClient console(robot.at, kFullToken);
      console.call(debug::request(Op::Ping));
      ++admitted;
    } catch (const Error& e) {
      last_error = e.what();
    }
  }
  EXPECT_EQ(admitted, 15) << last_error;
  // The silent peers were timed out (2 s) and came back: they held pre-authentication slots only.
  std::this_thread::sleep_for(std::chrono::milliseconds(2500));
  EXPECT_GT(a.reopened() + b.reopened(), 17);
  DebugClient console(robot.at, kFullToken);
  console.call(debug::request(Op::Ping));
}

TEST(DebugHardening, RemoteLogOnAFullDiskStopsThatLogNotTheRun) {
  const std::string dir = fresh_dir("served_full");
  const std::string report = dir + "/report.json";
  // A file size limit of 256 KiB stands for a disk that fills; the report stays below it.
  const std::string command = "ulimit -f 512; trap '' XFSZ; exec " + kStrideRun + " run " +
                              kStandScene + " --seconds 5 --debug 127.0.0.1:0 --report " + report;
  ChildProcess run({"/bin/sh", "-c", command}, "served_full", dir);
  const std::string text = served_endpoint(run, false);
  ASSERT_FALSE(text.empty()) << run.err();
  DebugClient client(debug::parse_endpoint(text, "test"), "");
  client.call(debug::request(Op::LogStart, "big.log"));
  std::vector<std::string> notes;  // the robot tells this client, unasked
  try {
    for (int i = 0; i < 1000 && notes.empty(); ++i) {
      client.keep_alive();
      notes = client.take_notes();
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    client.call(debug::request(Op::Ping));  // the server goes on
    EXPECT_NE(refusal(client, debug::request(Op::LogStop)).find("no log"), std::string::npos);
  } catch (const debug::ConnectionLost& e) {
    ADD_FAILURE() << e.what();
  }
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].find("log 'big.log' stopped after "), std::string::npos) << notes[0];
  // The run goes on to its end and its report.
  EXPECT_EQ(run.wait_for(60), 0) << run.err();
  EXPECT_TRUE(std::filesystem::exists(report)) << run.out() << run.err();
  const std::string err = run.err();
  EXPECT_NE(err.find("log 'big.log' stopped after "), std::string::npos) << err;
  EXPECT_EQ(err.find("log 'big.log'"), err.rfind("log 'big.log'")) << "one line: " << err;
  // The frames before the disk filled stay readable.
  EXPECT_GT(LogReader(dir + "/big.log").readable_prefix(), 0u);
}

TEST(DebugHardening, MrWithAnUnknownRepresentationIsAnErrorLocallyAndRemotely) {
  const auto local =
      console::run_child({kStrideRun, "-c", "mr NoSuchRep default", kStandScene}, "");
  EXPECT_EQ(local.exit_status, 1) << local.out << local.err;
  EXPECT_NE(local.err.find("NoSuchRep"), std::string::npos) << local.err;
  EXPECT_NE(local.err.find("JointRequest"), std::string::npos) << "known names: " << local.err;
  EXPECT_EQ(local.err.find('\n'), local.err.size() - 1) << local.err;
  EXPECT_EQ(local.out.find("<-"), std::string::npos) << local.out;

  Served robot("served_mr", false);
  ASSERT_NE(robot.at.port, 0) << robot.process.err();
  const auto remote = console::run_child(
      {kStrideRun, "--connect", robot.at.text(), "-c", "mr NoSuchRep default"}, "");
  EXPECT_EQ(remote.exit_status, 1) << remote.out << remote.err;
  EXPECT_NE(remote.err.find("JointRequest"), std::string::npos) << remote.err;
  EXPECT_EQ(remote.out.find("<-"), std::string::npos) << remote.out;
  // A module that does not provide the representation names the ones that do.
  DebugClient client(robot.at, "");
  const std::string e = refusal(client, debug::request(Op::Mr, "JointRequest", "NoSuchModule"));
  EXPECT_NE(e.find("NoSuchModule"), std::string::npos) << e;
}

TEST(DebugHardening, StringsThatAreNotUtf8AreRefusedInUtf8) {
  Served robot("served_utf8", false);
  ASSERT_NE(robot.at.port, 0) << robot.process.err();
  const std::string bad = "\xff\xfe\xc3";
  for (const auto& payload :
       {raw_request("req", "get" + bad, "representation:FrameInfo"),
        raw_request("req", "get", "representation:" + bad), raw_request("req" + bad, "get", "x")}) {
    const std::string answer = answer_to(robot.at, payload);
    ASSERT_FALSE(answer.empty());
    const auto h = msgpack::unpack(answer.data(), answer.size());
    EXPECT_TRUE(all_ascii(h.get())) << answer;
    const debug::MapView m(h.get(), "answer");
    const std::string why = m.text_or("error", m.text_or("why", ""));
    EXPECT_NE(why.find("UTF-8"), std::string::npos) << why;
    EXPECT_NE(why.find("\\xff\\xfe"), std::string::npos) << why;
  }
  DebugClient client(robot.at, "");  // the server goes on serving
  client.call(debug::request(Op::Ping));
}

}  // namespace
}  // namespace stride::test
