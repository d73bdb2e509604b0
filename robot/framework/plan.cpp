#include "robot/framework/plan.hpp"

#include <algorithm>
#include <deque>

#include "robot/core/error.hpp"

namespace stride {

namespace {

std::string join(const std::vector<std::string>& items) {
  std::string s;
  for (const auto& i : items) s += (s.empty() ? "" : ", ") + i;
  return s;
}

bool contains(const std::vector<std::string>& v, const std::string& x) {
  return std::find(v.begin(), v.end(), x) != v.end();
}

// The module that provides `rep`: the configuration's choice, else its only provider.
std::string provider_for(const std::string& rep, const std::vector<ModuleDeclaration>& modules,
                         const std::map<std::string, std::string>& chosen,
                         const std::map<std::string, const ModuleDeclaration*>& by_name,
                         std::map<std::string, std::vector<std::string>>& required_by) {
  if (auto it = chosen.find(rep); it != chosen.end()) {
    auto m = by_name.find(it->second);
    if (m == by_name.end())
      throw Error("configuration chooses '" + it->second + "' for representation '" + rep +
                  "', but no module '" + it->second + "' is registered");
    if (!contains(m->second->provides, rep))
      throw Error("configuration chooses '" + it->second + "' for representation '" + rep +
                  "', but '" + it->second + "' does not provide it");
    return it->second;
  } else {
    std::vector<std::string> candidates;
    for (const auto& m : modules)
      if (contains(m.provides, rep)) candidates.push_back(m.name);
    std::sort(candidates.begin(), candidates.end());
    if (candidates.empty()) {
      auto users = required_by[rep];
      std::sort(users.begin(), users.end());
      throw Error("no provider for representation '" + rep + "' (required by " +
                  (users.empty() ? std::string("the runtime") : join(users)) + ")");
    }
    if (candidates.size() > 1)
      throw Error("representation '" + rep + "' has several providers (" + join(candidates) +
                  "); choose one in the configuration");
    return candidates.front();
  }
}

// Modules left over by the sort lie on a cycle or behind one; names one cycle, provider first.
[[noreturn]] void throw_cycle(const ModulePlan& plan,
                              const std::map<std::string, const ModuleDeclaration*>& by_name,
                              const std::map<std::string, int>& in_degree) {
  // Walk back from a module left over: every one of them has a predecessor that is left over too.
  auto left = [&](const std::string& m) {
    const auto it = in_degree.find(m);
    return it != in_degree.end() && it->second > 0;
  };
  std::string start;
  for (const auto& [m, d] : in_degree)
    if (d > 0) {
      start = m;
      break;
    }
  std::vector<std::string> path;  // modules, each requiring what the next one provides
  std::vector<std::string> via;   // via[i]: representation path[i+1] provides to path[i]
  std::map<std::string, std::size_t> seen;
  std::string m = start;
  while (!seen.count(m)) {
    seen[m] = path.size();
    path.push_back(m);
    for (const auto& need : by_name.at(m)->requires_) {
      auto p = plan.provider.find(need);
      if (p != plan.provider.end() && left(p->second)) {
        via.push_back(need);
        m = p->second;
        break;
      }
    }
  }
  // The cycle is path[seen[m]..] read backwards: provider first.
  std::string text = m;
  for (std::size_t i = path.size(); i-- > seen[m];) text += " -[" + via[i] + "]-> " + path[i];
  throw Error("dependency cycle: " + text);
}

}  // namespace

ModulePlan plan_modules(const std::vector<ModuleDeclaration>& modules,
                        const std::map<std::string, std::string>& chosen,
                        const std::set<std::string>& built_in,
                        const std::vector<std::string>& roots) {
  std::map<std::string, const ModuleDeclaration*> by_name;
  for (const auto& m : modules) by_name[m.name] = &m;

  ModulePlan plan;
  std::map<std::string, std::vector<std::string>> required_by;  // rep -> modules needing it
  std::deque<std::string> pending;
  for (const auto& r : roots) pending.push_back(r);
  for (const auto& [rep, module] : chosen) pending.push_back(rep);

  std::set<std::string> selected;
  while (!pending.empty()) {
    const auto rep = pending.front();
    pending.pop_front();
    if (built_in.count(rep) || plan.provider.count(rep)) continue;
    const std::string module = provider_for(rep, modules, chosen, by_name, required_by);
    plan.provider[rep] = module;
    if (selected.insert(module).second) {
      for (const auto& need : by_name[module]->requires_) {
        required_by[need].push_back(module);
        pending.push_back(need);
      }
    }
  }

  // Outputs nobody asked for go to the blackboard too when exactly one running module makes them.
  std::map<std::string, std::vector<std::string>> extra;
  for (const auto& m : selected)
    for (const auto& rep : by_name[m]->provides)
      if (!plan.provider.count(rep) && !built_in.count(rep)) extra[rep].push_back(m);
  for (const auto& [rep, makers] : extra)
    if (makers.size() == 1) plan.provider[rep] = makers.front();

  // Kahn's algorithm; ties broken by name so the order is reproducible.
  std::map<std::string, std::set<std::string>> after;  // module -> modules that need its output
  std::map<std::string, int> in_degree;
  for (const auto& m : selected) in_degree[m] = 0;
  for (const auto& m : selected)
    for (const auto& need : by_name[m]->requires_)
      if (auto p = plan.provider.find(need); p != plan.provider.end())
        if (after[p->second].insert(m).second) ++in_degree[m];
  std::set<std::string> ready;
  for (const auto& [m, d] : in_degree)
    if (d == 0) ready.insert(m);
  while (!ready.empty()) {
    const auto m = *ready.begin();
    ready.erase(ready.begin());
    plan.order.push_back(m);
    for (const auto& next : after[m])
      if (--in_degree[next] == 0) ready.insert(next);
  }
  if (plan.order.size() == selected.size()) return plan;

  throw_cycle(plan, by_name, in_degree);
}

}  // namespace stride
