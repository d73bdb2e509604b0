// The spring/damper <-> ERP/CFM mapping of a soft contact.
#include <gtest/gtest.h>

#include "simulator/scene/contact_softness.hpp"

namespace stride {
namespace {

TEST(ContactSoftness, DefaultErpCfmAreAStiffOverdampedSpring) {
  // The scene default (ERP 0.2, CFM 1e-4 at 1 ms): 2e6 N/m and 8000 N s/m per contact point.
  const sim::ContactSoftness d{0.2, 1e-4};
  EXPECT_NEAR(sim::contact_stiffness_of(d, 0.001), 2e6, 1e-6);
  EXPECT_NEAR(sim::contact_damping_of(d), 8000, 1e-9);
}

TEST(ContactSoftness, SpringAndDamperRoundTrip) {
  for (double h : {0.0005, 0.001, 0.002})
    for (double k : {1e3, 4e4, 2e6})
      for (double c : {0.0, 10.0, 8000.0}) {
        const sim::ContactSoftness s = sim::contact_softness(k, c, h);
        EXPECT_GT(s.erp, 0);
        EXPECT_LE(s.erp, 1);
        EXPECT_NEAR(sim::contact_stiffness_of(s, h), k, 1e-9 * k);
        EXPECT_NEAR(sim::contact_damping_of(s), c, 1e-9 * (k * h + c));
      }
  // No damper: ERP 1, CFM 1 / (h k).
  const sim::ContactSoftness undamped = sim::contact_softness(4e4, 0, 0.001);
  EXPECT_DOUBLE_EQ(undamped.erp, 1);
  EXPECT_DOUBLE_EQ(undamped.cfm, 1 / 40.0);
}

}  // namespace
}  // namespace stride
