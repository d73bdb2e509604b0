#include "simulator/scene/robot_override_file.hpp"

#include "robot/core/error.hpp"
#include "robot/core/input_file.hpp"
#include "robot/core/xml_error.hpp"
#include "simulator/scene/include_walk.hpp"

namespace stride::sim {

std::vector<XmlElement> robot_override_children(const XmlElement& e, RobotOverrideFiles& files) {
  e.allow_only({"file"});
  if (e.raw()->FirstChildElement()) e.fail("unexpected child element of <include>");
  files.paths.push_back(std::make_unique<std::string>(resolve_from(e, e.text("file"))));
  const std::string& path = *files.paths.back();
  std::string text;
  try {  // a directory, device, FIFO or oversized file is refused before it is read
    text = read_input_file(path, kMaxTextInputBytes, "robot override file");
  } catch (const Error& err) {
    e.fail(err.what());
  }
  files.docs.push_back(std::make_unique<tinyxml2::XMLDocument>());
  tinyxml2::XMLDocument& doc = *files.docs.back();
  if (doc.Parse(text.c_str(), text.size()) != tinyxml2::XML_SUCCESS)
    throw error_at(path, doc.ErrorLineNum(), xml_error_text(doc));
  const tinyxml2::XMLElement* root = doc.RootElement();
  if (!root || std::string_view(root->Name()) != "robot_override")
    throw error_at(path, root ? root->GetLineNum() : 1,
                   "expected <robot_override> as the root element (included from " + e.file() +
                       ":" + std::to_string(e.line()) + ")");
  XmlElement(root, path).allow_only({});
  std::vector<XmlElement> out;
  for (const tinyxml2::XMLElement* c = root->FirstChildElement(); c; c = c->NextSiblingElement()) {
    XmlElement child(c, path);
    const std::string_view n = child.name();
    if (n != "motor" && n != "servo" && n != "calibration" && n != "imu")
      child.fail(
          "unexpected element in <robot_override> (expected motor, servo, calibration or imu)");
    out.push_back(child);
  }
  return out;
}

}  // namespace stride::sim
