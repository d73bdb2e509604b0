#include "behaviours/balance/modules/balance_outlook.hpp"

#include "behaviours/balance/modules/balance_representations.hpp"
#include "behaviours/balance/strategy_classifier.hpp"

namespace stride::behaviours {
namespace {

class BalanceOutlook final : public Module {
 public:
  explicit BalanceOutlook(ModuleContext& c)
      : com_(c.require<ComState>()),
        model_(c.require<BalanceModel>()),
        params_(c.parameters<BalanceOutlookParameters>()),
        out_(c.provide<BalancePrediction>()) {}

  void update() override {
    out_ = BalancePrediction{};
    if (!com_.valid || !model_.valid) return;
    const balance::BalanceParams p =
        balance_params(model_, params_.tau_forward, params_.tau_backward);
    const balance::Classification c = balance::classify(p, {com_.x, com_.xdot});
    out_.valid = true;
    out_.capture_point = c.capture_point;
    out_.ankle_recovers = c.ankle_recovers;
    out_.hip_recovers = c.hip_recovers;
    out_.combined_recovers = c.combined_recovers;
    out_.strategy = static_cast<std::int32_t>(c.strategy);
    out_.omega = p.omega();
    out_.ankle_lo = c.ankle.lo, out_.ankle_hi = c.ankle.hi;
    out_.hip_lo = c.hip.lo, out_.hip_hi = c.hip.hi;
    out_.combined_lo = c.combined.lo, out_.combined_hi = c.combined.hi;
  }

 private:
  const ComState& com_;
  const BalanceModel& model_;
  const BalanceOutlookParameters& params_;
  BalancePrediction& out_;
};

}  // namespace

void register_balance_outlook(ModuleRegistry& registry) {
  registry.add<BalanceOutlook>("BalanceOutlook");
}

}  // namespace stride::behaviours
