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

}  // namespace stride
