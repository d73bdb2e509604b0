#include "robot/debug/robot_report.hpp"

#include <sstream>

#include "robot/core/json_writer.hpp"
#include "robot/debug/msgpack_map.hpp"
#include "robot/debug/server_message.hpp"

namespace stride::debug {

std::string robot_report_text(const RobotState& s, const ServerStats& st) {
  std::ostringstream o;
  o.precision(10);
  o << "robot " << s.robot << ": frame " << s.frame << ", time " << s.time << " s, period "
    << s.period << " s\n";
  o << "providers:";
  for (std::size_t i = 0; i < s.listing->representations.size(); ++i)
    o << (i ? ", " : " ") << s.listing->representations[i] << " <- "
      << (s.listing->providers[i].empty() ? "(built in)" : s.listing->providers[i]);
  o << "\nmodule times (last frame, us):";
  for (std::size_t i = 0; i < s.listing->module_order.size() && i < s.module_ns.size(); ++i)
    o << (i ? ", " : " ") << s.listing->module_order[i] << " " << s.module_ns[i] / 1000.0;
  o << "\ndebug requests:";
  if (s.listing->debug_requests.empty()) o << " none";
  for (std::size_t i = 0; i < s.listing->debug_requests.size(); ++i)
    o << (i ? ", " : " ") << s.listing->debug_requests[i] << " " << s.debug_states[i];
  o << "\nlog: ";
  if (s.log_file.empty() && s.log_frames == 0)
    o << "none";
  else
    o << (s.log_file.empty() ? "(started on the robot)" : s.log_file) << ", " << s.log_frames
      << " frames";
  o << "\ndebug server: " << st.clients << " client(s), " << st.accepted << " connection(s), "
    << st.rejected << " rejected, " << st.requests << " request(s), " << st.samples_sent
    << " samples sent, " << st.samples_dropped << " dropped for slow clients, " << st.snapshots_lost
    << " frames missed by the server\n";
  return o.str();
}

std::string robot_report_json(const RobotState& s, const ServerStats& st) {
  JsonWriter j;
  j.begin_object();
  j.key("robot").value(s.robot);
  j.key("frame").value(static_cast<long long>(s.frame));
  j.key("time").value(s.time);
  j.key("period").value(s.period);
  j.key("providers").begin_object();
  for (std::size_t i = 0; i < s.listing->representations.size(); ++i)
    j.key(s.listing->representations[i]).value(s.listing->providers[i]);
  j.end_object();
  j.key("module_ns").begin_object();
  for (std::size_t i = 0; i < s.listing->module_order.size() && i < s.module_ns.size(); ++i)
    j.key(s.listing->module_order[i]).value(static_cast<long long>(s.module_ns[i]));
  j.end_object();
  j.key("debug_requests").begin_object();
  for (std::size_t i = 0; i < s.listing->debug_requests.size(); ++i)
    j.key(s.listing->debug_requests[i]).value(s.debug_states[i]);
  j.end_object();
  j.key("log").value(s.log_file);
  j.key("log_frames").value(static_cast<long long>(s.log_frames));
  j.key("debug_server").begin_object();
  j.key("clients").value(static_cast<long long>(st.clients));
  j.key("accepted").value(static_cast<long long>(st.accepted));
  j.key("rejected").value(static_cast<long long>(st.rejected));
  j.key("requests").value(static_cast<long long>(st.requests));
  j.key("samples_sent").value(static_cast<long long>(st.samples_sent));
  j.key("samples_dropped").value(static_cast<long long>(st.samples_dropped));
  j.key("snapshots_lost").value(static_cast<long long>(st.snapshots_lost));
  j.end_object();
  j.end_object();
  return j.str() + "\n";
}

void write_list_fields(MapWriter& w, const RobotState& s) {
  w.text("robot", s.robot)
      .number("period", s.period)
      .integer("frame", s.frame)
      .number("time", s.time)
      .texts("representations", s.listing->representations)
      .texts("providers", s.listing->providers)
      .text_lists("available", s.listing->available)
      .texts("modules", s.listing->parameter_modules)
      .texts("debug", s.listing->debug_requests)
      .texts("debug_state", s.debug_states)
      .texts("order", s.listing->module_order)
      .text("log", s.log_file)
      .unsigned_integer("log_frames", s.log_frames);
  write_module_graph(w, s.listing->declarations);
}

}  // namespace stride::debug
