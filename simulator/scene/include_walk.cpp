#include "simulator/scene/include_walk.hpp"

#include <filesystem>

#include "robot/core/error.hpp"
#include "robot/core/input_file.hpp"
#include "robot/core/xml_error.hpp"

namespace stride::sim {
namespace {

namespace fs = std::filesystem;

}  // namespace

std::string resolve_from(const XmlElement& e, const std::string& rel) {
  fs::path p(rel);
  if (p.is_relative()) p = fs::path(e.file()).parent_path() / p;
  return p.lexically_normal().string();
}

void IncludeWalk::walk_file(const std::string& path) {
  walk_text(read_input_file(path, kMaxTextInputBytes, "scene"), path);
}

void IncludeWalk::walk_text(const std::string& text, const std::string& path) {
  open(text, path, nullptr);
  walk();
}

void IncludeWalk::open(const std::string& text, const std::string& path,
                       const XmlElement* included_from) {
  std::error_code ec;  // a name the system cannot resolve (too long) stands for itself
  const fs::path resolved = fs::weakly_canonical(fs::path(path), ec);
  const std::string canonical = ec ? path : resolved.string();
  if (open_files_.count(canonical)) included_from->fail("include cycle through '" + path + "'");
  docs_.push_back(std::make_unique<tinyxml2::XMLDocument>());
  paths_.push_back(std::make_unique<std::string>(path));
  tinyxml2::XMLDocument& doc = *docs_.back();
  const std::string& file = *paths_.back();
  if (doc.Parse(text.c_str(), text.size()) != tinyxml2::XML_SUCCESS)
    throw error_at(file, doc.ErrorLineNum(), xml_error_text(doc));
  const tinyxml2::XMLElement* root = doc.RootElement();
  if (!root || std::string_view(root->Name()) != "scene")
    throw error_at(file, root ? root->GetLineNum() : 1, "expected <scene> as the root element");
  scene_(XmlElement(root, file));
  open_files_.insert(canonical);
  stack_.push_back({root->FirstChildElement(), canonical, &file});
}

void IncludeWalk::include(const XmlElement& e) {
  e.allow_only({"file"});
  using namespace include_limits;
  if (stack_.size() > kMaxDepth)
    e.fail("includes nested " + std::to_string(stack_.size()) + " deep (at most " +
           std::to_string(kMaxDepth) + ")");
  if (++files_ > kMaxFiles)
    e.fail("the scene would include more than " + std::to_string(kMaxFiles) + " files (at most " +
           std::to_string(kMaxFiles) + " includes per scene)");
  const std::string path = resolve_from(e, e.text("file"));
  std::string text;
  try {  // a directory, device, FIFO or oversized file is refused before it is read
    text = read_input_file(path, kMaxTextInputBytes, "included file");
  } catch (const Error& err) {
    e.fail(err.what());
  }
  bytes_ += text.size();
  if (bytes_ > kMaxBytes)
    e.fail("the scene's included files would hold " + std::to_string(bytes_) + " bytes (at most " +
           std::to_string(kMaxBytes) + " in all)");
  open(text, path, &e);
}

void IncludeWalk::walk() {
  while (!stack_.empty()) {
    OpenFile& top = stack_.back();
    if (!top.next) {
      open_files_.erase(top.canonical);
      stack_.pop_back();
      continue;
    }
    const XmlElement e(top.next, *top.file);
    top.next = top.next->NextSiblingElement();  // before include() grows the stack
    if (e.name() == "include")
      include(e);
    else
      element_(e);
  }
}

}  // namespace stride::sim
