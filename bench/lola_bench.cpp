// LoLA's cost per control frame: packet encode and decode, and the whole round trip over a unix
// socket as `stride robot` and `stride run --lola` do it (a server thread sends the 896-byte
// sensor packet and applies the 786-byte answer; LolaLink reads, decodes, encodes and answers).
// Target: below 50 us per frame for the round trip.
#include <benchmark/benchmark.h>

#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <thread>

#include "robot/hal/lola/actuator_packet.hpp"
#include "robot/hal/lola/lola_link.hpp"
#include "robot/hal/lola/lola_protocol.hpp"
#include "robot/hal/lola/packet_stream.hpp"
#include "robot/hal/lola/sensor_packet.hpp"
#include "robot/hal/unix_socket.hpp"
#include "simulator/lola/lola_frames.hpp"

namespace stride::bench {
namespace {

hal::SensorFrame standing_frame() {
  hal::SensorFrame s;
  for (int i = 0; i < hal::kNumJoints; ++i) {
    s.position[i] = 0.01 * i;
    s.stiffness[i] = 1;
    s.current[i] = 0.1;
    s.temperature[i] = 35;
  }
  s.accelerometer = {0.1, 0.0, 9.81};
  s.fsr.fill(12.0);
  return s;
}

void BM_SensorPacketEncode(benchmark::State& state) {
  const hal::SensorFrame s = standing_frame();
  std::string out;
  for (auto _ : state) {
    sim::simulated_sensor_packet(s, out);
    benchmark::DoNotOptimize(out.data());
  }
}
BENCHMARK(BM_SensorPacketEncode);

void BM_SensorPacketDecode(benchmark::State& state) {
  std::string packet;
  sim::simulated_sensor_packet(standing_frame(), packet);
  hal::SensorFrame f;
  for (auto _ : state) {
    hal::lola::decode_sensor_packet(packet, f);
    benchmark::DoNotOptimize(f.position.data());
  }
}
BENCHMARK(BM_SensorPacketDecode);

void BM_ActuatorPacketEncodeDecode(benchmark::State& state) {
  hal::ActuatorFrame a;
  a.position.fill(0.1);
  a.stiffness.fill(1);
  std::string packet;
  hal::ActuatorFrame applied;
  for (auto _ : state) {
    hal::lola::encode_actuator_packet(a, packet);
    sim::apply_lola_answer(packet, applied);
    benchmark::DoNotOptimize(applied.position.data());
  }
}
BENCHMARK(BM_ActuatorPacketEncodeDecode);

// The simulator's side in a thread: per frame, send the sensor packet and apply the answer.
void serve(hal::UnixListener& listener, std::atomic<bool>& stop) {
  auto client = listener.accept(std::chrono::steady_clock::now() + std::chrono::seconds(10));
  if (!client) return;
  const hal::SensorFrame s = standing_frame();
  hal::ActuatorFrame commands;
  hal::lola::PacketStream stream;
  std::string packet;
  while (!stop) {
    sim::simulated_sensor_packet(s, packet);
    if (!client->send_all(packet)) return;
    std::span<const char> answer;
    std::string error;
    while (stream.next(answer, error) != hal::lola::PacketStream::Result::Packet) {
      const long n = client->receive(stream.reserve(4096));
      if (n <= 0) return;
      stream.commit(static_cast<std::size_t>(n));
    }
    sim::apply_lola_answer(answer, commands);
  }
}

void BM_LolaRoundTripOverUnixSocket(benchmark::State& state) {
  const std::string path = (std::filesystem::temp_directory_path() /
                            ("stride_lola_bench_" + std::to_string(::getpid()) + ".sock"))
                               .string();
  hal::UnixListener listener(path);
  std::atomic<bool> stop{false};
  std::thread server([&] { serve(listener, stop); });
  {
    hal::lola::LolaLink link(path, hal::lola::kPeriod);
    hal::SensorFrame f;
    hal::ActuatorFrame a;
    a.position.fill(0.1);
    a.stiffness.fill(1);
    for (auto _ : state) {
      if (!link.read(f)) {
        state.SkipWithError("link lost");
        break;
      }
      link.write(a);
    }
    stop = true;
  }  // the link closes: the server thread ends
  server.join();
}
BENCHMARK(BM_LolaRoundTripOverUnixSocket)->UseRealTime();

}  // namespace
}  // namespace stride::bench

BENCHMARK_MAIN();
