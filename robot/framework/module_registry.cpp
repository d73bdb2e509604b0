#include "robot/framework/module_registry.hpp"

namespace stride {

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

}  // namespace stride
