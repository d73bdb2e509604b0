#include "robot/app/robot_process.hpp"

#include <algorithm>
#include <ostream>
#include <sstream>
#include <thread>

#include "robot/core/error.hpp"
#include "robot/hal/lola/simulator_restart.hpp"
#include "robot/model/urdf_loader.hpp"
#include "robot/runtime/controller_schedule.hpp"

namespace stride {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

std::string ms(double seconds) {
  std::ostringstream o;
  o.setf(std::ios::fixed);
  o.precision(1);
  o << seconds * 1e3 << " ms";
  return o.str();
}

}  // namespace

RobotProcess::RobotProcess(RobotConfig config, const ModuleRegistry& registry, std::ostream& events)
    : config_(std::move(config)), registry_(registry), events_(events) {
  std::shared_ptr<const model::RobotModel> model;
  try {
    model = std::make_shared<const model::RobotModel>(model::load_urdf(config_.urdf));
  } catch (const Error& e) {
    throw Error(config_.file + ": <model>: " + e.what());
  }
  // A robot with motors holds a failing module's frame and goes on when its disk fills.
  RuntimeConfig rc{config_.controller.providers, config_.controller.parameters, model,
                   ModuleErrorPolicy::Hold, LogErrorPolicy::StopLogging};
  link_ =
      hal::lola::LolaLink::connect(config_.lola_socket, config_.period, config_.connect_timeout);
  runtime_config_ = rc;
  try {
    runtime_ = std::make_unique<Runtime>(registry, rc, *link_);
  } catch (const Error& e) {
    throw Error(config_.file + ": <controller>: " + e.what());
  }
  check_changes(registry, rc, *link_, config_.controller.changes);
}

RobotProcess::~RobotProcess() = default;

void RobotProcess::report_frame_events() {
  std::string line;
  std::int64_t frame = 0;
  if (link_->take_new_error(line, frame)) {
    // One line a second at most: a stream of bad packets must not flood the log.
    if (seconds_since(last_error_line_) >= 1.0) {
      events_ << "stride robot: frame " << frame << ": " << line << " (frame held";
      if (errors_unreported_ > 0) events_ << "; " << errors_unreported_ << " more since the last";
      events_ << ")" << std::endl;
      last_error_line_ = Clock::now();
      errors_unreported_ = 0;
    } else {
      ++errors_unreported_;
    }
  }
  if (!runtime_->log_stopped().empty() && !log_stop_reported_) {
    events_ << "stride robot: frame " << frames_ << ": logging stopped: " << runtime_->log_stopped()
            << " (the control loop goes on)" << std::endl;
    log_stop_reported_ = true;
  }
  const auto& faults = runtime_->module_faults();
  for (; faults_reported_ < faults.size(); ++faults_reported_)
    events_ << "stride robot: frame " << faults[faults_reported_].frame << ": module '"
            << faults[faults_reported_].module << "' failed: " << faults[faults_reported_].message
            << (config_.stop_on_module_error ? " (holding the last safe command; stopping)"
                                             : " (holding the last safe command; going on)")
            << std::endl;
}

bool RobotProcess::link_down(double& lost_for) {
  if (!lost_) {
    lost_ = true;
    const double silent = link_->since_last_packet();
    lost_at_ = Clock::now() -
               std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(silent));
    events_ << "stride robot: frame " << frames_ << ": LoLA link "
            << (link_->state() == hal::lola::LolaLink::State::Closed
                    ? "lost (" + link_->closed_because() + ")"
                    : std::string("silent"))
            << ", last packet " << ms(silent) << " ago: holding the last command; exiting if it is "
            << "not back within " << config_.link_timeout << " s" << std::endl;
  }
  lost_for = seconds_since(lost_at_);
  if (lost_for > config_.link_timeout) return false;
  if (link_->state() == hal::lola::LolaLink::State::Closed) {
    std::this_thread::sleep_for(std::chrono::duration<double>(config_.period));
    link_->reconnect();
  }
  return true;
}

void RobotProcess::say_link_back() {
  if (!lost_) return;
  events_ << "stride robot: frame " << frames_ << ": LoLA link back after "
          << ms(seconds_since(lost_at_)) << std::endl;
  lost_ = false;
}

bool RobotProcess::hold_until(const std::function<bool(Runtime&)>& ready,
                              const std::function<bool()>& stop_requested) {
  hal::SensorFrame sensors;
  const auto period =
      std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(config_.period));
  auto due = Clock::now();
  while (!stop_requested() && !ready(*runtime_)) {
    if (link_->read(sensors)) {
      link_->write_nothing();
      say_link_back();
      // A NAO's LoLA paces itself; a lockstep simulator would otherwise race through its run.
      due = std::max(due + period, Clock::now() - period);
      std::this_thread::sleep_until(due);
      continue;
    }
    double lost_for = 0;
    if (!link_down(lost_for)) {
      events_ << "stride robot: no LoLA link for " << ms(lost_for) << ": exiting" << std::endl;
      return false;
    }
  }
  first_packet_ = link_->stats().packets;
  return !stop_requested();
}

void RobotProcess::restart_controller(const std::function<bool()>& stop_requested) {
  runtime_->set_frame_boundary(nullptr);  // a client's log of the old controller ends, said
  // A simulated NAO goes back to its scene's start too: held until the simulator says it did.
  if (auto simulator = hal::lola::SimulatorRestart::ask(config_.lola_socket)) {
    const auto until = Clock::now() + std::chrono::seconds(2);
    bool done = false;
    hold_until([&](Runtime&) { return (done = simulator->done()) || Clock::now() > until; },
               stop_requested);
    events_ << "stride robot: frame " << frames_
            << (done ? ": the simulator put the robot back at its start"
                     : ": the simulator did not put the robot back within 2 s")
            << std::endl;
  }
  runtime_ = std::make_unique<Runtime>(registry_, runtime_config_, *link_);
  runtime_->set_frame_boundary(boundary_);
  faults_reported_ = 0;
  events_ << "stride robot: frame " << frames_
          << ": controller restarted from its configured start (a console asked)" << std::endl;
}

int RobotProcess::run(const std::function<bool()>& stop_requested,
                      const std::function<bool()>& restart_requested) {
  ControllerSchedule schedule(config_.controller.changes);
  events_ << "stride robot: " << config_.name << " on LoLA " << config_.lola_socket << " ("
          << config_.period * 1e3 << " ms), modules:";
  for (const auto& m : runtime_->module_order()) events_ << " " << m;
  events_ << std::endl;
  while (!stop_requested()) {
    if (restart_requested && restart_requested()) {
      restart_controller(stop_requested);
      schedule = ControllerSchedule(config_.controller.changes);
      first_packet_ = link_->stats().packets;
    }
    // Changes due at the coming frame's time (LoLA's clock: one period per packet), counted from
    // the controller's start, so a wait for a console or a restart does not make them all due.
    schedule.apply_due(*runtime_, hal::lola::lola_frame_time(link_->stats().packets - first_packet_,
                                                             config_.period));
    if (runtime_->step()) {
      ++frames_;
      if (runtime_->logging()) log_frames_ = runtime_->logged_frames();
      say_link_back();
      report_frame_events();
      if (config_.stop_on_module_error && !runtime_->module_faults().empty())
        return kRobotModuleFailed;
      continue;
    }
    report_frame_events();
    double lost_for = 0;
    if (!link_down(lost_for)) {
      events_ << "stride robot: no LoLA link for " << ms(lost_for) << ": exiting" << std::endl;
      return kRobotLinkLost;
    }
  }
  return kRobotStopped;
}

std::string RobotProcess::summary() const {
  const auto& l = link_->stats();
  const auto& s = runtime_->representation<CommandSafety>();
  std::ostringstream o;
  o << "frames " << frames_ << "  LoLA packets " << l.packets << " (bad " << l.bad_packets
    << ", stale skipped " << l.stale_skipped << ")  stalls " << l.stalls << "  reconnects "
    << l.reconnects << "  torque refused " << l.torque_refused << "  unsent answers "
    << l.unsent_answers << "\n";
  o << "safety: positions clamped " << s.clamped_positions << "  stiffness clamped "
    << s.clamped_stiffness << "  non-finite held " << s.nonfinite_held << "  held frames "
    << s.held_frames << "  module errors " << s.module_errors << "\n";
  for (const auto& f : runtime_->module_faults())
    o << "module '" << f.module << "' failed in " << f.count << " frames, first at frame "
      << f.frame << ": " << f.message << "\n";
  if (!l.first_error.empty()) o << "first link error: " << l.first_error << "\n";
  if (!runtime_->log_stopped().empty())
    o << "log: stopped after " << log_frames_ << " frames: " << runtime_->log_stopped() << "\n";
  // The walking modules' count of leg IK solutions beyond the joint limits, when one runs.
  const auto names = runtime_->representation_names();
  if (std::find(names.begin(), names.end(), "WalkingJointRequest") != names.end())
    o << "leg IK beyond the joint limits: "
      << runtime_->get("representation:WalkingJointRequest.ik_beyond_limit_frames") << " frames\n";
  // A walk on request: where its plan took the torso (what the walk granted, integrated).
  if (std::find(names.begin(), names.end(), "WalkStatus") != names.end())
    o << "walk plan odometry: " << runtime_->get("representation:WalkStatus.odometry")
      << "  steps " << runtime_->get("representation:WalkStatus.steps") << "\n";
  return o.str();
}

}  // namespace stride
