#include "robot/debug/exchange.hpp"

namespace stride::debug {

void encode_copies(Snapshot& s) {
  s.bytes.clear();
  s.parts.assign(s.slot_count, {Snapshot::kAbsent, 0});
  ByteWriter w(s.bytes);
  for (const std::uint32_t i : s.copied) {
    const auto at = static_cast<std::uint32_t>(s.bytes.size());
    s.copies[i]->encode(w);
    s.parts[i] = {at, static_cast<std::uint32_t>(s.bytes.size() - at)};
  }
}

}  // namespace stride::debug
