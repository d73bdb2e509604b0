// Every run report names the solver setting its figures come from.
#include <gtest/gtest.h>

#include "simulator/report/run_report.hpp"
#include "tests/simulator/sim_test_util.hpp"

namespace stride {
namespace {

std::string report_of(const std::string& physics) {
  auto sim = test::scene_from_text("<scene>" + physics + "<ground/></scene>");
  return sim::run_report_json(*sim, {}) + sim::run_report_text(*sim, {});
}

TEST(RunReportSolver, NamesTheSolverSetting) {
  const std::string by_default = report_of("<physics/>");
  EXPECT_NE(by_default.find("\"solver\":\"iterative 10\""), std::string::npos) << by_default;
  EXPECT_NE(by_default.find("  solver iterative 10  "), std::string::npos) << by_default;
  const std::string pinned = report_of(R"(<physics iterations="20" sor="1.5"/>)");
  EXPECT_NE(pinned.find("\"solver\":\"iterative 20 sor 1.5\""), std::string::npos) << pinned;
  const std::string exact = report_of(R"(<physics solver="exact"/>)");
  EXPECT_NE(exact.find("\"solver\":\"exact\""), std::string::npos) << exact;
  EXPECT_NE(exact.find("\"engine\":\"ode\",\"step\":0.001,\"contact\":\"engine's own\""),
            std::string::npos)
      << exact;
}

TEST(RunReportSolver, NamesTheContactLaw) {
  const std::string law = report_of(
      R"(<physics solver="exact" step="0.5ms"/><contact stiffness="1e5" damping="1000"/>)");
  EXPECT_NE(law.find("\"step\":5e-04,\"contact\":\"law k 100000 N/m c 1000 N s/m per body mu "
                     "0.8 elliptic\""),
            std::string::npos)
      << law;
}

}  // namespace
}  // namespace stride
