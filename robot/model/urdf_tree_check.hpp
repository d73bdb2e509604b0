#pragma once
// The structure of a URDF as links and joints named in the file: one tree (one root, every other
// link the child of exactly one joint, no cycles), unique names, at most limits::kMaxLinks links,
// and mimic joints that copy a movable joint which itself copies none. Iterative throughout, so a
// deep chain cannot overflow the stack.
#include <string>
#include <vector>

namespace stride::model {

struct UrdfLinkRecord {
  std::string name;
  int line = 0;
};

struct UrdfJointRecord {
  std::string name, type, parent, child;
  std::string mimic;  // joint it copies, "" if none
  int line = 0;
};

// Throws stride::Error("source:line: ...") at the first problem, naming the links and joints.
void check_urdf_tree(const std::vector<UrdfLinkRecord>& links,
                     const std::vector<UrdfJointRecord>& joints, const std::string& source);

}  // namespace stride::model
