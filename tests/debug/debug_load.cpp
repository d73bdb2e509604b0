// debug_load: the debug server under load against a 12 ms real-time robot loop.
//   debug_load [--seconds S] [--block B] [--clients N] [--fields F] [--scene f]
//              [--judge all|streams] [--rt-priority 1..99] [--cpu K] [--twin on|off]
//              [--view on|off]  (--serve-twin <scene>: the twin robot's own process)
// The simulated NAO walks (Ch. 4 hip strategy, medium speed) with a 12 ms control period, paced
// to the wall clock, its controller served by a debug server. Quiet blocks (no client) alternate
// with loaded blocks (N clients each streaming F fields every frame while one more floods garbage
// and another connects and drops in a loop, each its own debug_peer process): quiet, loaded,
// quiet, ..., quiet, S seconds loaded in all, in blocks of B seconds (default B = S: one loaded
// block between two quiet ones). Alternating short blocks lets both conditions see the same
// drift of the machine and the same mix of the walk. Prints per condition the frames, the missed
// frames (a frame whose control step started a whole period late), the control step's compute
// time (modules + the debug exchange) and the frame boundary's own time p50/p99/max, and the
// clients' account of their streams. Exit 1 if a criterion fails: an honest stream not complete
// (every frame received or counted as dropped), or with --judge all a missed frame or a loaded
// p99 more than 10 % over the quiet one. --rt-priority runs the loop under SCHED_FIFO, as
// `stride robot --rt-priority` does on the NAO (the server thread and the peers stay normal);
// --cpu gives the loop CPU K alone (the server thread and the peers run on the others), so the
// network work of the flood, done where its sockets live, stays off the loop's CPU. --twin on
// adds a block after each loaded one whose peers load a twin robot's server instead (see Twin):
// the machine as loaded, this robot with no client; the p99 bound is then judged against those
// blocks, and the ratio to the quiet blocks is printed beside it. --view on loads the robot with
// the live view instead: `stride view --connect` and a page watching 20 numbers (view_peer.py).
// Each step's thread CPU time and the host's steal on the loop's CPU are printed too.
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <thread>
#include <vector>

#include "console/session/sim_session.hpp"
#include "robot/core/number_text.hpp"
#include "robot/core/thread_priority.hpp"
#include "robot/debug/server.hpp"
#include "simulator/scene/scene_parser.hpp"
#include "tests/simulator/frame_hook.hpp"
#include "timed_boundary.hpp"

extern char** environ;

namespace {

using namespace stride;
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
constexpr double kPeriod = 0.012;  // s, the NAO's LoLA cycle as a 12 ms control frame

struct Options {
  double seconds = 10;
  double block = 0;  // 0: one block of `seconds`
  int clients = 8;
  int fields = 50;
  std::string scene = STRIDE_SOURCE_DIR "/scenes/experiments/hip_medium.xml";
  bool judge_timing = true;
  int rt_priority = 0;  // 0: time-shared
  int cpu = -1;         // -1: any
  bool twin = false;    // also load a twin robot's server (this robot then has no client)
  bool view = false;    // the load is a live view (stride view + a page), not debug_peers
};

Options read_options(int argc, char** argv) {
  Options o;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string flag = argv[i], value = argv[i + 1];
    if (flag == "--seconds")
      o.seconds = std::stod(value);
    else if (flag == "--block")
      o.block = std::stod(value);
    else if (flag == "--clients")
      o.clients = std::stoi(value);
    else if (flag == "--fields")
      o.fields = std::stoi(value);
    else if (flag == "--scene")
      o.scene = value;
    else if (flag == "--judge")
      o.judge_timing = value == "all";
    else if (flag == "--rt-priority")
      o.rt_priority = parse_realtime_priority(value, "debug_load: --rt-priority");
    else if (flag == "--cpu")
      o.cpu = static_cast<int>(parse_integer(value, "debug_load: --cpu", 0, 1023));
    else if (flag == "--twin" && (value == "on" || value == "off"))
      o.twin = value == "on";
    else if (flag == "--view" && (value == "on" || value == "off"))
      o.view = value == "on";
    else
      throw Error("debug_load: unknown flag '" + flag + "'");
  }
  if (argc % 2 == 0) throw Error("debug_load: every flag takes a value");
  if (!(o.seconds > 0) || o.block < 0 || o.block > o.seconds)
    throw Error("debug_load: expected 0 < --block <= --seconds");
  if (o.block == 0) o.block = o.seconds;
  return o;
}

// F keys over the 25 joints: JointRequest positions, then JointSensorData positions, currents.
std::string field_spec(int fields) {
  std::string spec;
  const char* arrays[] = {"JointRequest.position", "JointSensorData.position",
                          "JointSensorData.current", "JointSensorData.temperature"};
  for (int i = 0; fields > 0 && i < 4; ++i) {
    const int n = std::min(fields, 25);
    spec += (spec.empty() ? "" : ",") + std::string(arrays[i]) + ":" + std::to_string(n);
    fields -= n;
  }
  return spec;
}

struct Peer {
  pid_t pid;
  std::string output;  // file with its result line
};

// Starts a peer on `cpus` (children inherit the starting thread's CPUs), then returns the
// calling thread to `home`.
// `program` empty: debug_peer beside this tool.
Peer spawn_peer(const std::vector<std::string>& args, const std::string& output,
                const std::vector<int>& cpus, const std::vector<int>& home, std::string peer = "") {
  if (!cpus.empty()) set_cpu_affinity(cpus, "debug_load: --cpu");
  if (peer.empty())
    peer = (fs::path(fs::read_symlink("/proc/self/exe")).parent_path() / "debug_peer").string();
  std::vector<std::string> all{peer};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, output.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = 0;
  if (posix_spawn(&pid, peer.c_str(), &actions, nullptr, argv.data(), environ) != 0)
    throw Error("debug_load: cannot start " + peer);
  posix_spawn_file_actions_destroy(&actions);
  if (!home.empty()) set_cpu_affinity(home, "debug_load: --cpu");
  return {pid, output};
}

std::string finish_peer(const Peer& p) {
  int status = 0;
  waitpid(p.pid, &status, 0);
  std::ifstream in(p.output);
  std::string line;
  std::getline(in, line);
  return line + (WIFEXITED(status) && WEXITSTATUS(status) == 0 ? "" : " (exit status nonzero)");
}

std::vector<double> percentiles(std::vector<double> v, std::initializer_list<double> ps) {
  std::vector<double> out;
  if (v.empty()) return std::vector<double>(ps.size(), 0.0);
  std::sort(v.begin(), v.end());
  for (double p : ps)
    out.push_back(v[std::min(v.size() - 1, static_cast<std::size_t>(p * (v.size() - 1)))]);
  return out;
}

// One condition's frames, pooled over its blocks.
struct Condition {
  std::string name;
  std::vector<double> compute_us, boundary_us;
  std::vector<double> steady_us;  // compute_us after each block's first 1.5 s (a view attaching)
  std::vector<double> cpu_us;  // the loop thread's CPU time in the step (the host's steal excluded)
  std::vector<double> due_s;   // each frame's time into its block
  std::vector<bool> allocated;    // the loop allocated a snapshot buffer or copy in that frame
  std::uint64_t steal_ticks = 0;  // time the host ran something else on the loop's vCPU
  std::int64_t frames = 0, missed = 0, blocks = 0;
  std::uint64_t allocations = 0;  // snapshot buffers and copies the loop allocated
  std::uint64_t interrupts = 0;   // on the loop's CPU (with --cpu), all sources
  std::uint64_t shootdowns = 0;   // of them TLB shootdowns (another thread unmapped memory)
  double p99() const { return percentiles(compute_us, {0.99})[0]; }
  double steady_p99() const { return percentiles(steady_us, {0.99})[0]; }
  double cpu_p99() const { return percentiles(cpu_us, {0.99})[0]; }
};

// Interrupts CPU `cpu` has taken since boot (/proc/interrupts' column): of the named source
// ("TLB:"), or every source summed ("").
std::uint64_t interrupts_on(int cpu, const std::string& source = "") {
  if (cpu < 0) return 0;
  std::ifstream in("/proc/interrupts");
  std::string line;
  std::getline(in, line);  // the CPU names
  std::uint64_t sum = 0;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::string name;
    fields >> name;
    if (!source.empty() && name != source) continue;
    std::uint64_t n = 0;
    for (int i = 0; i <= cpu && fields >> n; ++i)
      if (i == cpu) sum += n;
  }
  return sum;
}

// The loop thread's CPU time (with paravirtual steal accounting, without the host's steal).
double thread_cpu_us() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) * 1e6 + static_cast<double>(t.tv_nsec) * 1e-3;
}

// Ticks of steal time on CPU `cpu` since boot (/proc/stat's eighth column).
std::uint64_t steal_on(int cpu) {
  if (cpu < 0) return 0;
  std::ifstream in("/proc/stat");
  const std::string name = "cpu" + std::to_string(cpu);
  for (std::string line; std::getline(in, line);) {
    std::istringstream fields(line);
    std::string first;
    fields >> first;
    if (first != name) continue;
    std::uint64_t v = 0;
    for (int i = 0; i < 8 && fields >> v; ++i) {
    }
    return v;
  }
  return 0;
}

// Runs the walking robot in real time for `seconds`, timing each control step and its boundary.
void run_block(sim::Simulation& sim, PacedRuntime& rt, const test::TimedBoundary& boundary,
               const debug::DebugServer& server, int cpu, double seconds, Condition& c) {
  const double period = kPeriod;
  const std::uint64_t allocations_before = server.stats().loop_allocations;
  const std::uint64_t interrupts_before = interrupts_on(cpu);
  const std::uint64_t shootdowns_before = interrupts_on(cpu, "TLB:");
  const std::uint64_t steal_before = steal_on(cpu);
  const double start = sim.time();
  const auto wall_start = Clock::now();
  test::FrameHook hook([&](const hal::SensorFrame& sensors, hal::ActuatorFrame& commands) {
    const std::uint64_t made = server.stats().loop_allocations;  // read outside the timed step
    const auto now = Clock::now();
    const double due = sim.time() - start;
    const double late = std::chrono::duration<double>(now - wall_start).count() - due;
    if (late > period) ++c.missed;
    const double cpu_start = thread_cpu_us();
    const bool written = rt.step(sensors, commands);
    c.compute_us.push_back(std::chrono::duration<double, std::micro>(Clock::now() - now).count());
    if (due >= 1.5) c.steady_us.push_back(c.compute_us.back());
    c.due_s.push_back(due);
    c.allocated.push_back(server.stats().loop_allocations != made);
    c.cpu_us.push_back(thread_cpu_us() - cpu_start);
    c.boundary_us.push_back(static_cast<double>(boundary.last_ns.load()) * 1e-3);
    ++c.frames;
    return written;
  });
  sim.set_controller(0, &hook);
  while (sim.time() - start < seconds - 1e-9) {
    sim.step();
    std::this_thread::sleep_until(wall_start +
                                  std::chrono::duration_cast<Clock::duration>(
                                      std::chrono::duration<double>(sim.time() - start)));
  }
  sim.set_controller(0, nullptr);  // the hook ends with this block
  ++c.blocks;
  c.allocations += server.stats().loop_allocations - allocations_before;
  c.interrupts += interrupts_on(cpu) - interrupts_before;
  c.shootdowns += interrupts_on(cpu, "TLB:") - shootdowns_before;
  c.steal_ticks += steal_on(cpu) - steal_before;
}

// The integer after "key=" in a peer's result line (0 when absent).
std::uint64_t field_of(const std::string& line, const std::string& key) {
  const auto at = line.find(key + "=");
  return at == std::string::npos ? 0 : std::stoull(line.substr(at + key.size() + 1));
}

// The clients' accounts, summed over the loaded blocks.
struct PeerTotals {
  std::int64_t streams = 0, complete = 0;
  std::uint64_t received = 0, dropped = 0, flood_bytes = 0, flood_connections = 0, churned = 0;
  std::string first_failure;
  std::vector<std::string> views;  // a live view's page: what it received
  void add(const std::string& line) {
    if (line.starts_with("role=honest")) {
      ++streams;
      const bool ok =
          line.find("complete=1") != std::string::npos && line.find("nonzero") == std::string::npos;
      complete += ok;
      if (!ok && first_failure.empty()) first_failure = line;
      received += field_of(line, "received");
      dropped += field_of(line, "dropped");
    } else if (line.starts_with("role=garbage")) {
      flood_bytes += field_of(line, "bytes");
      flood_connections += field_of(line, "connections");
    } else if (line.starts_with("role=churn")) {
      churned += field_of(line, "greeted");
    } else if (line.starts_with("view peer:")) {
      views.push_back(line);
      if (line.find("nonzero") != std::string::npos && first_failure.empty()) first_failure = line;
    }
  }
};

struct Peers {
  std::string at;
  std::vector<int> cpus, loop_cpu;
  fs::path dir;
};

// A twin robot in its own process (`debug_load --serve-twin <scene>`): the same walking robot
// with its own debug server, its physics paced to the wall clock on the peers' CPUs for the whole
// run. A block whose peers load the twin's server loads the machine as a loaded block does while
// this robot has no client: the same run with no client, which tells the server's cost to the loop
// from the machine's. Its clock runs, so a view attached to it follows it as it would this robot.
sim::SceneDescription scene_of(const std::string& file) {
  sim::SceneDescription scene = sim::parse_scene_file(file);
  scene.robots.at(0).period = kPeriod;
  return scene;
}

// The twin's process: prints "twin at host:port", then runs until its parent is gone.
int serve_twin(const std::string& scene_file) {
  console::SimSession session(scene_of(scene_file));
  debug::ServerOptions options;
  options.listen = {"127.0.0.1", 0};
  options.robot = "twin";
  options.max_clients = 64;
  options.log = [](const std::string&) {};
  debug::DebugServer server(options);
  session.runtime(0)->set_frame_boundary(&server.boundary());
  std::cout << "twin at " << server.endpoint().text() << std::endl;
  const pid_t parent = getppid();
  sim::Simulation& sim = session.simulation();
  const auto start = Clock::now();
  const double t0 = sim.time();
  while (getppid() == parent) {  // one control period of physics, then wait for the wall clock
    const double until = sim.time() + kPeriod;
    while (sim.time() < until - 1e-9) sim.step();
    std::this_thread::sleep_until(start + std::chrono::duration_cast<Clock::duration>(
                                              std::chrono::duration<double>(sim.time() - t0)));
  }
  session.runtime(0)->set_frame_boundary(nullptr);
  return 0;
}

class Twin {
 public:
  Twin(const Options& o, const Peers& where)
      : peer_(spawn_peer({"--serve-twin", o.scene}, (where.dir / "twin").string(), where.cpus,
                         where.loop_cpu, fs::read_symlink("/proc/self/exe").string())) {
    for (int i = 0; i < 200 && at_.empty(); ++i) {  // up to 10 s for it to listen
      std::ifstream in(peer_.output);
      std::string line;
      if (std::getline(in, line) && line.starts_with("twin at ")) at_ = line.substr(8);
      if (at_.empty()) std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    if (at_.empty()) {
      stop();
      throw Error("debug_load: the twin robot did not start (see " + peer_.output + ")");
    }
  }
  ~Twin() { stop(); }
  Twin(const Twin&) = delete;
  Twin& operator=(const Twin&) = delete;
  const std::string& at() const { return at_; }

 private:
  void stop() {
    if (peer_.pid <= 0) return;
    kill(peer_.pid, SIGTERM);
    waitpid(peer_.pid, nullptr, 0);
    peer_.pid = 0;
  }
  Peer peer_;
  std::string at_;
};

// One loaded block: the peers run `block` seconds, the loop one more so they end within it.
void run_loaded_block(sim::Simulation& sim, PacedRuntime& rt, const test::TimedBoundary& boundary,
                      const debug::DebugServer& server, const Options& o, const Peers& where,
                      const std::string& at, Condition& c, PeerTotals& totals) {
  std::vector<Peer> peers;
  const std::string peer_seconds = std::to_string(o.block);
  if (o.view) {  // Debian's python3 has python3-websocket
    peers.push_back(spawn_peer({STRIDE_SOURCE_DIR "/tests/debug/view_peer.py",
                                STRIDE_BINARY_DIR "/stride", at, peer_seconds},
                               (where.dir / "view").string(), where.cpus, where.loop_cpu,
                               "/usr/bin/python3"));
    run_block(sim, rt, boundary, server, o.cpu, o.block + 1.0, c);
    for (const auto& p : peers) totals.add(finish_peer(p));
    return;
  }
  for (int i = 0; i < o.clients; ++i)
    peers.push_back(spawn_peer({"honest", at, peer_seconds, field_spec(o.fields), "1"},
                               (where.dir / ("honest" + std::to_string(i))).string(), where.cpus,
                               where.loop_cpu));
  peers.push_back(spawn_peer({"garbage", at, peer_seconds}, (where.dir / "garbage").string(),
                             where.cpus, where.loop_cpu));
  peers.push_back(spawn_peer({"churn", at, peer_seconds}, (where.dir / "churn").string(),
                             where.cpus, where.loop_cpu));
  run_block(sim, rt, boundary, server, o.cpu, o.block + 1.0, c);
  for (const auto& p : peers) totals.add(finish_peer(p));
}

void print_condition(const Condition& c) {
  const auto step = percentiles(c.compute_us, {0.5, 0.99, 1.0});
  const auto edge = percentiles(c.boundary_us, {0.5, 0.99, 1.0});
  const auto cpu = percentiles(c.cpu_us, {0.5, 0.99, 1.0});
  std::cout << "  " << c.name << " (" << c.blocks << " blocks): frames " << c.frames << ", missed "
            << c.missed << ", control step us p50 " << step[0] << " p99 " << step[1] << " max "
            << step[2] << "; frame boundary us p50 " << edge[0] << " p99 " << edge[1] << " max "
            << edge[2] << "; loop allocations " << c.allocations
            << ", interrupts on the loop's CPU " << c.interrupts << " (TLB shootdowns "
            << c.shootdowns << "), steal ticks " << c.steal_ticks << "; step CPU time us p50 "
            << cpu[0] << " p99 " << cpu[1] << " max " << cpu[2] << "\n";
}

// Where a condition's slowest frames fall in its blocks: of the frames over `threshold`, how many
// in each half second from a block's start (a view attaching shows as a heap at the start).
void print_tail_by_time(const Condition& c, double threshold) {
  std::vector<int> bins;
  int allocating = 0;
  for (std::size_t i = 0; i < c.compute_us.size(); ++i) {
    if (c.compute_us[i] <= threshold) continue;
    allocating += c.allocated[i] ? 1 : 0;
    const auto bin = static_cast<std::size_t>(c.due_s[i] / 0.5);
    if (bins.size() <= bin) bins.resize(bin + 1, 0);
    ++bins[bin];
  }
  std::cout << "  " << c.name << " frames over " << threshold << " us by half second into a block:";
  for (int n : bins) std::cout << " " << n;
  std::cout << " (" << allocating << " of them allocating)\n";
}

// Prints the figures; true when every criterion holds.
bool report(const Options& o, const Condition& quiet, const Condition& loaded,
            const Condition& twin, const PeerTotals& t, const debug::DebugServer& server,
            std::uint64_t log_lines) {
  std::cout << "debug_load: "
            << (o.view
                    ? std::string("a live view (stride view --connect, a page watching 20 numbers)")
                    : std::to_string(o.clients) + " clients x " + std::to_string(o.fields) +
                          " fields every 12 ms frame, + garbage flood + connect/drop loop")
            << ", " << o.seconds << " s loaded in blocks of " << o.block
            << " s between quiet blocks, loop "
            << (o.rt_priority > 0 ? "SCHED_FIFO " + std::to_string(o.rt_priority) : "time-shared")
            << (o.cpu >= 0 ? " on CPU " + std::to_string(o.cpu) + " alone" : "") << "\n";
  std::cout.setf(std::ios::fixed);
  std::cout.precision(1);
  print_condition(quiet);
  print_condition(loaded);
  if (o.twin) print_condition(twin);
  // With a twin, "no client" is the twin's blocks: the same load on the machine.
  const Condition& reference = o.twin ? twin : quiet;
  const double ratio = loaded.p99() / reference.p99();
  std::cout.precision(3);
  std::cout << "  loaded p99 / quiet p99 = " << loaded.p99() / quiet.p99() << " (CPU time "
            << loaded.cpu_p99() / quiet.cpu_p99() << ")";
  if (o.twin)
    std::cout << "; loaded p99 / twin-loaded p99 = " << ratio << " (CPU time "
              << loaded.cpu_p99() / twin.cpu_p99() << ")";
  std::cout << "; limit 1.10 on the " << (o.twin ? "second" : "first") << "\n";
  std::cout << "  after each block's first 1.5 s (attached, not attaching): loaded p99 / "
            << reference.name << " p99 = " << loaded.steady_p99() / reference.steady_p99() << " ("
            << loaded.steady_p99() << " / " << reference.steady_p99() << " us)\n";
  if (o.twin) {  // the tail over both conditions' pooled p99, where it falls in time
    std::vector<double> both = loaded.compute_us;
    both.insert(both.end(), twin.compute_us.begin(), twin.compute_us.end());
    const double threshold = percentiles(both, {0.99})[0];
    print_tail_by_time(loaded, threshold);
    print_tail_by_time(twin, threshold);
  }
  std::cout << "  honest streams: " << t.complete << " of " << t.streams << " complete, "
            << t.received << " samples received, " << t.dropped << " dropped (counted)\n"
            << "  garbage flood: " << t.flood_bytes << " bytes over " << t.flood_connections
            << " connections; churn: " << t.churned << " connections greeted and dropped\n";
  for (const auto& v : t.views) std::cout << "  " << v << "\n";
  if (!t.first_failure.empty())
    std::cout << "  first incomplete stream: " << t.first_failure << "\n";
  const auto stats = server.stats();
  std::cout << "  server: " << stats.accepted << " connections, " << stats.rejected << " rejected, "
            << stats.requests << " requests, " << stats.samples_sent << " samples sent, "
            << stats.samples_dropped << " dropped, " << stats.snapshots_lost
            << " frames missed by the server thread, " << log_lines << " log lines\n";
  const bool streams_ok = o.view ? !t.views.empty() && t.first_failure.empty()
                                 : t.streams > 0 && t.complete == t.streams;
  bool ok = streams_ok;
  if (!streams_ok) std::cout << "FAIL: an honest stream is incomplete and not counted\n";
  if (o.judge_timing) {
    if (loaded.missed > 0) std::cout << "FAIL: missed frames under load\n";
    if (ratio > 1.10)
      std::cout << "FAIL: loaded p99 more than 10 % over the " << reference.name << " p99\n";
    ok = ok && loaded.missed == 0 && ratio <= 1.10;
  }
  std::cout << (ok ? "PASS" : "FAIL") << std::endl;
  return ok;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    if (argc == 3 && std::string(argv[1]) == "--serve-twin") return serve_twin(argv[2]);
    const Options o = read_options(argc, argv);
    console::SimSession session(scene_of(o.scene));
    Runtime& runtime = *session.runtime(0);
    PacedRuntime& rt = *session.paced_runtime(0);
    debug::ServerOptions options;
    options.listen = {"127.0.0.1", 0};
    options.robot = "nao";
    options.max_clients = static_cast<std::size_t>(o.clients) + 8;
    std::uint64_t log_lines = 0;
    options.log = [&](const std::string&) { ++log_lines; };  // counted, not printed
    Peers where;
    if (o.cpu >= 0) {
      where.loop_cpu = {o.cpu};
      where.cpus = cpus_except(o.cpu);
      set_cpu_affinity(where.cpus, "debug_load: --cpu");  // the server thread inherits these
    }
    debug::DebugServer server(options);
    where.dir = fs::temp_directory_path() / ("debug_load_" + std::to_string(getpid()));
    fs::create_directories(where.dir);
    std::unique_ptr<Twin> other;
    if (o.twin) other = std::make_unique<Twin>(o, where);
    if (o.cpu >= 0) set_cpu_affinity(where.loop_cpu, "debug_load: --cpu");
    test::TimedBoundary boundary(server.boundary());
    runtime.set_frame_boundary(&boundary);
    where.at = server.endpoint().text();
    if (o.rt_priority > 0) set_realtime_priority(o.rt_priority, "debug_load: --rt-priority");
    auto& sim = session.simulation();

    Condition quiet{"quiet"}, loaded{"loaded"}, twin{"twin-loaded"};
    PeerTotals totals;
    const int blocks = std::max(1, static_cast<int>(std::lround(o.seconds / o.block)));
    run_block(sim, rt, boundary, server, o.cpu, o.block, quiet);
    for (int i = 0; i < blocks; ++i) {
      run_loaded_block(sim, rt, boundary, server, o, where, where.at, loaded, totals);
      run_block(sim, rt, boundary, server, o.cpu, o.block, quiet);
      if (!other) continue;
      run_loaded_block(sim, rt, boundary, server, o, where, other->at(), twin, totals);
      run_block(sim, rt, boundary, server, o.cpu, o.block, quiet);
    }
    other.reset();
    runtime.set_frame_boundary(nullptr);
    fs::remove_all(where.dir);
    return report(o, quiet, loaded, twin, totals, server, log_lines) ? 0 : 1;
  } catch (const Error& e) {
    std::cerr << e.what() << "\n";
    return 2;
  }
}
