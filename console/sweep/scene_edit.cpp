#include "console/sweep/scene_edit.hpp"

#include <fstream>
#include <sstream>

#include <tinyxml2.h>

#include "robot/core/error.hpp"
#include "robot/core/xml_error.hpp"
#include "simulator/scene/scene_parser.hpp"

namespace stride::sweep {
namespace {

struct Segment {
  std::string name;
  int index = 1;            // [N]
  std::string attr, value;  // [attr=value]
};

struct Target {
  std::vector<Segment> path;
  std::string attribute;
};

Target parse_target(const std::string& target) {
  const auto fail = [&](const std::string& what) -> Error {
    return Error("'" + target + "': " + what +
                 " (expected scene:<element>[/<child>...]@<attribute>, an element written "
                 "name, name[N] or name[attr=value])");
  };
  if (target.rfind("scene:", 0) != 0) throw fail("not a scene attribute");
  const std::string body = target.substr(6);
  const std::size_t at = body.rfind('@');
  if (at == std::string::npos || at == 0 || at + 1 == body.size()) throw fail("no @attribute");
  Target t;
  t.attribute = body.substr(at + 1);
  std::stringstream ss(body.substr(0, at));
  for (std::string part; std::getline(ss, part, '/');) {
    Segment s;
    const std::size_t open = part.find('[');
    s.name = part.substr(0, open);
    if (s.name.empty()) throw fail("an empty element name");
    if (open != std::string::npos) {
      if (part.back() != ']') throw fail("'[' without ']'");
      const std::string inner = part.substr(open + 1, part.size() - open - 2);
      const std::size_t eq = inner.find('=');
      if (eq == std::string::npos) {
        std::size_t used = 0;
        try {
          s.index = std::stoi(inner, &used);
        } catch (const std::exception&) {
          used = 0;
        }
        if (used != inner.size() || inner.empty() || s.index < 1) throw fail("a bad index");
      } else {
        s.attr = inner.substr(0, eq);
        s.value = inner.substr(eq + 1);
        if (s.attr.empty()) throw fail("an empty attribute name in [...]");
      }
    }
    t.path.push_back(std::move(s));
  }
  if (t.path.empty()) throw fail("no element");
  return t;
}

tinyxml2::XMLElement* find(tinyxml2::XMLElement* parent, const Segment& s) {
  int seen = 0;
  for (auto* e = parent->FirstChildElement(s.name.c_str()); e;
       e = e->NextSiblingElement(s.name.c_str())) {
    if (!s.attr.empty()) {
      const char* v = e->Attribute(s.attr.c_str());
      if (v && s.value == v) return e;
    } else if (++seen == s.index) {
      return e;
    }
  }
  return nullptr;
}

std::string read_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw Error(path + ":0: cannot open scene file");
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace

void check_scene_target(const std::string& target) {
  parse_target(target);
}

sim::SceneDescription load_edited_scene(const std::string& path,
                                        const std::vector<Setting>& edits) {
  if (edits.empty()) return sim::parse_scene_file(path);
  tinyxml2::XMLDocument doc;
  const std::string text = read_file(path);
  if (doc.Parse(text.c_str(), text.size()) != tinyxml2::XML_SUCCESS)
    throw error_at(path, doc.ErrorLineNum(), xml_error_text(doc));
  tinyxml2::XMLElement* root = doc.RootElement();
  if (!root) throw error_at(path, 1, "expected <scene> as the root element");
  std::string changed;
  for (const Setting& edit : edits) {
    const Target t = parse_target(edit.target);
    tinyxml2::XMLElement* e = root;
    for (const Segment& s : t.path) {
      e = find(e, s);
      if (!e)
        throw Error(path + ": " + edit.target + ": no element <" + s.name +
                    (s.attr.empty() ? (s.index > 1 ? "> number " + std::to_string(s.index) : ">")
                                    : " " + s.attr + "=\"" + s.value + "\">") +
                    " in the scene (elements of included files cannot be edited)");
    }
    e->SetAttribute(t.attribute.c_str(), edit.value.c_str());
    changed += (changed.empty() ? "" : ", ") + edit.target + "=" + edit.value;
  }
  tinyxml2::XMLPrinter printer;
  doc.Print(&printer);
  try {
    return sim::parse_scene_text(printer.CStr(), path);
  } catch (const Error& e) {
    throw Error("scene " + path + " with " + changed + ": " + e.what());
  }
}

}  // namespace stride::sweep
