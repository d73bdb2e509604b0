#include "robot/runtime/runtime.hpp"

#include <algorithm>
#include <chrono>
#include <utility>

#include "robot/core/error.hpp"
#include "robot/core/quote.hpp"
#include "robot/runtime/console_key.hpp"
#include "robot/runtime/finite_parameters.hpp"
#include "robot/runtime/nao_io_modules.hpp"
#include "robot/runtime/parameter_override.hpp"
#include "robot/runtime/recorded_config.hpp"
#include "robot/runtime/runtime_events.hpp"
#include "robot/runtime/world_pose.hpp"

namespace stride {

namespace {

const std::set<std::string> kBuiltIn = {"SensorFrame", "FrameInfo", "ModuleTimes", "CommandSafety"};

}  // namespace

struct Runtime::ModuleEntry {
  std::string name;
  std::set<std::string> owns;                  // representations it is the chosen provider of
  std::vector<std::unique_ptr<Slot>> scratch;  // outputs nobody reads (another module provides)
  std::unique_ptr<Module> module;              // last: destroyed before the slots it refers to
};

class Runtime::Context final : public ModuleContext {
 public:
  Context(Runtime& rt, const std::string& name, ModuleEntry* entry)
      : rt_(rt), name_(name), entry_(entry) {}

  DebugRequest debug_request(std::string_view name) override {
    return {&rt_.debug_, rt_.debug_request_index(name)};
  }
  const std::string& module_name() const override { return name_; }
  const model::RobotModel& robot_model() override {
    if (rt_.config_.model) return *rt_.config_.model;
    if (!entry_) return rt_.declaring_model_;
    throw Error("module '" + name_ +
                "' needs the robot's model (its URDF), and this runtime was given none");
  }

  ModuleDeclaration declaration;               // filled when entry_ is null (declaring only)
  std::vector<std::unique_ptr<Slot>> scratch;  // declaring only

 protected:
  Slot& bind(Use use, std::string_view name, std::type_index type, SlotFactory make) override {
    if (use == Use::Parameters) {
      auto& p = rt_.parameters_[name_];
      if (!p) p = make();
      if (p->type() != type)
        throw Error("module " + quote(name_) + " asks for two different parameter types");
      return *p;
    }
    if (!entry_) {
      (use == Use::Require ? declaration.requires_ : declaration.provides).emplace_back(name);
      scratch.push_back(make());
      return *scratch.back();
    }
    if (use == Use::Require || entry_->owns.count(std::string(name)))
      return rt_.blackboard_slot(name, type, make);
    entry_->scratch.push_back(make());
    return *entry_->scratch.back();
  }

 private:
  Runtime& rt_;
  std::string name_;
  ModuleEntry* entry_;
};

Runtime::Runtime(const ModuleRegistry& registry, RuntimeConfig config, hal::HardwareLink& link)
    : registry_(registry),
      config_(std::move(config)),
      link_(link),
      guard_(lola_joint_limits(config_.model.get())) {
  events_ = std::make_unique<RuntimeEvents>();
  sensor_ = &slot_value<hal::SensorFrame>(
      blackboard_slot("SensorFrame", typeid(hal::SensorFrame), &make_slot<hal::SensorFrame>));
  frame_info_ = &slot_value<FrameInfo>(
      blackboard_slot("FrameInfo", typeid(FrameInfo), &make_slot<FrameInfo>));
  times_ = &slot_value<ModuleTimes>(
      blackboard_slot("ModuleTimes", typeid(ModuleTimes), &make_slot<ModuleTimes>));
  safety_ = &slot_value<CommandSafety>(
      blackboard_slot("CommandSafety", typeid(CommandSafety), &make_slot<CommandSafety>));

  for (const auto& name : registry_.names()) {
    Context c(*this, name, nullptr);
    (*registry_.find(name))(c).reset();  // only the declarations are wanted
    c.declaration.name = name;
    declarations_.push_back(std::move(c.declaration));
  }

  std::map<std::string, std::string> updates;  // module -> "field=value ..."
  for (const auto& [key, value] : config_.parameters) {
    const ParameterOverride o{parse_parameter_key(key, "parameter"), value};
    if (!parameters_.count(o.key.module))
      throw Error("parameter " + quote(key) + ": no module " + quote(o.key.module) +
                  " with parameters");
    updates[o.key.module] += assignment_text(o) + " ";
  }
  for (const auto& [module, text] : updates) parameters_.at(module)->update(text, module);

  replan(config_.providers);
  actuator_ = &slot_value<hal::ActuatorFrame>(
      blackboard_slot("ActuatorFrame", typeid(hal::ActuatorFrame), &make_slot<hal::ActuatorFrame>));
}

Runtime::~Runtime() = default;

Slot& Runtime::blackboard_slot(std::string_view name, std::type_index type,
                               std::unique_ptr<Slot> (*make)()) {
  if (auto it = by_name_.find(name); it != by_name_.end()) {
    if (it->second->type() != type)
      throw Error("representation " + quote(name) + " is bound to two different C++ types");
    return *it->second;
  }
  slots_.push_back(make());
  by_name_.emplace(std::string(name), slots_.back().get());
  return *slots_.back();
}

const Slot& Runtime::typed_slot(std::string_view name, std::type_index type) const {
  const auto& s = representation_slot(std::string(name));
  if (s.type() != type) throw Error("representation " + quote(name) + " has another type");
  return s;
}

const Slot& Runtime::representation_slot(const std::string& name) const {
  auto it = by_name_.find(name);
  if (it == by_name_.end()) throw Error("no representation " + quote(name) + " on the blackboard");
  return *it->second;
}

const Slot& Runtime::parameter_slot_of(const std::string& module) const {
  auto it = parameters_.find(module);
  if (it == parameters_.end()) throw Error("no module " + quote(module) + " with parameters");
  return *it->second;
}

int Runtime::debug_request_index(std::string_view name) {
  auto& names = debug_.names;
  auto it = std::find(names.begin(), names.end(), name);
  if (it != names.end()) return static_cast<int>(it - names.begin());
  if (names.size() >= kMaxDebugRequests)
    throw Error("debug request " + quote(name) + ": more than " +
                std::to_string(kMaxDebugRequests) + " debug requests");
  names.emplace_back(name);
  return static_cast<int>(names.size()) - 1;
}

void Runtime::replan(const std::map<std::string, std::string>& chosen) {
  auto plan = plan_modules(declarations_, chosen, kBuiltIn, {"ActuatorFrame"});
  // Build what is new first, so a failing constructor leaves the running plan untouched.
  std::vector<std::unique_ptr<ModuleEntry>> next(plan.order.size());
  std::vector<std::size_t> reuse(plan.order.size(), modules_.size());
  for (std::size_t i = 0; i < plan.order.size(); ++i) {
    const auto& name = plan.order[i];
    std::set<std::string> owns;
    for (const auto& [rep, m] : plan.provider)
      if (m == name) owns.insert(rep);
    for (std::size_t k = 0; k < modules_.size(); ++k)
      if (modules_[k]->name == name && modules_[k]->owns == owns) reuse[i] = k;
    if (reuse[i] < modules_.size()) continue;
    next[i] = std::make_unique<ModuleEntry>();
    next[i]->name = name;
    next[i]->owns = std::move(owns);
    Context c(*this, name, next[i].get());
    next[i]->module = (*registry_.find(name))(c);
  }
  for (std::size_t i = 0; i < next.size(); ++i)
    if (!next[i]) next[i] = std::move(modules_[reuse[i]]);
  modules_ = std::move(next);
  plan_ = std::move(plan);
  chosen_ = chosen;
  order_ = plan_.order;
  ++plan_generation_;
  times_->modules = order_;
  times_->ns.assign(order_.size(), 0);
  // The fall line reads the IMU and its threshold where a controller has them.
  auto inertial = by_name_.find(Reflect<InertialSensorData>::type_name());
  inertial_ = inertial != by_name_.end() && inertial->second->type() == typeid(InertialSensorData)
                  ? &slot_value<InertialSensorData>(*inertial->second)
                  : nullptr;
  auto conversion = parameters_.find("SensorConversion");
  fall_params_ = conversion != parameters_.end() &&
                         conversion->second->type() == typeid(SensorConversionParameters)
                     ? &slot_value<SensorConversionParameters>(*conversion->second)
                     : nullptr;
}

void Runtime::say_events() {
  const double tilt = inertial_ ? imu_tilt(*inertial_) : -1;
  const double fall_tilt =
      fall_params_ ? fall_params_->fall_tilt : SensorConversionParameters{}.fall_tilt;
  events_->after_frame(frame_info_->time, tilt, fall_tilt, *safety_);
}

void Runtime::say(std::string line) {
  if (debug_.lines.size() < kMaxDebugLines)  // nobody taking them (a headless run) costs nothing
    debug_.lines.push_back(std::move(line));
  else
    ++debug_.dropped_lines;
}

bool Runtime::step() {
  const bool read = link_.read(*sensor_);
  const auto now = std::chrono::steady_clock::now().time_since_epoch();
  events_->link_lost(!read, std::chrono::duration<double>(now).count());
  if (!read) return false;
  frame_info_->time = sensor_->time;
  frame_info_->frame = frame_counter_++;
  frame_info_->period = link_.period();
  if (frame_info_->frame == 0) guard_.hold_measured(*sensor_);
  if (!overrides_.empty()) apply_overrides_of(kBuiltIn);
  if (run_modules()) {
    command_ = *actuator_;
    guard_.apply(command_, *safety_);
  } else {
    command_ = guard_.last_safe();
    ++safety_->held_frames;
  }
  say_events();
  link_.write(command_);
  if (log_) try {
      log_->write_frame();
    } catch (const Error& e) {
      log_.reset();  // the frames written so far stay readable; recording stops here
      if (config_.on_log_error == LogErrorPolicy::Propagate) throw;
      log_stopped_ = e.what();
    }
  if (boundary_) boundary_->after_frame(*this);
  return true;
}

bool Runtime::run_modules() {
  using Clock = std::chrono::steady_clock;
  auto before = Clock::now();
  for (std::size_t i = 0; i < modules_.size(); ++i) {
    if (config_.on_module_error == ModuleErrorPolicy::Propagate) {
      modules_[i]->module->update();
    } else {
      try {
        modules_[i]->module->update();
      } catch (const std::exception& e) {
        record_fault(modules_[i]->name, e.what());
        return false;
      } catch (...) {
        record_fault(modules_[i]->name, "an exception that is not a std::exception");
        return false;
      }
    }
    if (!overrides_.empty()) apply_overrides_of(modules_[i]->owns);
    const auto after = Clock::now();
    times_->ns[i] = std::chrono::duration_cast<std::chrono::nanoseconds>(after - before).count();
    before = after;
  }
  return true;
}

void Runtime::record_fault(const std::string& module, const char* what) {
  ++safety_->module_errors;
  for (auto& f : faults_)
    if (f.module == module) {
      ++f.count;
      return;
    }
  if (faults_.empty()) safety_->first_error = module + ": " + what;
  faults_.push_back({module, what, frame_info_->frame, 1});
  say(RuntimeEvents::fault_line(module, what));
}

std::string Runtime::provider_of(const std::string& representation) const {
  auto it = plan_.provider.find(representation);
  return it == plan_.provider.end() ? std::string() : it->second;
}

std::vector<std::string> Runtime::providers_available(const std::string& representation) const {
  std::vector<std::string> out;
  for (const auto& d : declarations_)
    if (std::find(d.provides.begin(), d.provides.end(), representation) != d.provides.end())
      out.push_back(d.name);
  return out;
}

void Runtime::swap_provider(const std::string& representation, const std::string& module) {
  check_provider_choice(representation, module);  // before anything changes
  auto chosen = chosen_;
  if (module == "default") {
    auto it = config_.providers.find(representation);
    if (it == config_.providers.end())
      chosen.erase(representation);
    else
      chosen[representation] = it->second;
  } else {
    chosen[representation] = module;
  }
  const std::string before = provider_of(representation);
  replan(chosen);
  if (overrides_.count(representation) && provider_of(representation) != before)
    say(RuntimeEvents::swapped_override_line(representation, before, provider_of(representation)));
}

void Runtime::check_provider_choice(const std::string& representation,
                                    const std::string& module) const {
  auto names = [](const std::vector<std::string>& list) {
    std::string out;
    for (const auto& n : list) out += (out.empty() ? "" : ", ") + n;
    return out;
  };
  const std::vector<std::string> providers = providers_available(representation);
  if (providers.empty()) {
    std::set<std::string> known;
    for (const auto& d : declarations_) known.insert(d.provides.begin(), d.provides.end());
    throw Error("mr: no module provides a representation " + quote(representation) +
                " (representations with providers: " +
                names(std::vector<std::string>(known.begin(), known.end())) + ")");
  }
  if (module != "default" &&
      std::find(providers.begin(), providers.end(), module) == providers.end())
    throw Error("mr: " + quote(module) + " does not provide " + quote(representation) +
                " (its providers: " + names(providers) + ")");
}

void Runtime::set_parameters(const std::string& module, std::string_view text) {
  auto it = parameters_.find(module);
  if (it == parameters_.end()) throw Error("no module " + quote(module) + " with parameters");
  Slot& slot = *it->second;
  Value v = slot.value();
  update_value(slot.desc(), v, text, module);
  refuse_nonfinite(slot.desc(), v, slot.fresh()->value(), module);  // all or nothing
  std::string bytes;
  ByteWriter w(bytes);
  write_value(slot.desc(), v, w);
  slot.decode(bytes);
}

std::string Runtime::get(std::string_view key) const {
  const auto k = split_console_key(key);
  if (k.representation) return representation_slot(k.name).text_at(k.path, k.name);
  auto it = parameters_.find(k.name);
  if (it == parameters_.end()) throw Error("no module " + quote(k.name) + " with parameters");
  return it->second->text_at(k.path, k.name);
}

void Runtime::set(std::string_view key, std::string_view text) {
  const auto k = split_console_key(key);
  const std::string update = k.path.empty() ? std::string(text) : k.path + "=" + std::string(text);
  if (!k.representation) return set_parameters(k.name, update);
  auto it = by_name_.find(k.name);
  if (it == by_name_.end())
    throw Error("no representation " + quote(k.name) + " on the blackboard");
  if (text == "unchanged") {
    if (!k.path.empty())
      throw Error("'unchanged' releases a whole representation: set representation:" + k.name +
                  " unchanged");
    if (!overrides_.erase(k.name)) throw Error("representation '" + k.name + "' is not overridden");
    return;
  }
  it->second->update(update, k.name, Numbers::Finite);  // all or nothing: a bad text holds nothing
  auto& held = overrides_[k.name];
  held += (held.empty() ? "" : " ") + update;
}

void Runtime::apply_override(const std::string& representation, const std::string& text) {
  try {
    by_name_.at(representation)->update(text, representation);
  } catch (const Error& e) {
    // A list field can shrink under an index the override names: release it and say so.
    debug_.lines.push_back("override of " + representation + " released: " + e.what());
    overrides_.erase(representation);
  }
}

void Runtime::apply_overrides_of(const std::set<std::string>& representations) {
  for (auto it = overrides_.begin(); it != overrides_.end();) {
    const auto next = std::next(it);
    if (representations.count(it->first)) apply_override(it->first, it->second);
    it = next;
  }
}

const TypeDesc& Runtime::type_of(std::string_view key) const {
  const auto k = split_console_key(key);
  const Slot* s = nullptr;
  if (k.representation)
    s = &representation_slot(k.name);
  else if (auto it = parameters_.find(k.name); it != parameters_.end())
    s = it->second.get();
  else
    throw Error("no module " + quote(k.name) + " with parameters");
  if (k.path.empty()) return s->desc();
  const auto v = s->value();
  return *value_at(s->desc(), v, k.path, k.name).first;
}

std::vector<std::string> Runtime::representation_names() const {
  std::vector<std::string> out;
  for (const auto& s : slots_) out.push_back(s->desc().name);
  return out;
}

std::vector<std::string> Runtime::parameter_modules() const {
  std::vector<std::string> out;
  for (const auto& [name, slot] : parameters_) out.push_back(name);
  return out;
}

const Slot* Runtime::parameters_of(std::string_view module) const {
  const auto it = parameters_.find(module);
  return it == parameters_.end() ? nullptr : it->second.get();
}

std::vector<std::pair<std::string, DebugSwitch>> Runtime::debug_requests() const {
  std::vector<std::pair<std::string, DebugSwitch>> out;
  for (std::size_t i = 0; i < debug_.names.size(); ++i)
    out.emplace_back(debug_.names[i], !debug_.bits.test(i)   ? DebugSwitch::Off
                                      : debug_.quiet.test(i) ? DebugSwitch::Quiet
                                                             : DebugSwitch::On);
  return out;
}

void Runtime::set_debug_request(const std::string& name, DebugSwitch state) {
  const auto& names = debug_.names;
  auto it = std::find(names.begin(), names.end(), name);
  if (it == names.end()) throw Error("no debug request " + quote(name) + " (dr ? lists them)");
  const auto i = static_cast<std::size_t>(it - names.begin());
  debug_.bits.set(i, state != DebugSwitch::Off);
  debug_.quiet.set(i, state == DebugSwitch::Quiet);
}

std::vector<std::string> Runtime::take_debug_lines() {
  std::vector<std::string> lines = std::move(debug_.lines);
  debug_.lines.clear();
  events_->take(lines);  // the frames' events, written now: a step never allocates for them
  if (debug_.dropped_lines > 0)
    lines.push_back("(" + std::to_string(debug_.dropped_lines) + " debug lines dropped)");
  debug_.dropped_lines = 0;
  return lines;
}

std::string Runtime::take_debug_stop() {
  return std::exchange(debug_.stop, std::string());
}

RuntimeConfig Runtime::running_config() const {
  RuntimeConfig c = config_;
  c.providers = plan_.provider;
  c.parameters.clear();
  for (const auto& [module, slot] : parameters_)
    for (const FieldDesc& f : slot->desc().fields)
      c.parameters[module + "." + f.name] = slot->text_at(f.name, module);
  return c;
}

void Runtime::start_log(const std::string& path, const LogMetadata& metadata) {
  log_ = open_log(path, metadata);
  log_stopped_.clear();
}

std::unique_ptr<LogWriter> Runtime::open_log(const std::string& path,
                                             const LogMetadata& metadata) const {
  std::vector<std::pair<std::string, const Slot*>> slots;
  for (const auto& s : slots_) slots.emplace_back(s->desc().name, s.get());
  slots.insert(slots.end(), log_also_.begin(), log_also_.end());
  // The log says what it ran with, so a replay after `mr` or `set module:` builds the same.
  LogMetadata all = config_metadata(running_config());
  for (const auto& [key, value] : metadata) all[key] = value;
  return std::make_unique<LogWriter>(path, std::move(slots), all);
}

std::size_t Runtime::logged_frames() const {
  return log_ ? log_->frames_written() : 0;
}

void Runtime::stop_log() {
  auto log = std::move(log_);
  if (log) log->close();
}

std::vector<std::string> Runtime::load_frame(const LogReader& log, std::size_t frame) {
  std::vector<std::string> skipped;
  std::vector<std::pair<Slot*, std::string_view>> loads;
  for (std::size_t i = 0; i < log.types().size(); ++i) {
    const auto& t = log.types()[i];
    if (t.name == SimulatedTorsoPose::kTypeName) continue;  // the world's, not the blackboard's
    auto it = by_name_.find(t.name);
    if (it == by_name_.end() || !same_type(it->second->desc(), *t.desc)) {
      skipped.push_back(t.name);
      continue;
    }
    const std::string_view bytes = log.bytes(frame, static_cast<int>(i));
    it->second->fresh()->decode(bytes);  // every one decodes before the blackboard changes
    loads.emplace_back(it->second, bytes);
  }
  for (const auto& [slot, bytes] : loads) slot->decode(bytes);
  return skipped;
}

}  // namespace stride
