#pragma once
// A scene file's elements with its <include>s expanded in place, in document order. The walk
// keeps its own stack of open files (no recursion: a chain of includes costs no call stack) and
// bounds what a scene may pull in: how deep includes nest, how many files and how many bytes in
// all. A limit broken, a cycle or an unreadable file is an error at the <include> that did it.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include <tinyxml2.h>

#include "robot/core/xml_element.hpp"

namespace stride::sim {

namespace include_limits {
inline constexpr std::size_t kMaxDepth = 64;             // includes inside includes
inline constexpr std::size_t kMaxFiles = 1000;           // <include>s followed in one scene
inline constexpr std::uint64_t kMaxBytes = 64ull << 20;  // text of every included file
}  // namespace include_limits

// `rel` as written in the file of `e`: a relative path is taken from that file's directory.
std::string resolve_from(const XmlElement& e, const std::string& rel);

class IncludeWalk {
 public:
  // `scene`: the <scene> root of every file (the root file's first); `element`: each child of a
  // root that is not an <include>.
  using Visit = std::function<void(const XmlElement&)>;
  IncludeWalk(Visit scene, Visit element)
      : scene_(std::move(scene)), element_(std::move(element)) {}

  void walk_file(const std::string& path);
  // `text` as if it were the file `path` (includes resolve from its directory).
  void walk_text(const std::string& text, const std::string& path);

 private:
  struct OpenFile {
    const tinyxml2::XMLElement* next;  // the next child of its root to visit
    std::string canonical;             // for cycle checks
    const std::string* file;
  };
  void open(const std::string& text, const std::string& path, const XmlElement* included_from);
  void include(const XmlElement& e);
  void walk();

  Visit scene_, element_;
  std::vector<OpenFile> stack_;
  std::set<std::string> open_files_;
  // Documents and names stay alive while errors and the scene description refer to them.
  std::vector<std::unique_ptr<tinyxml2::XMLDocument>> docs_;
  std::vector<std::unique_ptr<std::string>> paths_;
  std::size_t files_ = 0;
  std::uint64_t bytes_ = 0;
};

}  // namespace stride::sim
