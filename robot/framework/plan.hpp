#pragma once
// Choosing providers and ordering modules: a pure function of the declarations and the choices.
#include <map>
#include <set>
#include <string>
#include <vector>

namespace stride {

struct ModuleDeclaration {
  std::string name;
  std::vector<std::string> requires_;
  std::vector<std::string> provides;
};

struct ModulePlan {
  std::vector<std::string> order;               // modules to run, each after its inputs' providers
  std::map<std::string, std::string> provider;  // representation -> module
};

// Every representation in `roots` and in `chosen` gets a provider, then every requirement of a
// chosen provider, transitively; `built_in` representations are written by the runtime itself.
// `chosen` maps representation -> module; otherwise the only module providing it is used.
// A running module's other outputs are also assigned to it when no other running module makes
// them (otherwise they stay private to each module and off the blackboard).
// Errors (exact text, tested):
//   no provider for representation 'X' (required by A, B)
//   representation 'X' has several providers (A, B); choose one in the configuration
//   configuration chooses 'M' for representation 'X', but no module 'M' is registered
//   configuration chooses 'M' for representation 'X', but 'M' does not provide it
//   dependency cycle: A -[X]-> B -[Y]-> A   (A provides X, which B requires, ...)
ModulePlan plan_modules(const std::vector<ModuleDeclaration>& modules,
                        const std::map<std::string, std::string>& chosen,
                        const std::set<std::string>& built_in,
                        const std::vector<std::string>& roots);

}  // namespace stride
