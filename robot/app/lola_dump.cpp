// `stride lola dump [<socket>] [--frames N]`: decoded sensor frames from a LoLA server, for a
// person checking a robot (or the simulator's LoLA).
#include <charconv>
#include <iomanip>
#include <ostream>

#include "robot/app/flags.hpp"
#include "robot/app/robot_main.hpp"
#include "robot/app/stop_signals.hpp"
#include "robot/core/error.hpp"
#include "robot/hal/lola/lola_link.hpp"
#include "robot/hal/lola/lola_protocol.hpp"

namespace stride {
namespace {

template <std::size_t N, class T>
void named_line(std::ostream& out, const char* title, const std::array<std::string_view, N>& names,
                const std::array<T, N>& v) {
  out << "  " << title << ":";
  for (std::size_t i = 0; i < N; ++i) out << " " << names[i] << " " << v[i];
  out << "\n";
}

template <std::size_t N>
void values_line(std::ostream& out, const char* title, const std::array<double, N>& v) {
  out << "  " << title << ":";
  for (double x : v) out << " " << x;
  out << "\n";
}

void print_frame(std::ostream& out, std::int64_t n, const hal::SensorFrame& s) {
  out << std::fixed << std::setprecision(4);
  out << "frame " << n << "  t " << s.time << " s  robot " << s.robot_config[0] << " "
      << s.robot_config[1] << " / head " << s.robot_config[2] << " " << s.robot_config[3] << "\n";
  named_line(out, "position [rad]", hal::kJointNames, s.position);
  named_line(out, "stiffness", hal::kJointNames, s.stiffness);
  named_line(out, "current [A]", hal::kJointNames, s.current);
  named_line(out, "temperature [degC]", hal::kJointNames, s.temperature);
  named_line(out, "status", hal::kJointNames, s.status);
  values_line(out, "accelerometer [m/s^2, torso frame, +z up]", s.accelerometer);
  values_line(out, "gyroscope [rad/s]", s.gyroscope);
  values_line(out, "angles [rad, roll pitch]", s.angles);
  named_line(out, "fsr [N]", hal::kFsrNames, s.fsr);
  values_line(out, "battery [charge, status, A, degC]", s.battery);
  values_line(out, "sonar [m]", s.sonar);
  named_line(out, "touch", hal::kTouchNames, s.touch);
}

std::int64_t frame_count(const Flags& f) {
  const std::string t = f.value_or("--frames", "0");
  std::int64_t n = 0;
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), n);
  if (ec != std::errc() || end != t.data() + t.size() || n < 0)
    throw Error("stride lola dump: --frames: expected a count >= 0 (0: until stopped), got '" + t +
                "'");
  return n;
}

}  // namespace

int lola_main(std::span<const std::string> args, std::ostream& out, std::ostream& err) {
  StopSignals stop;
  std::unique_ptr<hal::lola::LolaLink> link;
  std::int64_t frames = 0;
  try {
    if (args.empty() || args[0] != "dump")
      throw Error("stride lola: expected 'dump' (usage: stride " + std::string(kLolaUsage) + ")");
    const Flags f = read_flags(args.subspan(1), {"--frames"}, "stride lola dump");
    if (f.positional.size() > 1)
      throw Error("stride lola dump: unexpected argument '" + f.positional[1] + "'");
    const std::string socket =
        f.positional.empty() ? std::string(hal::lola::kDefaultSocket) : f.positional[0];
    frames = frame_count(f);
    link = std::make_unique<hal::lola::LolaLink>(socket, hal::lola::kPeriod);
  } catch (const Error& e) {
    err << e.what() << std::endl;
    return 1;
  }
  hal::SensorFrame s;
  std::int64_t n = 0;
  std::string line;
  std::int64_t packet = 0;
  while (!stop.requested() && (frames == 0 || n < frames)) {
    const bool got = link->read(s);
    while (link->take_new_error(line, packet))
      err << "stride lola dump: packet " << packet << ": " << line << std::endl;
    if (got) {
      link->write_nothing();
      print_frame(out, ++n, s);
      out << std::flush;
    } else if (link->state() == hal::lola::LolaLink::State::Closed) {
      err << "stride lola dump: the LoLA server closed the socket after " << n << " frames"
          << std::endl;
      return 2;
    }
  }
  const auto& st = link->stats();
  err << "stride lola dump: " << n << " frames, " << st.bad_packets << " bad packets" << std::endl;
  return 0;
}

}  // namespace stride
