// Provider choice and execution order: the topological sort and its exact error texts.
#include <gtest/gtest.h>

#include "robot/core/error.hpp"
#include "robot/framework/plan.hpp"

namespace stride {
namespace {

using Decls = std::vector<ModuleDeclaration>;

std::string plan_error(const Decls& d, const std::map<std::string, std::string>& chosen = {}) {
  try {
    plan_modules(d, chosen, {"Sensors"}, {"Out"});
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

TEST(Plan, OrdersEveryModuleAfterTheProvidersOfItsInputs) {
  const Decls d = {{"Sink", {"B", "C"}, {"Out"}},
                   {"MakeC", {"A", "B"}, {"C"}},
                   {"MakeB", {"A"}, {"B"}},
                   {"MakeA", {"Sensors"}, {"A"}},
                   {"Unused", {"A"}, {"D"}}};
  const auto plan = plan_modules(d, {}, {"Sensors"}, {"Out"});
  EXPECT_EQ(plan.order, (std::vector<std::string>{"MakeA", "MakeB", "MakeC", "Sink"}));
  EXPECT_EQ(plan.provider.at("C"), "MakeC");
  EXPECT_EQ(plan.provider.count("D"), 0u);
  EXPECT_EQ(plan.provider.count("Sensors"), 0u);
}

TEST(Plan, IndependentModulesAreOrderedByName) {
  const Decls d = {{"Sink", {"X", "Y"}, {"Out"}}, {"Zed", {}, {"X"}}, {"Alpha", {}, {"Y"}}};
  EXPECT_EQ(plan_modules(d, {}, {}, {"Out"}).order,
            (std::vector<std::string>{"Alpha", "Zed", "Sink"}));
}

TEST(Plan, ConfigurationChoosesAmongSeveralProviders) {
  const Decls d = {
      {"Sink", {"X"}, {"Out"}}, {"P1", {}, {"X"}}, {"P2", {"Y"}, {"X"}}, {"MakeY", {}, {"Y"}}};
  const auto plan = plan_modules(d, {{"X", "P2"}}, {}, {"Out"});
  EXPECT_EQ(plan.order, (std::vector<std::string>{"MakeY", "P2", "Sink"}));
}

TEST(Plan, MissingProviderNamesTheRepresentationAndWhoRequiresIt) {
  const Decls d = {{"A", {"X"}, {"Out"}}, {"B", {"X"}, {"Y"}}};
  EXPECT_EQ(plan_error(d, {{"Y", "B"}}), "no provider for representation 'X' (required by A, B)");
  EXPECT_EQ(plan_error({}), "no provider for representation 'Out' (required by the runtime)");
}

TEST(Plan, TwoProvidersWithoutAChoiceNameBoth) {
  const Decls d = {{"Sink", {"X"}, {"Out"}}, {"Q", {}, {"X"}}, {"P", {}, {"X"}}};
  EXPECT_EQ(plan_error(d),
            "representation 'X' has several providers (P, Q); choose one in the configuration");
}

TEST(Plan, BadChoicesAreNamed) {
  const Decls d = {{"Sink", {"X"}, {"Out"}}, {"P", {}, {"X"}}};
  EXPECT_EQ(plan_error(d, {{"X", "Nope"}}),
            "configuration chooses 'Nope' for representation 'X', but no module 'Nope' is "
            "registered");
  EXPECT_EQ(plan_error(d, {{"X", "Sink"}}),
            "configuration chooses 'Sink' for representation 'X', but 'Sink' does not provide it");
}

TEST(Plan, CycleNamesModulesAndRepresentations) {
  const Decls d = {{"A", {"Y"}, {"Out"}}, {"B", {"Z"}, {"Y"}}, {"C", {"Y"}, {"Z"}}};
  EXPECT_EQ(plan_error(d), "dependency cycle: B -[Y]-> C -[Z]-> B");
  const Decls self = {{"A", {"Out"}, {"Out"}}};
  EXPECT_EQ(plan_error(self), "dependency cycle: A -[Out]-> A");
}

}  // namespace
}  // namespace stride
