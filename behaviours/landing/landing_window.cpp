#include "behaviours/landing/landing_window.hpp"

#include "behaviours/balance/modules/balance_actuation.hpp"

namespace stride::behaviours {

FootLanding advance_landing(const FootLanding& f, const LandingWindow& w, double now,
                            double planned_height, double load) {
  FootLanding n = f;
  n.planned_height = planned_height;
  const bool descending = planned_height < f.planned_height;
  auto enter = [&](LandingStage s) {
    n.stage = s;
    n.since = now;
  };
  switch (f.stage) {
    case LandingStage::idle:
    case LandingStage::returning:
      if (planned_height > w.lift_height) enter(LandingStage::swinging);
      break;
    case LandingStage::swinging:
      // A load counts only on the way down: the sole still carries some while it peels off.
      if (planned_height <= w.touch_height || (descending && load > w.contact_force))
        enter(LandingStage::landing);
      break;
    case LandingStage::landing:
      if (planned_height > w.lift_height)
        enter(LandingStage::swinging);
      else if (now - f.since >= w.hold_time)
        enter(LandingStage::returning);
      break;
  }
  if (n.stage == LandingStage::returning) {
    const double s = w.return_time > 0 ? (now - n.since) / w.return_time : 1;
    n.weight = 1 - smooth_ramp(s);
    if (s >= 1) n.stage = LandingStage::idle;
  }
  if (n.stage == LandingStage::landing) n.weight = 1;
  if (n.stage == LandingStage::idle || n.stage == LandingStage::swinging) n.weight = 0;
  return n;
}

}  // namespace stride::behaviours
