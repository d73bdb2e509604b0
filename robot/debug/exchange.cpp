#include "robot/debug/exchange.hpp"

namespace stride::debug {

void encode_copies(Snapshot& s) {
  s.bytes.clear();
  ByteWriter w(s.bytes);
  for (std::size_t i = 0; i < s.parts.size(); ++i) {
    if (s.parts[i].first == Snapshot::kAbsent) continue;
    const auto at = static_cast<std::uint32_t>(s.bytes.size());
    s.copies[i]->encode(w);
    s.parts[i] = {at, static_cast<std::uint32_t>(s.bytes.size() - at)};
  }
}

}  // namespace stride::debug
