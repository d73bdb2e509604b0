#include "robot/runtime/console_key.hpp"

#include <algorithm>

#include "robot/core/error.hpp"
#include "robot/core/quote.hpp"

namespace stride {

ConsoleKey split_console_key(std::string_view key) {
  ConsoleKey k;
  std::string_view rest;
  if (key.starts_with("representation:")) {
    k.representation = true;
    rest = key.substr(15);
  } else if (key.starts_with("module:")) {
    k.representation = false;
    rest = key.substr(7);
  } else {
    throw Error("key " + quote(key) + ": expected representation:<Name> or module:<Name>");
  }
  const auto cut = std::min(rest.find('.'), rest.find('['));
  k.name = std::string(rest.substr(0, cut));
  if (cut != std::string_view::npos)
    k.path = std::string(rest.substr(rest[cut] == '.' ? cut + 1 : cut));
  if (k.name.empty()) throw Error("key " + quote(key) + ": expected a name after ':'");
  return k;
}

}  // namespace stride
