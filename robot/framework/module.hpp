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
#include <cstdint>
#include <initializer_list>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <typeindex>
#include <utility>
#include <vector>

#include "robot/framework/reflect.hpp"
#include "robot/framework/slot.hpp"

namespace stride {
namespace model {
struct RobotModel;
}

namespace model {
struct RobotModel;
}

inline constexpr int kMaxDebugRequests = 256;
using DebugRequestBits = std::bitset<kMaxDebugRequests>;
// A debug request off, on, or on without printing (values and stops only).
enum class DebugSwitch : std::uint8_t { Off, On, Quiet };
template <>
struct EnumNames<DebugSwitch> {
  static constexpr std::string_view type_name = "DebugSwitch";
  static constexpr std::array<std::string_view, 3> names{"off", "on", "quiet"};
};
std::string_view debug_switch_name(DebugSwitch s);  // its EnumNames: "off", "on", "quiet"

inline constexpr std::size_t kMaxDebugLines = 10000;  // undrained lines beyond this are counted

// The Runtime's debug requests and what they emitted since the console (or debug server) last
// took it: printed lines, plotted values (latest per name), and a request to pause the run.
struct DebugChannel {
  DebugRequestBits bits;
  DebugRequestBits quiet;          // on without printing: values and stops only
  std::vector<std::string> names;  // request index -> name, e.g. "posture:corrections"
  std::vector<std::string> lines;  // "name: text", oldest first
  std::size_t dropped_lines = 0;
  std::map<std::string, double, std::less<>> values;  // "name.value" -> latest
  std::string stop;                                   // first stop reason not yet taken
};

// A named switch owned by the Runtime; testing it is one bit lookup. Output calls do nothing
// while the request is off, so a module may call them unconditionally.
class DebugRequest {
 public:
  DebugRequest(DebugChannel* channel, int index) : channel_(channel), index_(index) {}
  bool on() const { return channel_->bits.test(index_); }
  // A line for the console, shown as "name: text" (not while the request is quiet).
  void print(std::string_view text) const;
  // A value the console reads as debug:<name>.<value> (get, watch, plot).
  void plot(std::string_view value, double v) const;
  // A line for the console whether the request is on or not: what a module refuses or defers
  // (said once, not every frame).
  void say(std::string_view text) const;
  // Prints "a=1.5 b=-0.25" and plots each value: what most requests do every frame.
  void show(std::initializer_list<std::pair<std::string_view, double>> values) const;
  // Asks whoever runs the frames to pause after this one, saying why.
  void stop(std::string_view reason) const;

 private:
  DebugChannel* channel_;
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
