#include "console/sweep/expression.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>

#include "robot/core/error.hpp"

namespace stride::sweep {

enum class Op {
  Number,
  Text,
  Slot,
  Negate,
  Not,
  Add,
  Sub,
  Mul,
  Div,
  Lt,
  Le,
  Gt,
  Ge,
  Eq,
  Ne,
  And,
  Or,
  Call
};

struct Expression::Node {
  Op op = Op::Number;
  double number = 0;
  std::string text;  // Text: the value; Call: the function
  int slot = -1;
  std::vector<std::unique_ptr<Node>> args;
};

namespace {

using Node = Expression::Node;
constexpr std::string_view kFunctions[] = {"abs", "min", "max", "sqrt", "hypot", "isnan", "if"};

bool name_char(char c, bool first) {
  const auto u = static_cast<unsigned char>(c);
  if (std::isalpha(u) || c == '_') return true;
  return !first && (std::isdigit(u) || c == '.' || c == ':' || c == '[' || c == ']');
}

// Recursive descent over the text; every error names the column it stopped at.
class Parser {
 public:
  Parser(std::string_view text, const Expression::Resolver& resolve, std::vector<int>& used)
      : s_(text), resolve_(resolve), used_(used) {}

  std::unique_ptr<Node> parse() {
    auto n = disjunction();
    skip_space();
    if (i_ != s_.size()) fail("unexpected '" + std::string(1, s_[i_]) + "'");
    return n;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw Error("expression '" + std::string(s_) + "': " + what + " at column " +
                std::to_string(i_ + 1));
  }
  void skip_space() {
    while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_]))) ++i_;
  }
  bool eat(std::string_view token) {
    skip_space();
    if (s_.substr(i_, token.size()) != token) return false;
    const bool word = std::isalpha(static_cast<unsigned char>(token[0]));
    if (word && i_ + token.size() < s_.size() && name_char(s_[i_ + token.size()], false))
      return false;  // `order` is a name, not `or` + `der`
    i_ += token.size();
    return true;
  }
  static std::unique_ptr<Node> join(Op op, std::unique_ptr<Node> a, std::unique_ptr<Node> b) {
    auto n = std::make_unique<Node>();
    n->op = op;
    n->args.push_back(std::move(a));
    n->args.push_back(std::move(b));
    return n;
  }

  std::unique_ptr<Node> disjunction() {
    auto n = conjunction();
    while (eat("or")) n = join(Op::Or, std::move(n), conjunction());
    return n;
  }
  std::unique_ptr<Node> conjunction() {
    auto n = negation();
    while (eat("and")) n = join(Op::And, std::move(n), negation());
    return n;
  }
  std::unique_ptr<Node> negation() {
    if (!eat("not")) return comparison();
    auto n = std::make_unique<Node>();
    n->op = Op::Not;
    n->args.push_back(negation());
    return n;
  }
  std::unique_ptr<Node> comparison() {
    auto n = sum();
    static constexpr std::pair<std::string_view, Op> kOps[] = {{"<=", Op::Le}, {">=", Op::Ge},
                                                               {"==", Op::Eq}, {"!=", Op::Ne},
                                                               {"<", Op::Lt},  {">", Op::Gt}};
    for (const auto& [token, op] : kOps)
      if (eat(token)) return join(op, std::move(n), sum());
    return n;
  }
  std::unique_ptr<Node> sum() {
    auto n = product();
    for (;;) {
      if (eat("+"))
        n = join(Op::Add, std::move(n), product());
      else if (eat("-"))
        n = join(Op::Sub, std::move(n), product());
      else
        return n;
    }
  }
  std::unique_ptr<Node> product() {
    auto n = unary();
    for (;;) {
      if (eat("*"))
        n = join(Op::Mul, std::move(n), unary());
      else if (eat("/"))
        n = join(Op::Div, std::move(n), unary());
      else
        return n;
    }
  }
  std::unique_ptr<Node> unary() {
    if (!eat("-")) return primary();
    auto n = std::make_unique<Node>();
    n->op = Op::Negate;
    n->args.push_back(unary());
    return n;
  }
  std::unique_ptr<Node> primary() {
    skip_space();
    if (i_ >= s_.size()) fail("expected a value");
    auto n = std::make_unique<Node>();
    const char c = s_[i_];
    if (c == '(') {
      ++i_;
      n = disjunction();
      if (!eat(")")) fail("expected ')'");
    } else if (c == '\'') {
      const std::size_t end = s_.find('\'', i_ + 1);
      if (end == std::string_view::npos) fail("unterminated text");
      n->op = Op::Text;
      n->text = std::string(s_.substr(i_ + 1, end - i_ - 1));
      i_ = end + 1;
    } else if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') {
      number(*n);
    } else if (name_char(c, true)) {
      name(*n);
    } else {
      fail("unexpected '" + std::string(1, c) + "'");
    }
    return n;
  }
  void number(Node& n) {
    const auto r = std::from_chars(s_.data() + i_, s_.data() + s_.size(), n.number);
    if (r.ec != std::errc()) fail("expected a number");
    i_ = static_cast<std::size_t>(r.ptr - s_.data());
    n.op = Op::Number;
  }
  void name(Node& n) {
    const std::size_t start = i_;
    while (i_ < s_.size() && name_char(s_[i_], false)) ++i_;
    const std::string word(s_.substr(start, i_ - start));
    skip_space();
    if (i_ < s_.size() && s_[i_] == '(') {
      if (std::find(std::begin(kFunctions), std::end(kFunctions), word) == std::end(kFunctions))
        fail("unknown function '" + word + "' (abs, min, max, sqrt, hypot, isnan, if)");
      ++i_;
      n.op = Op::Call;
      n.text = word;
      if (!eat(")")) {
        do n.args.push_back(disjunction());
        while (eat(","));
        if (!eat(")")) fail("expected ')' or ','");
      }
      const std::size_t want = word == "if"                                        ? 3
                               : word == "min" || word == "max" || word == "hypot" ? 2
                                                                                   : 1;
      if (n.args.size() != want && !(want == 2 && word != "hypot" && n.args.size() > 2))
        fail(word + "() takes " + std::to_string(want) + (want == 2 && word != "hypot" ? "+" : "") +
             " argument(s)");
      return;
    }
    if (word == "nan" || word == "inf") {
      n.op = Op::Number;
      n.number = word == "nan" ? NAN : INFINITY;
      return;
    }
    if (word == "true" || word == "false") {
      n.op = Op::Number;
      n.number = word == "true";
      return;
    }
    n.op = Op::Slot;
    try {
      n.slot = resolve_(word);
    } catch (const Error& e) {
      throw Error("expression '" + std::string(s_) + "': " + e.what());
    }
    if (std::find(used_.begin(), used_.end(), n.slot) == used_.end()) used_.push_back(n.slot);
  }

  std::string_view s_;
  std::size_t i_ = 0;
  const Expression::Resolver& resolve_;
  std::vector<int>& used_;
};

double as_number(const Cell& c, const std::string& text) {
  if (const double* d = std::get_if<double>(&c)) return *d;
  throw Error("expression '" + text + "': expected a number, got the text '" +
              std::get<std::string>(c) + "'");
}

bool truth_of(const Cell& c) {
  if (const double* d = std::get_if<double>(&c)) return *d != 0 && !std::isnan(*d);
  return !std::get<std::string>(c).empty();
}

Cell compare(Op op, const Cell& a, const Cell& b, const std::string& text) {
  if (a.index() != b.index()) {
    if (op == Op::Eq || op == Op::Ne) return (op == Op::Ne) ? 1.0 : 0.0;
    throw Error("expression '" + text + "': cannot order a number against a text");
  }
  const auto cmp = [&](const auto& x, const auto& y) -> double {
    switch (op) {
      case Op::Lt:
        return x < y;
      case Op::Le:
        return x <= y;
      case Op::Gt:
        return x > y;
      case Op::Ge:
        return x >= y;
      case Op::Eq:
        return x == y;
      default:
        return x != y;
    }
  };
  if (a.index() == 0) return cmp(std::get<double>(a), std::get<double>(b));
  return cmp(std::get<std::string>(a), std::get<std::string>(b));
}

Cell call(const Node& n, const std::vector<double>& v) {
  if (n.text == "abs") return std::abs(v[0]);
  if (n.text == "sqrt") return std::sqrt(v[0]);
  if (n.text == "isnan") return std::isnan(v[0]) ? 1.0 : 0.0;
  if (n.text == "hypot") return std::hypot(v[0], v[1]);
  double r = v[0];
  for (std::size_t i = 1; i < v.size(); ++i)
    r = n.text == "min" ? std::min(r, v[i]) : std::max(r, v[i]);
  return r;
}

Cell eval(const Node& n, std::span<const Cell> slots, const std::string& text) {
  switch (n.op) {
    case Op::Number:
      return n.number;
    case Op::Text:
      return n.text;
    case Op::Slot:
      return slots[static_cast<std::size_t>(n.slot)];
    case Op::Negate:
      return -as_number(eval(*n.args[0], slots, text), text);
    case Op::Not:
      return truth_of(eval(*n.args[0], slots, text)) ? 0.0 : 1.0;
    case Op::And:
      return truth_of(eval(*n.args[0], slots, text)) && truth_of(eval(*n.args[1], slots, text))
                 ? 1.0
                 : 0.0;
    case Op::Or:
      return truth_of(eval(*n.args[0], slots, text)) || truth_of(eval(*n.args[1], slots, text))
                 ? 1.0
                 : 0.0;
    case Op::Call: {
      if (n.text == "if")  // only the branch taken is evaluated
        return eval(*n.args[truth_of(eval(*n.args[0], slots, text)) ? 1 : 2], slots, text);
      std::vector<double> v;
      for (const auto& a : n.args) v.push_back(as_number(eval(*a, slots, text), text));
      return call(n, v);
    }
    default:
      break;
  }
  const Cell a = eval(*n.args[0], slots, text), b = eval(*n.args[1], slots, text);
  switch (n.op) {
    case Op::Add:
      return as_number(a, text) + as_number(b, text);
    case Op::Sub:
      return as_number(a, text) - as_number(b, text);
    case Op::Mul:
      return as_number(a, text) * as_number(b, text);
    case Op::Div:
      return as_number(a, text) / as_number(b, text);
    default:
      return compare(n.op, a, b, text);
  }
}

bool text_result(const Node& n, const std::function<bool(int)>& slot_is_text) {
  if (n.op == Op::Text) return true;
  if (n.op == Op::Call && n.text == "if")
    return text_result(*n.args[1], slot_is_text) || text_result(*n.args[2], slot_is_text);
  if (n.op == Op::Slot) return slot_is_text(n.slot);
  return false;
}

}  // namespace

Expression::Expression(std::string_view text, const Resolver& resolve) : text_(text) {
  Parser p(text_, resolve, used_);
  root_ = p.parse();
}
Expression::~Expression() = default;
Expression::Expression(Expression&&) noexcept = default;
Expression& Expression::operator=(Expression&&) noexcept = default;

Cell Expression::evaluate(std::span<const Cell> slots) const {
  return eval(*root_, slots, text_);
}

double Expression::number(std::span<const Cell> slots) const {
  return as_number(evaluate(slots), text_);
}

bool Expression::truth(std::span<const Cell> slots) const {
  return truth_of(evaluate(slots));
}

bool Expression::yields_text(const std::function<bool(int)>& slot_is_text) const {
  return text_result(*root_, slot_is_text);
}

std::vector<std::string> split_names(std::string_view text) {
  std::vector<std::string> out;
  std::string item;
  for (char c : text) {
    if (c == ',' || std::isspace(static_cast<unsigned char>(c))) {
      if (!item.empty()) out.push_back(std::move(item));
      item.clear();
    } else {
      item += c;
    }
  }
  if (!item.empty()) out.push_back(std::move(item));
  return out;
}

}  // namespace stride::sweep
