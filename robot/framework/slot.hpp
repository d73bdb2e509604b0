#pragma once
// A type-erased reflected object (one representation instance, or one module's parameters):
// what the blackboard, the logger and the console see.
#include <memory>
#include <string>
#include <string_view>
#include <typeindex>

#include "robot/framework/text.hpp"

namespace stride {

class Slot {
 public:
  virtual ~Slot() = default;
  virtual const TypeDesc& desc() const = 0;
  virtual std::type_index type() const = 0;
  virtual void encode(ByteWriter& w) const = 0;
  // Replaces the value by `bytes` (exactly one encoded value); unchanged on error.
  virtual void decode(std::string_view bytes) = 0;
  // A default-constructed object of the same type.
  virtual std::unique_ptr<Slot> fresh() const = 0;
  // Copies the value into `to`, a slot of the same type (type() equal); reuses `to`'s storage, so
  // a warmed-up copy does not allocate.
  virtual void copy_to(Slot& to) const = 0;

  Value value() const {
    std::string bytes;
    ByteWriter w(bytes);
    encode(w);
    ByteReader r(bytes);
    return read_value(desc(), r);
  }
  std::string text() const { return print_value(desc(), value()); }
  // Text of the part at `path` ("" = all), e.g. "position[3]".
  std::string text_at(std::string_view path, std::string_view root) const {
    const auto v = value();
    const auto [d, sub] = value_at(desc(), v, path, root);
    return print_value(*d, *sub);
  }
  // Whole or partial text update, all or nothing; errors start with `root`.
  void update(std::string_view text, std::string_view root, Numbers numbers = Numbers::Any) {
    auto v = value();
    update_value(desc(), v, text, root, numbers);
    std::string bytes;
    ByteWriter w(bytes);
    write_value(desc(), v, w);
    decode(bytes);
  }
};

template <class T>
class SlotOf final : public Slot {
 public:
  T value_{};

  const TypeDesc& desc() const override { return *describe<T>(); }
  std::type_index type() const override { return typeid(T); }
  void encode(ByteWriter& w) const override { stride::encode(w, value_); }
  void decode(std::string_view bytes) override { from_binary(value_, bytes); }
  std::unique_ptr<Slot> fresh() const override { return std::make_unique<SlotOf<T>>(); }
  void copy_to(Slot& to) const override { static_cast<SlotOf<T>&>(to).value_ = value_; }
};

template <class T>
std::unique_ptr<Slot> make_slot() {
  return std::make_unique<SlotOf<T>>();
}

// The typed object inside `s`; the caller has checked s.type() == typeid(T).
template <class T>
T& slot_value(Slot& s) {
  return static_cast<SlotOf<T>&>(s).value_;
}
template <class T>
const T& slot_value(const Slot& s) {
  return static_cast<const SlotOf<T>&>(s).value_;
}

}  // namespace stride
