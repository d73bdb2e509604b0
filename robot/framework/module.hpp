#pragma once
// A module: computes the representations it provides from those it requires, once per frame.
//
//   class Stand final : public stride::Module {
//    public:
//     explicit Stand(stride::ModuleContext& c)
//         : frame_(c.require<FrameInfo>()), request_(c.provide<JointRequest>()),
//           params_(c.parameters<StandParameters>()), trace_(c.debug_request("stand:trace")) {}
//     void update() override;  // reads frame_.period, writes request_
//   };
//
// The constructor only binds (it is also run to learn the declarations); the references stay
// valid for the module's lifetime. Parameters change only between frames.
#include <bitset>
#include <memory>
#include <string>
#include <string_view>
#include <typeindex>

#include "robot/framework/slot.hpp"

namespace stride {
namespace model {
struct RobotModel;
}

inline constexpr int kMaxDebugRequests = 256;
using DebugRequestBits = std::bitset<kMaxDebugRequests>;

// A named switch owned by the Runtime; testing it is one bit lookup.
class DebugRequest {
 public:
  DebugRequest(const DebugRequestBits* bits, int index) : bits_(bits), index_(index) {}
  bool on() const { return bits_->test(index_); }

 private:
  const DebugRequestBits* bits_;
  int index_;
};

class Module {
 public:
  virtual ~Module() = default;
  virtual void update() = 0;
};

class ModuleContext {
 public:
  virtual ~ModuleContext() = default;

  template <class T>
  const T& require() {
    return slot_value<T>(bind(Use::Require, Reflect<T>::type_name(), typeid(T), &make_slot<T>));
  }
  template <class T>
  T& provide() {
    return slot_value<T>(bind(Use::Provide, Reflect<T>::type_name(), typeid(T), &make_slot<T>));
  }
  // This module's parameter struct (reflected; fields may declare ranges).
  template <class P>
  const P& parameters() {
    return slot_value<P>(bind(Use::Parameters, Reflect<P>::type_name(), typeid(P), &make_slot<P>));
  }
  virtual DebugRequest debug_request(std::string_view name) = 0;
  virtual const std::string& module_name() const = 0;
  // The robot's model (from its URDF), for modules that compute with masses or kinematics: they
  // copy what they need here, never loading files in update(). Throws naming the module when the
  // runtime has no model (while the runtime only learns declarations: an empty model).
  virtual const model::RobotModel& robot_model() = 0;

 protected:
  enum class Use { Require, Provide, Parameters };
  using SlotFactory = std::unique_ptr<Slot> (*)();
  // Returns a slot holding exactly `type`; throws if `name` is bound to another C++ type.
  virtual Slot& bind(Use use, std::string_view name, std::type_index type, SlotFactory make) = 0;
};

}  // namespace stride
