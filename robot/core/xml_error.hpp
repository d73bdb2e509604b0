#pragma once
// tinyxml2's error as words: "malformed XML (mismatched element)".
#include <cctype>
#include <string>

#include <tinyxml2.h>

namespace stride {

inline std::string xml_error_text(const tinyxml2::XMLDocument& doc) {
  std::string id = doc.ErrorName();
  if (id.rfind("XML_ERROR_", 0) == 0) id = id.substr(10);
  for (char& c : id)
    c = c == '_' ? ' ' : static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return "malformed XML (" + id + ")";
}

}  // namespace stride
