#pragma once
// The Ch. 7 strategies by name, the module that acts each out, and which capture region of
// balance::classify each relies on: one list for every command and study that picks a strategy.
#include <array>
#include <optional>
#include <string_view>

#include "behaviours/balance/strategy_classifier.hpp"

namespace stride::behaviours {

struct BalanceStrategyModule {
  std::string_view strategy, module;
};

inline constexpr std::array<BalanceStrategyModule, 4> kBalanceStrategyModules{{
    {"ankle", "AnkleBalance"},
    {"hip", "HipBalance"},
    {"combined", "CombinedBalance"},
    {"lqr", "LqrBalance"},
}};

// The module of a strategy named in kBalanceStrategyModules; nullopt for any other name.
inline std::optional<std::string_view> balance_module_of(std::string_view strategy) {
  for (const BalanceStrategyModule& s : kBalanceStrategyModules)
    if (s.strategy == strategy) return s.module;
  return std::nullopt;
}

// Whether the strategy's region holds the classified state; combined and LQR use ankle and hip
// together.
inline bool strategy_recovers(std::string_view strategy, const balance::Classification& c) {
  if (strategy == "ankle") return c.ankle_recovers;
  if (strategy == "hip") return c.hip_recovers;
  return c.combined_recovers;
}

}  // namespace stride::behaviours
