#pragma once
// Modules by name. A registry is a plain value that the program fills explicitly (e.g.
// register_stand(registry)), so there is no hidden global state and no linker surprise.
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "robot/framework/module.hpp"

namespace stride {

using ModuleFactory = std::unique_ptr<Module> (*)(ModuleContext&);

class ModuleRegistry {
 public:
  template <class M>
  void add(const std::string& name) {
    add(name, [](ModuleContext& c) -> std::unique_ptr<Module> { return std::make_unique<M>(c); });
  }
  void add(const std::string& name, ModuleFactory factory);  // throws on a duplicate name
  const ModuleFactory* find(const std::string& name) const;
  std::vector<std::string> names() const;  // sorted

 private:
  std::map<std::string, ModuleFactory> factories_;
};

// The model a ModuleContext hands out while modules are only being declared: no links, no joints.
const model::RobotModel& empty_robot_model();

// Every registered module's parameter struct at its defaults (module -> slot), learned by
// constructing each module once as the Runtime does; modules without parameters are left out.
std::map<std::string, std::unique_ptr<Slot>> default_parameters(const ModuleRegistry& registry);

// One line per parameter field: "Module.field = default [unit] in [min, max]", for `--set ?`.
std::vector<std::string> parameter_lines(const ModuleRegistry& registry);

}  // namespace stride
