#include "robot/debug/served_values.hpp"

#include "robot/core/error.hpp"
#include "robot/core/one_line.hpp"
#include "robot/runtime/console_key.hpp"

namespace stride::debug {

ServedCatalogue::ServedCatalogue(std::shared_ptr<const Catalogue> c) : raw_(std::move(c)) {
  for (std::size_t i = 0; i < raw_->keys.size(); ++i) {
    ByteReader r(raw_->desc_bytes[i]);
    descs_.push_back(read_type_desc(r));
    index_.emplace(raw_->keys[i], i);
  }
}

std::optional<std::size_t> ServedCatalogue::find(const std::string& root_key) const {
  auto it = index_.find(root_key);
  if (it == index_.end()) return std::nullopt;
  return it->second;
}

std::string_view SnapshotValues::bytes(std::size_t slot) const {
  const auto [offset, size] = s_.parts[slot];
  return std::string_view(s_.bytes).substr(offset, size);
}

const Value& SnapshotValues::value(std::size_t slot) {
  if (!values_[slot]) {
    ByteReader r(bytes(slot));
    values_[slot] = read_value(c_.desc(slot), r);
  }
  return *values_[slot];
}

namespace {
std::size_t slot_of(const std::string& key, const ServedCatalogue& c) {
  const ConsoleKey k = split_console_key(key);
  if (auto slot = c.find(k.root())) return *slot;
  throw Error(k.representation ? "no representation '" + one_line(k.name) + "' on the blackboard"
                               : "no module '" + one_line(k.name) + "' with parameters");
}
}  // namespace

std::vector<std::size_t> slots_of(const std::vector<std::string>& keys, const ServedCatalogue& c) {
  std::vector<std::size_t> out;
  for (const auto& key : keys) out.push_back(slot_of(key, c));
  return out;
}

std::vector<StreamKey> resolve_keys(const std::vector<std::string>& keys, const ServedCatalogue& c,
                                    SnapshotValues& values) {
  std::vector<StreamKey> out;
  for (const auto& key : keys) {
    const ConsoleKey k = split_console_key(key);
    StreamKey s{key, slot_of(key, c), k.name, k.path, {}, {}, {}};
    s.root_desc_bytes = c.desc_bytes(s.slot);
    const TypeDesc* sub = value_at(c.desc(s.slot), values.value(s.slot), s.path, s.name).first;
    ByteWriter w(s.desc_bytes);
    write_type_desc(w, *sub);
    ByteReader r(s.desc_bytes);
    s.desc = read_type_desc(r);  // an owned copy: the catalogue may be replaced
    out.push_back(std::move(s));
  }
  return out;
}

std::vector<std::string> sample_values(const std::vector<StreamKey>& keys, SnapshotValues& values) {
  std::vector<std::string> out(keys.size());
  for (std::size_t i = 0; i < keys.size(); ++i) {
    const auto& k = keys[i];
    if (k.slot == StreamKey::kGone || !values.has(k.slot)) continue;
    try {
      const auto [d, v] = value_at(values.desc(k.slot), values.value(k.slot), k.path, k.name);
      ByteWriter w(out[i]);
      write_value(*d, *v, w);
    } catch (const Error&) {
      out[i].clear();  // e.g. a list that no longer reaches the index
    }
  }
  return out;
}

void rebind_keys(std::vector<StreamKey>& keys, const ServedCatalogue& c) {
  for (auto& k : keys) {
    const auto slot = c.find(split_console_key(k.key).root());
    k.slot = slot && c.desc_bytes(*slot) == k.root_desc_bytes ? *slot : StreamKey::kGone;
  }
}

}  // namespace stride::debug
