// Issue 49 point 3: no parameter of any module becomes NaN through `set`. Mid-walk, every field
// of every module is set to each legal extreme (a range's ends, every enumerator, true/false),
// one frame runs, and no parameter, joint request or walking request holds a NaN; `nan` itself
// is refused with one line naming the field, except where the default is NaN ("from the preset").
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "console/interpreter/interpreter.hpp"
#include "console/target/local_target.hpp"
#include "robot/core/error.hpp"

namespace stride::console {
namespace {

const std::string kWalk = STRIDE_SOURCE_DIR "/scenes/walking/open_loop_medium.xml";

struct Leaf {
  std::string path;
  const TypeDesc* type;
  std::optional<Range> range;
};

void leaves(const TypeDesc& d, const std::string& path, const std::optional<Range>& range,
            std::vector<Leaf>& out) {
  if (d.kind == Kind::Struct) {
    for (const FieldDesc& f : d.fields)
      leaves(*f.type, path + (path.empty() ? "" : ".") + f.name, f.range, out);
  } else if (d.kind == Kind::Array) {
    for (std::size_t i = 0; i < d.length; ++i)
      leaves(*d.element, path + "[" + std::to_string(i) + "]", range, out);
  } else if (d.kind != Kind::List && d.kind != Kind::String) {
    out.push_back({path, &d, range});
  }
}

std::string text(double x) {
  std::ostringstream s;
  s.precision(17);
  s << x;
  return s.str();
}

// The legal extremes of a leaf: a range's ends (unranged numbers: +-1e6), every enumerator.
std::vector<std::string> extremes(const Leaf& l) {
  if (l.type->kind == Kind::Bool) return {"true", "false"};
  if (l.type->kind == Kind::Enum) return l.type->enumerators;
  const double lo = l.range && std::isfinite(l.range->min) ? l.range->min : -1e6;
  const double hi = l.range && std::isfinite(l.range->max) ? l.range->max : 1e6;
  if (is_integer(l.type->kind)) return {text(std::max(lo, 0.0)), text(std::min(hi, 1e6))};
  return {text(lo), text(hi)};
}

// Every double in `text` (a printed value) that is NaN where `before` had a number.
std::vector<std::string> nan_words(const std::string& text) {
  std::vector<std::string> out;
  std::string word;
  for (char c : text + ",") {
    if (c == ',' || c == '{' || c == '}' || c == '[' || c == ']' || c == ' ') {
      if (word.ends_with("=nan") || word == "nan" || word.ends_with("inf")) out.push_back(word);
      word.clear();
    } else {
      word += c;
    }
  }
  return out;
}

class ParameterNanTest : public ::testing::Test {
 protected:
  void SetUp() override {
    target.load(kWalk);
    console.execute("run 3");  // mid-walk: the pattern starts after 2 s standing
    for (const std::string& m : target.parameter_modules())
      sentinels[m] = nan_words(target.get("module:" + m));
  }
  // NaN words now in any parameter set that were not there at the start, and NaN in requests.
  std::vector<std::string> new_nans() {
    std::vector<std::string> found;
    for (const std::string& m : target.parameter_modules())
      for (const std::string& w : nan_words(target.get("module:" + m)))
        if (std::find(sentinels[m].begin(), sentinels[m].end(), w) == sentinels[m].end())
          found.push_back(m + ": " + w);
    for (const char* rep : {"representation:JointRequest", "representation:WalkingJointRequest"})
      for (const std::string& w : nan_words(target.get(rep))) found.push_back(rep + (": " + w));
    return found;
  }

  LocalTarget target;
  std::ostringstream out;
  Interpreter console{target, out};
  std::map<std::string, std::vector<std::string>> sentinels;
};

TEST_F(ParameterNanTest, EveryFieldOfEveryModuleAtEachExtremeLeavesNoNan) {
  int sets = 0;
  for (const std::string& m : target.parameter_modules()) {
    std::vector<Leaf> all;
    leaves(target.type_of("module:" + m), "", std::nullopt, all);
    for (const Leaf& l : all) {
      const std::string key = "module:" + m + "." + l.path;
      const std::string saved = target.get(key);
      for (const std::string& v : extremes(l)) {
        try {
          console.execute("set module:" + m + " " + l.path + "=" + v);
          ++sets;
          console.execute("step 1");
        } catch (const Error& e) {  // refused or judged by the module: one line, nothing NaN
          EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
        }
        EXPECT_EQ(new_nans(), std::vector<std::string>{}) << key << "=" << v;
        console.execute("set module:" + m + " " + l.path + "=" + saved);
      }
    }
  }
  EXPECT_GT(sets, 100);
}

TEST_F(ParameterNanTest, NanIsRefusedNamingTheFieldUnlessTheDefaultIsNan) {
  int refused = 0;
  for (const std::string& m : target.parameter_modules()) {
    std::vector<Leaf> all;
    leaves(target.type_of("module:" + m), "", std::nullopt, all);
    for (const Leaf& l : all) {
      if (l.type->kind != Kind::Double && l.type->kind != Kind::Float) continue;
      const std::string key = "module:" + m + "." + l.path;
      const std::string before = target.get(key);
      for (const char* bad : {"nan", "inf", "-inf"}) {
        if (before == "nan" && std::string(bad) == "nan") continue;  // "from the preset"
        try {
          target.set("module:" + m, l.path + "=" + bad);
          ADD_FAILURE() << key << "=" << bad << " was accepted";
        } catch (const Error& e) {
          EXPECT_NE(std::string(e.what()).find(m + "." + l.path), std::string::npos) << e.what();
          ++refused;
        }
        EXPECT_EQ(target.get(key), before);
      }
    }
  }
  EXPECT_GT(refused, 100);
}

TEST_F(ParameterNanTest, FastPresetMidWalkLeavesEveryRequestFinite) {
  console.execute("set module:PatternWalk preset=fast");
  for (int i = 0; i < 100; ++i) {
    console.execute("run 0.02");
    ASSERT_EQ(new_nans(), std::vector<std::string>{}) << "at t=" << target.get("sim.time");
  }
  // A walk parameter given back to its preset ("nan" where the default is "nan") is allowed.
  console.execute("set module:PatternWalk T_stride=0.9");
  console.execute("set module:PatternWalk T_stride=nan");
  EXPECT_EQ(target.get("module:PatternWalk.T_stride"), "nan");
}

}  // namespace
}  // namespace stride::console
