// Sweep files: factors (values, ranges, levels with constants, templates), blocks, seeds, run
// length, records and tallies parse into the plan they say; every mistake is one line with
// file:line and what was expected.
#include <string>

#include <gtest/gtest.h>

#include "console/sweep/run_plan.hpp"
#include "console/sweep/sweep_parser.hpp"
#include "tests/error_text.hpp"

namespace stride::sweep {
namespace {

using test_support::error_of;

SweepSpec parse(const std::string& body) {
  return parse_sweep_text("<sweep name=\"t\">\n" + body + "\n</sweep>", "dir/t.sweep.xml");
}
std::string error(const std::string& body) {
  return error_of([&] { parse(body); });
}

TEST(SweepParser, GridOfFactorsWithSeedsInnermost) {
  const SweepSpec s = parse(R"(<scene file="a.xml"/>
<factor name="kp" target="HipStrategy.kp_pitch HipStrategy.kp_roll" values="0.1 0.2"/>
<factor name="rough" target="scene:uneven@height" range="0:4:2" format="{}mm"/>
<seeds from="3" to="4"/>
<run until="walk_end + 1s"/>)");
  EXPECT_EQ(s.scene_dir, "dir");
  EXPECT_EQ(s.until.mark, "walk_end");
  EXPECT_EQ(s.until.offset, 1.0);
  const Plan p = expand(s);
  EXPECT_EQ(p.columns, (std::vector<std::string>{"scene", "kp", "rough", "seed"}));
  ASSERT_EQ(p.runs.size(), 2u * 3u * 2u);
  EXPECT_EQ(p.runs[0].cells, (std::vector<std::string>{"a.xml", "0.1", "0", "3"}));
  EXPECT_EQ(p.runs[1].cells, (std::vector<std::string>{"a.xml", "0.1", "0", "4"}));
  EXPECT_EQ(p.runs[2].cells, (std::vector<std::string>{"a.xml", "0.1", "2", "3"}));
  EXPECT_EQ(p.runs[11].cells, (std::vector<std::string>{"a.xml", "0.2", "4", "4"}));
  const auto& set = p.runs[11].settings;  // scene, kp twice, height, seed
  ASSERT_EQ(set.size(), 5u);
  EXPECT_EQ(set[1].target, "HipStrategy.kp_pitch");
  EXPECT_EQ(set[2].value, "0.2");
  EXPECT_EQ(set[3].target, "scene:uneven@height");
  EXPECT_EQ(set[3].value, "4mm");
  EXPECT_EQ(set[4].value, "4");
  EXPECT_EQ(p.runs[11].id, 11);
}

TEST(SweepParser, LevelsCarryConstantsAndTemplatesComputeFromTheLevel) {
  const SweepSpec s = parse(R"(<factor name="case" target="scene" format="{}.xml">
  <level value="hip_slow" thesis="1.29"/>
  <level value="none_slow" thesis="nan"><set target="PatternWalk.steps" value="6"/></level>
</factor>
<factor name="v" values="0.3, 0.36">
  <set target="PatternWalk.V_min" value="{v - 0.005:g}"/>
  <set target="PatternWalk.V_max" value="{v + 0.005}"/>
  <column name="cm" value="{v * 100:.0f}"/>
</factor>
<run seconds="2s"/>)");
  const Plan p = expand(s);
  EXPECT_EQ(p.columns, (std::vector<std::string>{"scene", "case", "thesis", "v", "cm", "seed"}));
  ASSERT_EQ(p.runs.size(), 4u);
  EXPECT_EQ(p.runs[3].cells,
            (std::vector<std::string>{"none_slow.xml", "none_slow", "nan", "0.36", "36", "1"}));
  const auto& set = p.runs[3].settings;
  ASSERT_EQ(set.size(), 5u);
  EXPECT_EQ(set[0].value, "none_slow.xml");
  EXPECT_EQ(set[1].value, "6");
  EXPECT_EQ(set[2].value, "0.355");  // %g, as an ostream prints it
  EXPECT_EQ(set[3].value, "0.365");  // shortest exact text of 0.36 + 0.005
  EXPECT_EQ(s.until.offset, 2.0);
}

TEST(SweepParser, BlocksAreUnionedAndSamplesAreSeededAndStratified) {
  const SweepSpec s = parse(R"(<scene file="a.xml"/>
<grid><column name="sweep" value="kp"/><set target="M.kd" value="-0.05"/>
  <factor name="kp" target="M.kp" values="0 0.4"/></grid>
<sample method="lhs" count="10" seed="7">
  <range name="kd" target="M.kd" min="-0.2" max="0"/>
</sample>
<run seconds="1"/>)");
  const Plan p = expand(s);
  ASSERT_EQ(p.runs.size(), 12u);
  EXPECT_EQ(p.columns, (std::vector<std::string>{"scene", "sweep", "kp", "kd", "seed"}));
  EXPECT_EQ(p.runs[1].cells[1], "kp");
  EXPECT_EQ(p.runs[5].cells[1], "");  // the sample block has no such column
  std::vector<int> strata(10, 0);
  for (int i = 2; i < 12; ++i) {
    const double kd = std::stod(p.runs[i].cells[3]);
    ASSERT_GE(kd, -0.2);
    ASSERT_LT(kd, 0.0);
    ++strata[static_cast<int>((kd + 0.2) / 0.02)];
  }
  for (int n : strata) EXPECT_EQ(n, 1);                 // a Latin hypercube: each tenth once
  EXPECT_EQ(expand(s).runs[7].cells, p.runs[7].cells);  // the same draw every time
}

// Two factors of 2000 and 1000 levels are legal one by one, but their grid (2e6 runs) is refused
// before any point is built (two of 100000 levels would exhaust memory); the count is in the
// message.
TEST(SweepParser, ASeedsRangeIsOneDrawPerSeedTheSameForEveryLevel) {
  const SweepSpec s = parse(R"(<scene file="a.xml"/>
<factor name="N" target="scene:push@force" values="10 20"/>
<seeds count="3"><range name="at" target="scene:push@start" min="6" max="6.5" format="{}s"/></seeds>
<run seconds="2s"/>)");
  const Plan p = expand(s);
  EXPECT_EQ(p.columns, (std::vector<std::string>{"scene", "N", "seed", "at"}));
  ASSERT_EQ(p.runs.size(), 6u);
  std::vector<double> draws;
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(p.runs[k].cells[3], p.runs[k + 3].cells[3]) << "seed " << k + 1;  // N = 10, 20
    const double at = std::stod(p.runs[k].cells[3]);
    EXPECT_GE(at, 6.0);
    EXPECT_LT(at, 6.5);
    draws.push_back(at);
    const Setting& set = p.runs[k].settings.at(2);  // scene, N, the draw, seed
    EXPECT_EQ(set.target, "scene:push@start");
    EXPECT_EQ(set.value, p.runs[k].cells[3] + "s");
    EXPECT_EQ(p.runs[k].settings.at(3).target, "seed");
  }
  EXPECT_NE(draws[0], draws[1]);
  EXPECT_NE(draws[1], draws[2]);
  // Seed 1's draw is fixed by the seed alone: the same on every machine.
  EXPECT_EQ(p.runs[0].cells[3], "6.253390343518446");
  EXPECT_NE(error(R"(<seeds count="2"><factor name="x" values="1"/></seeds>)")
                .find("unknown element (expected range)"),
            std::string::npos);
}

TEST(SweepParser, AGridBeyondAMillionRunsIsRefusedBeforeItIsBuilt) {
  const SweepSpec s = parse(R"(<scene file="a.xml"/>
<factor name="kp" target="HipStrategy.kp_pitch" range="0:1999:1"/>
<factor name="kd" target="HipStrategy.kd_pitch" range="0:999:1"/>
<run seconds="1s"/>)");
  EXPECT_EQ(error_of([&] { expand(s); }),
            "sweep 't': 2e+06 runs (levels times seeds), more than the 1000000 a sweep may have");
  const SweepSpec seeded = parse(R"(<scene file="a.xml"/>
<factor name="kp" target="HipStrategy.kp_pitch" range="0:999:1"/>
<seeds from="1" to="1001"/>
<run seconds="1s"/>)");
  EXPECT_EQ(error_of([&] { expand(seeded); }),
            "sweep 't': 1.001e+06 runs (levels times seeds), more than the 1000000 a sweep may "
            "have");
  const SweepSpec small = parse(R"(<scene file="a.xml"/>
<factor name="kp" target="HipStrategy.kp_pitch" range="0:3:1"/>
<seeds from="1" to="3"/>
<run seconds="1s"/>)");
  EXPECT_EQ(expand(small, 12).runs.size(), 12u);
  EXPECT_EQ(error_of([&] { expand(small, 11); }),
            "sweep 't': 12 runs (levels times seeds), more than the 11 a sweep may have");
}

TEST(SweepParser, RecordAndTallies) {
  const SweepSpec s = parse(R"(<scene file="a.xml"/><run until="walk_end+1s"/>
<record>
  <value name="steps" key="walk.steps" at="walk_end+50ms"/>
  <summary name="sway" key="frame.true_pitch" stat="sd" from="walk_start" through="walk_end"
           until="abs(frame.true_pitch) > 0.4"/>
  <summary name="w" key="frame.knee_current_l" stat="sum" from="walk_start" to="walk_end"/>
  <derived name="speed" value="sway / 2"/>
</record>
<tally name="by" by="scene" where="steps > 0" title="T">
  <count name="n"/><mean name="m" of="speed" sd="true" decimals="3"/><text name="x" value="{n}"/>
</tally>)");
  ASSERT_EQ(s.record.summaries.size(), 2u);
  EXPECT_TRUE(s.record.summaries[0].to_inclusive);
  EXPECT_FALSE(s.record.summaries[1].to_inclusive);
  EXPECT_EQ(s.record.values[0].at.offset, 0.05);
  EXPECT_EQ(s.record.summaries[0].until, "abs(frame.true_pitch) > 0.4");
  ASSERT_EQ(s.tallies.size(), 1u);
  EXPECT_TRUE(s.tallies[0].columns[1].with_sd);
  EXPECT_EQ(s.tallies[0].columns[1].decimals, 3);
  EXPECT_EQ(s.tallies[0].by, (std::vector<std::string>{"scene"}));
}

TEST(SweepParser, PlotAxesNameTheirUnits) {
  const std::string tally = "<run seconds=\"1\"/><tally name=\"t\"><count name=\"n\"/></tally>\n";
  const SweepSpec s = parse(tally +
                            "<plot tally=\"t\" x=\"kd\" y=\"n\" x_label=\"K_d [s]\" "
                            "y_label=\"walks [-]\"/>");
  ASSERT_EQ(s.plots.size(), 1u);
  EXPECT_EQ(s.plots[0].x_label, "K_d [s]");
  EXPECT_EQ(error(tally + "<plot tally=\"t\" x=\"kd\" y=\"n\" y_label=\"walks [-]\"/>"),
            "dir/t.sweep.xml:3: <plot>: attribute 'x_label': expected the x axis' unit in [], e.g. "
            "'K_p [-]'");
  EXPECT_EQ(error(tally + "<plot tally=\"t\" x=\"kd [s]\" y=\"n\" y_label=\"walks\"/>"),
            "dir/t.sweep.xml:3: <plot>: attribute 'y_label': expected the y axis' unit in [], e.g. "
            "'sway [rad]'");
}

TEST(SweepParser, MistakesAreOneLineWithFileAndLine) {
  EXPECT_EQ(error("<run seconds=\"1\"/>\n<factr name=\"x\"/>"),
            "dir/t.sweep.xml:3: <factr>: unknown element (expected set, scene, factor, grid, "
            "sample, seeds, run, record, tally or plot)");
  EXPECT_EQ(error("<run seconds=\"1\"/>\n<factor name=\"x\" target=\"M.a\" range=\"1:0:1\"/>"),
            "dir/t.sweep.xml:3: <factor>: attribute 'range': expected first:last:step with first "
            "<= last and step > 0, got '1:0:1'");
  EXPECT_EQ(error("<factor name=\"x\" target=\"M.a\" values=\"1\"/>"),
            "dir/t.sweep.xml:1: <sweep>: expected <run seconds=\"...\"/> or <run until=\"...\"/>");
  EXPECT_EQ(error("<run until=\"walk_middle\"/>"),
            "dir/t.sweep.xml:2: <run>: attribute 'until': unknown time mark in 'walk_middle' "
            "(start, end, walk_start, walk_end, or a time)");
  EXPECT_EQ(error("<run seconds=\"1\"/><record><summary name=\"a\" key=\"frame.t\" "
                  "stat=\"median\"/></record>"),
            "dir/t.sweep.xml:2: <summary>: attribute 'stat': expected min, max, mean, rms, sd, "
            "first, final, change, sum, integral, count or first_past, got 'median'");
  EXPECT_EQ(error("<run seconds=\"1\"/><factor name=\"v\" values=\"1\"><set target=\"M.a\" "
                  "value=\"{w + 1}\"/></factor>"),
            "dir/t.sweep.xml:2: <set>: expression 'w + 1': unknown name 'w' (a level's value is "
            "'v')");
  EXPECT_NE(error("<run seconds=\"1\">").find("dir/t.sweep.xml:"), std::string::npos);
}

}  // namespace
}  // namespace stride::sweep
