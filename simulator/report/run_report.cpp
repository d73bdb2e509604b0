#include "simulator/report/run_report.hpp"

#include <cstdio>
#include <numbers>
#include <sstream>

#include "robot/core/json_writer.hpp"
#include "robot/framework/enum_names.hpp"
#include "simulator/scene/solver_names.hpp"

namespace stride::sim {

std::string hash_hex(std::uint64_t h) {
  char buf[20];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

std::string solver_text(const PhysicsSettings& physics) {
  std::ostringstream o;
  o << enum_name(physics.solver);
  if (physics.solver != PhysicsSettings::Solver::Iterative) return o.str();
  o << " " << physics.iterations;
  if (physics.sor != 1.3) o << " sor " << physics.sor;
  return o.str();
}

// The contact the figures were solved with: the scene's <contact> law, or the engine's own.
std::string contact_text(const PhysicsSettings& physics) {
  if (!physics.contact_law) return "engine's own";
  const ContactLaw& law = *physics.contact_law;
  std::ostringstream o;
  o << "law k " << law.stiffness << " N/m c " << law.damping << " N s/m per "
    << (law.per_body ? "body" : "point") << " mu " << law.friction << " "
    << (law.cone == ContactLaw::Cone::Elliptic ? "elliptic" : "pyramid");
  return o.str();
}

std::string run_report_json(const Simulation& sim, const RunTiming& timing) {
  JsonWriter j;
  j.begin_object();
  j.field("scene", sim.scene().name);
  j.field("seed", static_cast<long long>(sim.scene().physics.seed));
  // Results depend on the solver setting (docs/solver-settings.md), so every report names it.
  j.field("solver", solver_text(sim.scene().physics));
  j.field("engine", sim.world().engine_name());
  j.field("step", sim.scene().physics.step);
  j.field("contact", contact_text(sim.scene().physics));
  j.field("sim_time", sim.time());
  if (timing.interrupted)
    j.field("interrupted", true).field("requested_time", timing.requested_time);
  j.field("wall_time", timing.wall_time);
  j.field("real_time_factor", timing.wall_time > 0 ? sim.time() / timing.wall_time : 0.0);
  j.field("physics_steps", static_cast<long long>(sim.steps()));
  j.field("state_hash", hash_hex(sim.state_hash()));
  j.key("robots").begin_array();
  for (int i = 0; i < sim.robot_count(); ++i) {
    const auto& r = sim.robot(i);
    const TorsoPose p = r.torso_pose();
    j.begin_object();
    j.field("name", r.name());
    j.field("fell", r.fallen());
    if (!r.calibration_errors().empty()) {
      j.key("calibration_errors").begin_object();  // rad, the zero errors this seed drew
      for (const auto& [joint, error] : r.calibration_errors()) j.field(joint, error);
      j.end_object();
    }
    j.key("torso").begin_object();
    j.field("x", p.x).field("y", p.y).field("z", p.z);
    j.field("roll", p.roll).field("pitch", p.pitch).field("yaw", p.yaw);
    j.end_object();
    const WalkMetricsResult w = sim.walk_metrics(i).result();
    j.key("walk").begin_object();
    j.field("steps", w.steps).field("fk_distance", w.fk_distance);
    j.field("true_distance", w.true_distance).field("torso_distance", w.torso_distance);
    j.field("duration", w.duration).field("fk_speed", w.fk_speed).field("true_speed", w.true_speed);
    j.field("mean_step_length", w.mean_step_length);
    j.field("pitch_min", w.pitch_min).field("pitch_max", w.pitch_max);
    j.field("roll_min", w.roll_min).field("roll_max", w.roll_max);
    j.field("fell", w.fell).field("fell_at", w.fell_at);
    j.field("tipped", std::string(tip_name(w.tipped))).field("tipped_at", w.tipped_at);
    j.field("foot_slip", w.foot_slip).field("foot_slip_net_x", w.foot_slip_net_x);
    j.field("foot_tilt_max", w.foot_tilt_max).field("foot_tilted_time", w.foot_tilted_time);
    j.field("foot_spin", w.foot_spin).field("foot_spin_max", w.foot_spin_max);
    j.field("yaw_min", w.yaw_min).field("yaw_max", w.yaw_max);
    j.end_object();
    j.end_object();
  }
  j.end_array();
  if (const LolaServeReport* l = timing.lola) {
    j.key("lola").begin_object();
    j.field("socket", l->socket).field("robot", l->robot);
    j.field("pacing", std::string(enum_name(l->pacing)));
    j.field("period", l->period).field("frames", static_cast<long long>(l->frames));
    j.field("exchanged", static_cast<long long>(l->exchanged));
    j.field("missed", static_cast<long long>(l->missed));
    j.field("bad_packets", static_cast<long long>(l->bad_packets));
    j.field("late_answers", static_cast<long long>(l->late_answers));
    j.field("late_frames", static_cast<long long>(l->late_frames));
    j.field("without_client", static_cast<long long>(l->without_client));
    j.field("clients", l->clients).field("clients_lost", l->clients_lost);
    j.key("events").begin_array();
    for (const auto& e : l->events) j.value(e);
    j.end_array();
    j.end_object();
  }
  j.end_object();
  return j.str() + "\n";
}

std::string run_report_text(const Simulation& sim, const RunTiming& timing) {
  std::ostringstream o;
  o.setf(std::ios::fixed);
  o.precision(3);
  o << "scene " << sim.scene().name << "  seed " << sim.scene().physics.seed << "  solver "
    << solver_text(sim.scene().physics) << "  sim " << sim.time() << " s  wall " << timing.wall_time
    << " s  ";
  o.precision(1);
  o << (timing.wall_time > 0 ? sim.time() / timing.wall_time : 0.0) << "x real time  hash "
    << hash_hex(sim.state_hash()) << "\n";
  if (timing.interrupted)
    o << "  interrupted at " << sim.time() << " s of " << timing.requested_time
      << " s: the report covers what ran\n";
  for (int i = 0; i < sim.robot_count(); ++i) {
    const auto& r = sim.robot(i);
    const TorsoPose p = r.torso_pose();
    o.precision(4);
    o << "  " << r.name() << ": torso x " << p.x << " y " << p.y << " z " << p.z << " m  roll "
      << p.roll << " pitch " << p.pitch << " yaw " << p.yaw << " rad  "
      << (r.fallen() ? "FELL" : "upright") << "\n";
    const WalkMetricsResult w = sim.walk_metrics(i).result();
    if (w.steps > 0) o << "  walk: " << walk_metrics_text(w) << "\n";
    if (!r.calibration_errors().empty()) {
      o << "  calibration errors [deg]:";
      o.precision(2);
      for (const auto& [joint, error] : r.calibration_errors())
        o << " " << joint << " " << std::showpos << error * 180 / std::numbers::pi
          << std::noshowpos;
      o << "\n";
    }
  }
  if (timing.lola) o << "  " << lola_report_text(*timing.lola) << "\n";
  return o.str();
}

}  // namespace stride::sim
