#pragma once
// The server thread's view of the blackboard: the catalogue with decoded type descriptions, the
// values of one snapshot (decoded once, on demand), and stream subscriptions resolved against them.
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "robot/debug/exchange.hpp"
#include "robot/framework/value.hpp"

namespace stride::debug {

class ServedCatalogue {
 public:
  explicit ServedCatalogue(std::shared_ptr<const Catalogue> c);  // decodes the descriptions
  std::uint64_t generation() const { return raw_->generation; }
  std::size_t size() const { return raw_->keys.size(); }
  const std::string& key(std::size_t slot) const { return raw_->keys[slot]; }
  const std::string& desc_bytes(std::size_t slot) const { return raw_->desc_bytes[slot]; }
  const TypeDesc& desc(std::size_t slot) const { return *descs_[slot]; }
  // The slot of "representation:X" / "module:X" (no path), or nothing.
  std::optional<std::size_t> find(const std::string& root_key) const;

 private:
  std::shared_ptr<const Catalogue> raw_;
  std::vector<TypeDescPtr> descs_;
  std::map<std::string, std::size_t, std::less<>> index_;
};

// One snapshot's values; decoding happens at most once per slot.
class SnapshotValues {
 public:
  SnapshotValues(const ServedCatalogue& c, const Snapshot& s) : c_(c), s_(s), values_(c.size()) {}
  bool has(std::size_t slot) const {
    return slot < s_.parts.size() && s_.parts[slot].first != Snapshot::kAbsent;
  }
  std::string_view bytes(std::size_t slot) const;
  const Value& value(std::size_t slot);
  const Snapshot& snapshot() const { return s_; }
  const TypeDesc& desc(std::size_t slot) const { return c_.desc(slot); }

 private:
  const ServedCatalogue& c_;
  const Snapshot& s_;
  std::vector<std::optional<Value>> values_;
};

// One streamed key: its slot, the path inside, and the description of what the path selects.
struct StreamKey {
  std::string key;
  std::size_t slot = 0;
  std::string name;  // representation or module name (error texts)
  std::string path;
  std::string desc_bytes;  // of the selected part
  TypeDescPtr desc;
  std::string root_desc_bytes;  // of the whole slot, to check a new catalogue against
  static constexpr std::size_t kGone = static_cast<std::size_t>(-1);
};

// The slot each key needs; throws naming a key that is not on this robot.
std::vector<std::size_t> slots_of(const std::vector<std::string>& keys, const ServedCatalogue& c);
// Resolves every key against the values (paths into lists need a value); throws naming the key.
std::vector<StreamKey> resolve_keys(const std::vector<std::string>& keys, const ServedCatalogue& c,
                                    SnapshotValues& values);
// The encoded value of each key (empty where a list no longer reaches the path).
std::vector<std::string> sample_values(const std::vector<StreamKey>& keys, SnapshotValues& values);
// After a re-plan: each key's slot in the new catalogue, or kGone if it is not there with the same
// type (its samples are then empty).
void rebind_keys(std::vector<StreamKey>& keys, const ServedCatalogue& c);

}  // namespace stride::debug
