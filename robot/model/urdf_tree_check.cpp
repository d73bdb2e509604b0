#include "robot/model/urdf_tree_check.hpp"

#include <map>

#include "robot/core/error.hpp"
#include "robot/core/physical_limits.hpp"

namespace stride::model {
namespace {

using Links = std::vector<UrdfLinkRecord>;
using Joints = std::vector<UrdfJointRecord>;

std::string quoted(const std::string& s) {
  return "'" + s + "'";
}

// Name -> index; a second definition is an error naming both lines.
template <class Record>
std::map<std::string, int> index_names(const std::vector<Record>& records, const char* what,
                                       const std::string& source) {
  std::map<std::string, int> index;
  for (std::size_t i = 0; i < records.size(); ++i) {
    const auto [it, fresh] = index.emplace(records[i].name, static_cast<int>(i));
    if (!fresh)
      throw error_at(source, records[i].line,
                     std::string(what) + " " + quoted(records[i].name) + " defined twice (lines " +
                         std::to_string(records[it->second].line) + " and " +
                         std::to_string(records[i].line) + ")");
  }
  return index;
}

// parent_joint[link] = the joint whose child it is, or -1.
std::vector<int> parent_joints(const Links& links, const Joints& joints,
                               const std::map<std::string, int>& link_index,
                               const std::string& source) {
  std::vector<int> parent(links.size(), -1);
  for (std::size_t j = 0; j < joints.size(); ++j) {
    const UrdfJointRecord& jt = joints[j];
    const std::string what = "joint " + quoted(jt.name) + ": ";
    for (const std::string* end : {&jt.parent, &jt.child})
      if (!link_index.count(*end))
        throw error_at(source, jt.line,
                       what + (end == &jt.parent ? "parent" : "child") + " link " + quoted(*end) +
                           " is not defined");
    if (jt.parent == jt.child)
      throw error_at(source, jt.line, what + "connects link " + quoted(jt.child) + " to itself");
    int& p = parent[link_index.at(jt.child)];
    if (p >= 0)
      throw error_at(source, jt.line,
                     "link " + quoted(jt.child) + " has two parents: joint " +
                         quoted(joints[p].name) + " (line " + std::to_string(joints[p].line) +
                         ") and joint " + quoted(jt.name) + " (line " + std::to_string(jt.line) +
                         ")");
    p = static_cast<int>(j);
  }
  return parent;
}

// Every link must reach the root by its parents; a walk that meets itself is a cycle.
void check_no_cycles(const Links& links, const Joints& joints,
                     const std::map<std::string, int>& link_index, const std::vector<int>& parent,
                     const std::string& source) {
  enum : char { kUnseen, kOnPath, kDone };
  std::vector<char> state(links.size(), kUnseen);
  std::vector<int> path;
  for (std::size_t start = 0; start < links.size(); ++start) {
    path.clear();
    int l = static_cast<int>(start);
    while (l >= 0 && state[l] == kUnseen) {
      state[l] = kOnPath;
      path.push_back(l);
      l = parent[l] >= 0 ? link_index.at(joints[parent[l]].parent) : -1;
    }
    if (l >= 0 && state[l] == kOnPath) {
      std::string cycle;
      int closing = parent[l];
      for (int k = l;;) {
        cycle += quoted(links[k].name) + " <- ";
        k = link_index.at(joints[parent[k]].parent);
        if (k == l) break;
      }
      throw error_at(source, joints[closing].line,
                     "joint cycle: link " + cycle + quoted(links[l].name) +
                         " (expected a tree: each link reached from the root by one path)");
    }
    for (int k : path) state[k] = kDone;
  }
}

void check_root(const Links& links, const std::vector<int>& parent, const std::string& source) {
  int root = -1;
  for (std::size_t l = 0; l < links.size(); ++l) {
    if (parent[l] >= 0) continue;
    if (root >= 0)
      throw error_at(source, links[l].line,
                     "links " + quoted(links[root].name) + " and " + quoted(links[l].name) +
                         " both have no parent joint (expected one root link)");
    root = static_cast<int>(l);
  }
}

void check_mimics(const Joints& joints, const std::map<std::string, int>& joint_index,
                  const std::string& source) {
  for (const UrdfJointRecord& jt : joints) {
    if (jt.mimic.empty()) continue;
    const std::string what = "joint " + quoted(jt.name) + ": ";
    if (jt.type == "fixed") throw error_at(source, jt.line, what + "a fixed joint cannot mimic");
    if (jt.mimic == jt.name)
      throw error_at(source, jt.line, what + "mimics itself (expected another joint)");
    const auto it = joint_index.find(jt.mimic);
    if (it == joint_index.end())
      throw error_at(source, jt.line, what + "mimics unknown joint " + quoted(jt.mimic));
    const UrdfJointRecord& master = joints[it->second];
    if (master.type == "fixed")
      throw error_at(
          source, jt.line,
          what + "mimics fixed joint " + quoted(master.name) + " (expected a movable joint)");
    if (!master.mimic.empty())
      throw error_at(source, jt.line,
                     what + "mimics " + quoted(master.name) + ", which itself mimics " +
                         quoted(master.mimic) + " (expected a joint that mimics none)");
  }
}

}  // namespace

void check_urdf_tree(const Links& links, const Joints& joints, const std::string& source) {
  if (links.empty()) throw error_at(source, 1, "robot without links (expected at least one)");
  if (links.size() > static_cast<std::size_t>(limits::kMaxLinks))
    throw error_at(source, links[limits::kMaxLinks].line,
                   "robot with " + std::to_string(links.size()) + " links (at most " +
                       std::to_string(limits::kMaxLinks) + ")");  // for callers without XML
  const auto link_index = index_names(links, "link", source);
  const auto joint_index = index_names(joints, "joint", source);
  const std::vector<int> parent = parent_joints(links, joints, link_index, source);
  check_no_cycles(links, joints, link_index, parent, source);
  check_root(links, parent, source);
  check_mimics(joints, joint_index, source);
}

}  // namespace stride::model
