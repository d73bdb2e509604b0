#include "robot/framework/module_registry.hpp"

#include <sstream>

#include "robot/model/robot_model.hpp"

namespace stride {

namespace {

// Binds like the Runtime's declaring pass, keeping only the parameter structs.
class ParameterContext final : public ModuleContext {
 public:
  explicit ParameterContext(std::string name) : name_(std::move(name)) {}
  DebugRequest debug_request(std::string_view) override { return {&debug_, 0}; }
  const std::string& module_name() const override { return name_; }
  const model::RobotModel& robot_model() override { return empty_robot_model(); }
  std::unique_ptr<Slot> parameters;

 protected:
  Slot& bind(Use use, std::string_view, std::type_index, SlotFactory make) override {
    if (use == Use::Parameters) {
      if (!parameters) parameters = make();
      return *parameters;
    }
    scratch_.push_back(make());
    return *scratch_.back();
  }

 private:
  std::string name_;
  DebugChannel debug_{.names = {""}};
  std::vector<std::unique_ptr<Slot>> scratch_;
};

}  // namespace

const model::RobotModel& empty_robot_model() {
  static const model::RobotModel none;
  return none;
}

void ModuleRegistry::add(const std::string& name, ModuleFactory factory) {
  if (!factories_.emplace(name, factory).second)
    throw Error("module '" + name + "' is registered twice");
}

const ModuleFactory* ModuleRegistry::find(const std::string& name) const {
  auto it = factories_.find(name);
  return it == factories_.end() ? nullptr : &it->second;
}

std::vector<std::string> ModuleRegistry::names() const {
  std::vector<std::string> out;
  for (const auto& [name, f] : factories_) out.push_back(name);
  return out;
}

std::map<std::string, std::unique_ptr<Slot>> default_parameters(const ModuleRegistry& registry) {
  std::map<std::string, std::unique_ptr<Slot>> out;
  for (const auto& name : registry.names()) {
    ParameterContext c(name);
    (*registry.find(name))(c).reset();  // only the bindings are wanted
    if (c.parameters) out.emplace(name, std::move(c.parameters));
  }
  return out;
}

std::vector<std::string> parameter_lines(const ModuleRegistry& registry) {
  std::vector<std::string> lines;
  for (const auto& [module, slot] : default_parameters(registry)) {
    const TypeDesc& d = slot->desc();
    for (const FieldDesc& f : d.fields) {
      std::ostringstream line;
      line << module << "." << f.name << " = " << slot->text_at(f.name, module);
      if (!f.unit.empty()) line << " [" << f.unit << "]";
      if (f.range) line << " in [" << f.range->min << ", " << f.range->max << "]";
      if (f.type->kind != Kind::Double) line << " (" << type_label(*f.type) << ")";
      lines.push_back(line.str());
    }
  }
  return lines;
}

}  // namespace stride
