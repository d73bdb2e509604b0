#pragma once
// The small expression language of sweep files: derived columns (`distance / duration`), the
// rows a tally counts (`fell or tipped != 'none'`), a summary's stop condition. Numbers, 'text',
// names (columns or per-frame keys such as robot.torso.pitch), + - * /, comparisons, and/or/not,
// and abs min max sqrt hypot isnan if(condition, then, else). Names are bound to slots once, when
// the text is compiled.
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace stride::sweep {

// One value of a row: a number (booleans are 1 and 0) or a text.
using Cell = std::variant<double, std::string>;

class Expression {
 public:
  // Maps a name to the slot its value will be read from; throws stride::Error for an unknown
  // name (the message is used as is).
  using Resolver = std::function<int(std::string_view name)>;

  // Throws stride::Error "expression '<text>': <what> at column N" on bad text.
  Expression(std::string_view text, const Resolver& resolve);
  ~Expression();
  Expression(Expression&&) noexcept;
  Expression& operator=(Expression&&) noexcept;

  Cell evaluate(std::span<const Cell> slots) const;
  // evaluate() as a number: a text is an error (stride::Error naming the expression).
  double number(std::span<const Cell> slots) const;
  // Non-zero number, or non-empty text.
  bool truth(std::span<const Cell> slots) const;
  // True when the result is a text whatever the slots hold, given which slots hold texts.
  bool yields_text(const std::function<bool(int slot)>& slot_is_text) const;

  const std::string& text() const { return text_; }
  // The slots it reads, each once.
  const std::vector<int>& slots() const { return used_; }

  struct Node;

 private:
  std::string text_;
  std::unique_ptr<Node> root_;
  std::vector<int> used_;
};

// "a,b" / "a b": the names a text lists.
std::vector<std::string> split_names(std::string_view text);

}  // namespace stride::sweep
