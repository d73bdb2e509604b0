#pragma once
// A robot behind a debug server (`connect host:port`): the robot-side console commands over TCP.
// Values are decoded here from the type descriptions the robot sends with them, so a console
// built from another revision shows and edits the robot's representations all the same.
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "console/target/robot_target.hpp"
#include "robot/debug/debug_client.hpp"
#include "robot/framework/value.hpp"

namespace stride::console {

class RemoteTarget final : public RobotTarget {
 public:
  // Connects and authenticates; throws stride::Error (one line) naming the endpoint.
  RemoteTarget(const debug::Endpoint& endpoint, const std::string& token,
               debug::ClientOptions options = {});

  std::string name() const override;
  std::string label() const { return endpoint_.text(); }  // what `robot` and `disconnect` take
  const std::string& robot() const { return client_->hello().robot; }
  bool read_only() const { return client_->welcome().read_only; }
  bool loaded() const override { return true; }

  std::uint64_t advance(std::uint64_t steps, const std::function<bool()>& after_step) override;
  // While held, a run's stream outlives each advance and the next one goes on from the frame
  // after the last it read: a background run following the robot slice by slice does not ask the
  // robot's loop to change what it copies every frame. Released, the light stream follows.
  void hold_stream(bool hold);
  double step_seconds() const override { return period_; }
  // Asks the robot its period again while it has none (a robot that starts its loop when the
  // first console connects), waiting up to `patience` s; returns step_seconds().
  double refresh_period(double patience);
  std::string time_text() override;
  void observe(const std::vector<std::string>& keys) override { observed_ = keys; }
  std::uint64_t samples_dropped() const override { return dropped_; }

  std::string get(const std::string& key) override;
  const TypeDesc& type_of(const std::string& key) override;
  void set(const std::string& key, const std::string& fields) override;

  std::vector<std::string> representations() override;
  std::vector<std::string> parameter_modules() override;
  std::string provider_of(const std::string& representation) override;
  std::vector<std::string> providers_available(const std::string& representation) override;
  void swap_provider(const std::string& representation, const std::string& module) override;
  Providers providers() override;
  std::optional<std::vector<ModuleDeclaration>> module_declarations() override;
  std::vector<std::pair<std::string, DebugSwitch>> debug_requests() override;
  void set_debug_request(const std::string& name, DebugSwitch state) override;
  DebugOutput take_debug_output() override;

  void log_start(const std::string& path) override;
  void log_stop() override;
  std::string log_save(const std::string& path, const std::string& destination) override;

  std::string report_text() override;
  std::string report_json() override;

  // The robot's scenario from its start (Op::Restart); throws if its server does not restart.
  void restart();
  // Pings and returns what the robot said while the console waits at its prompt (a fall, a
  // lost link, a module fault, debug output): a stream of FrameInfo.frame alone carries them.
  std::vector<std::string> idle_lines();

 private:
  struct Listing {
    std::vector<std::string> representations, providers, modules, debug, debug_state;
    std::vector<std::vector<std::string>> available;
  };
  struct Root {  // a representation's or parameter set's last value and description
    std::string desc_bytes;
    TypeDescPtr desc;
    Value value;
  };
  std::unique_ptr<debug::ServerMessage> call(debug::Request r);
  Listing list();
  Root& fetch(const std::string& key);           // root of the key, fresh from the robot
  std::string streamed(const std::string& key);  // from the current sample
  std::vector<std::string> stream_keys() const;  // what a run streams: framework, then debug
  std::int64_t subscribe(const std::vector<std::string>& keys);  // the first frame streamed
  void stream_idle();                       // the light stream idle_lines() reads
  void hold_lines(const debug::Sample& s);  // a sample's lines, for the next reader
  std::string text_of(const TypeDesc& d, const std::string& bytes, const std::string& key);

  debug::Endpoint endpoint_;
  std::unique_ptr<debug::DebugClient> client_;
  double period_ = 0;
  std::map<std::string, Root> roots_;
  std::vector<std::string> observed_;
  std::vector<std::string> subscribed_;  // keys of the live subscription, in sample order
  std::vector<TypeDescPtr> subscribed_descs_;
  std::optional<debug::Sample> current_;  // while advancing
  double last_time_ = 0;
  bool idle_stream_ = false;                          // the light stream is asked for
  bool hold_stream_ = false;                          // a run's stream outlives its advance
  std::vector<std::string> stream_keys_;              // the run stream's, as asked for
  std::int64_t next_frame_ = -1;                      // after the last one a held stream read
  std::uint64_t seen_dropped_ = 0;                    // the stream's count when last read
  std::vector<std::pair<double, std::string>> held_;  // lines read between runs, with their t
  std::uint64_t dropped_ = 0;
};

}  // namespace stride::console
