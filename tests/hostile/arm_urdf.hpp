#pragma once
// A small generic robot for the hostile-input tests: fast to load, and every number replaceable.
#include <string>

namespace stride::hostile {

// A two-link arm whose numbers the tests replace; line numbers in the comments are fixed.
struct Arm {
  std::string mass = "1";
  std::string inertia = R"(ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0")";
  std::string box = "0.1 0.1 0.1";
  std::string cylinder = R"(radius="0.02" length="0.3")";
  std::string origin = "0 0 0.1";
  std::string axis = "0 1 0";
  std::string extra;  // from line 18

  std::string text() const {
    return "<?xml version=\"1.0\"?>\n<robot name=\"r\">\n  <link name=\"base\">\n"  // 1-3
           "    <inertial><mass value=\"" +
           mass +
           "\"/><origin xyz=\"0 0 0\"/>\n"  // 4
           "      <inertia " +
           inertia +
           "/></inertial>\n"  // 5
           "    <collision><geometry><box size=\"" +
           box +
           "\"/></geometry></collision>\n"                         // 6
           "  </link>\n  <joint name=\"j1\" type=\"revolute\">\n"  // 7-8
           "    <parent link=\"base\"/><child link=\"arm\"/>\n"    // 9
           "    <origin xyz=\"" +
           origin + "\" rpy=\"0 0 0\"/><axis xyz=\"" + axis +
           "\"/>\n"                                                                // 10
           "    <limit lower=\"-1\" upper=\"1\" effort=\"10\" velocity=\"5\"/>\n"  // 11
           "  </joint>\n  <link name=\"arm\">\n"                                   // 12-13
           "    <inertial><mass value=\"0.5\"/><origin xyz=\"0 0 0.15\"/>\n"       // 14
           "      <inertia ixx=\"0.004\" iyy=\"0.004\" izz=\"0.0001\" ixy=\"0\" ixz=\"0\" "
           "iyz=\"0\"/></inertial>\n"  // 15
           "    <collision><origin xyz=\"0 0 0.15\"/><geometry><cylinder " +
           cylinder + "/></geometry></collision>\n  </link>\n" +  // 16-17
           extra + "</robot>\n";
  }
};

}  // namespace stride::hostile
