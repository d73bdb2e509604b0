#pragma once
// One numeric leaf of a Slot ("position[3]", "cop.x", "gains.kp") read as a double many times:
// the path is checked once; when the slot's type has no strings or lists, the leaf sits at a
// fixed offset of the binary encoding, found once, and each read is an encode plus a copy.
#include <cstddef>
#include <string>
#include <string_view>

#include "robot/framework/slot.hpp"

namespace stride {

class LeafReader {
 public:
  // Throws stride::Error naming `root.path` when the path does not lead to a number or bool.
  LeafReader(const TypeDesc& type, std::string_view path, std::string_view root);

  // `scratch` is reused between calls to avoid allocations.
  double read(const Slot& slot, std::string& scratch) const;
  // Reads the leaf from the slot's encoding already in `bytes`.
  double read_encoded(const Slot& slot, const std::string& bytes) const;

 private:
  std::string path_, root_;
  Kind kind_ = Kind::Double;
  std::ptrdiff_t offset_ = -1;  // -1: the slot's type varies in size; decode the value instead
};

}  // namespace stride
