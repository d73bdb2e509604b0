// A scene's own <contact> replaces the law of a scene it includes (the shipped scenes state the
// default law; a study that includes one states its own); two laws in one file, or in two included
// files, stay an error naming both places.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "robot/core/error.hpp"
#include "simulator/scene/scene_parser.hpp"

namespace stride {
namespace {

namespace fs = std::filesystem;

class ContactLawInclude : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ =
        fs::temp_directory_path() /
        ("stride_law_include_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
         "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
    write("shipped.xml",
          "<scene>\n<ground/>\n<contact stiffness=\"1e5\" damping=\"1000\" friction=\"0.8\"/>\n"
          "</scene>\n");
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
    return (dir_ / name).string();
  }
  std::string error_of(const std::string& path) {
    try {
      sim::parse_scene_file(path);
    } catch (const Error& e) {
      return e.what();
    }
    return "";
  }
  fs::path dir_;
};

TEST_F(ContactLawInclude, TheScenesOwnLawReplacesTheIncludedOne) {
  const auto s = sim::parse_scene_file(
      write("study.xml",
            "<scene>\n<include file=\"shipped.xml\"/>\n"
            "<contact stiffness=\"2e4\" damping=\"50\" per=\"point\" friction=\"0.5\" "
            "cone=\"pyramid\"/>\n</scene>\n"));
  ASSERT_TRUE(s.physics.contact_law);
  const auto& law = *s.physics.contact_law;
  EXPECT_DOUBLE_EQ(law.stiffness, 2e4);
  EXPECT_DOUBLE_EQ(law.damping, 50);
  EXPECT_FALSE(law.per_body);
  EXPECT_EQ(law.cone, sim::ContactLaw::Cone::Pyramid);
  EXPECT_EQ(law.line, 3);
  EXPECT_DOUBLE_EQ(s.ground.friction, 0.5);  // the unstated ground takes the law that holds
}

TEST_F(ContactLawInclude, TheIncludedLawHoldsWhenTheSceneStatesNone) {
  const auto s = sim::parse_scene_file(
      write("plain.xml", "<scene>\n<include file=\"shipped.xml\"/>\n</scene>"));
  ASSERT_TRUE(s.physics.contact_law);
  EXPECT_DOUBLE_EQ(s.physics.contact_law->stiffness, 1e5);
  EXPECT_DOUBLE_EQ(s.ground.friction, 0.8);
}

TEST_F(ContactLawInclude, TwoLawsInOneFileOrTwoIncludesAreAnError) {
  const std::string twice = write(
      "twice.xml", "<scene>\n<include file=\"shipped.xml\"/>\n<contact/>\n<contact/>\n</scene>");
  EXPECT_NE(error_of(twice).find("twice.xml:4: <contact>: given twice (first at "),
            std::string::npos)
      << error_of(twice);
  write("other.xml", "<scene>\n<contact stiffness=\"3e4\"/>\n</scene>\n");
  const std::string both =
      write("both.xml",
            "<scene>\n<include file=\"shipped.xml\"/>\n<include file=\"other.xml\"/>\n</scene>");
  EXPECT_NE(error_of(both).find("other.xml:2: <contact>: given twice (first at "),
            std::string::npos)
      << error_of(both);
  EXPECT_NE(error_of(both).find("shipped.xml:3"), std::string::npos) << error_of(both);
}

}  // namespace
}  // namespace stride
