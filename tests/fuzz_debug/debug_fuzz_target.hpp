#pragma once
// The debug protocol's decoders under hostile bytes, shared by the libFuzzer entry and the corpus
// test: the framing, a client message as the server reads it, a server message as the console
// reads it, and a type description with a value after it as a robot could send them. Each must
// decode or fail with one stride::Error line; the messages of the failures are returned.
#include <cstdint>
#include <string>
#include <vector>

#include "robot/core/error.hpp"
#include "robot/debug/protocol.hpp"
#include "robot/debug/server_message.hpp"
#include "robot/debug/wire.hpp"
#include "robot/framework/value.hpp"

namespace stride::test {

inline std::vector<std::string> fuzz_debug_input(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  std::vector<std::string> errors;
  auto attempt = [&](auto&& f) {
    try {
      f();
    } catch (const Error& e) {
      errors.emplace_back(e.what());
    }
  };
  attempt([&] {  // framing, fed in two pieces as a socket may deliver it
    debug::FrameReader reader(debug::kMaxClientMessage);
    reader.feed(bytes.substr(0, size / 2));
    while (reader.next()) {
    }
    reader.feed(bytes.substr(size / 2));
    while (auto payload = reader.next()) debug::decode_client_message(*payload);
  });
  attempt([&] { debug::decode_client_message(bytes); });
  attempt([&] {
    const debug::ServerMessage m(bytes);
    if (m.type() == "hello") debug::hello_of(m.fields());
    if (m.type() == "welcome") debug::welcome_of(m.fields());
    if (m.type() == "sample") debug::sample_of(m.fields());
    if (m.type() == "reply") debug::module_graph_of(m.fields());
  });
  attempt([&] {
    ByteReader r(bytes);
    const TypeDescPtr d = read_type_desc(r);
    describe_text(*d);
    const Value v = read_value(*d, r);
    print_value(*d, v);
  });
  return errors;
}

}  // namespace stride::test
