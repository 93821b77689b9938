// A recursive-descent parser of affine expressions:
//   expr   := term (('+' | '-') term)*
//   term   := unary (('*' | '/') unary)*
//   unary  := ('+' | '-') unary | factor
//   factor := number | name | '(' expr ')'
#include "config/affine_expression.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>

#include "hinf/common/error.hpp"
#include "hinf/common/number_text.hpp"
#include "hinf/common/suggest.hpp"

namespace hinf::synth {
namespace {

// Deeper nesting than this is refused (a hostile entry cannot exhaust the stack).
constexpr int kMaxNesting = 64;
// A message echoes an expression whole up to this many characters; a longer one (or a long
// token in it) by the kEchoContext characters either side of where reading stopped.
constexpr std::size_t kMaxEchoed = 160;
constexpr std::size_t kEchoContext = 60;

// `text` whole if short, else its characters [at − kEchoContext, at + kEchoContext) with
// "..." where cut.
std::string excerpt(const std::string& text, std::size_t at) {
  if (text.size() <= kMaxEchoed) return text;
  const std::size_t from = at > kEchoContext ? at - kEchoContext : 0;
  const std::size_t to = std::min(text.size(), at + kEchoContext);
  return (from > 0 ? "..." : "") + text.substr(from, to - from) + (to < text.size() ? "..." : "");
}

class AffineParser {
 public:
  AffineParser(const std::string& text, const ExpressionSymbols& symbols) : text_(text), symbols_(symbols) {}

  AffineForm parse() {
    AffineForm f = expr(0);
    skip_space();
    if (pos_ != text_.size()) fail("unexpected '" + std::string(1, text_[pos_]) + "'");
    if (!std::isfinite(f.constant) || !f.coefficients.allFinite()) fail("the value is not finite");
    return f;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw Error(ErrorCode::InvalidInput,
                "'" + excerpt(text_, pos_) + "': " + what + " (at character " + std::to_string(pos_ + 1) + ")");
  }
  void skip_space() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
  }
  bool accept(char c) {
    skip_space();
    if (pos_ < text_.size() && text_[pos_] == c) {
      ++pos_;
      return true;
    }
    return false;
  }
  AffineForm constant(double v) const {
    return AffineForm{v, Eigen::VectorXd::Zero(static_cast<Eigen::Index>(symbols_.parameters.size()))};
  }
  static bool is_constant(const AffineForm& f) { return (f.coefficients.array() == 0).all(); }

  AffineForm expr(int depth) {
    if (depth > kMaxNesting) fail("nested deeper than " + std::to_string(kMaxNesting) + " levels");
    AffineForm f = term(depth);
    for (;;) {
      if (accept('+')) {
        const AffineForm g = term(depth);
        f.constant += g.constant;
        f.coefficients += g.coefficients;
      } else if (accept('-')) {
        const AffineForm g = term(depth);
        f.constant -= g.constant;
        f.coefficients -= g.coefficients;
      } else {
        return f;
      }
    }
  }

  AffineForm term(int depth) {
    AffineForm f = unary(depth);
    for (;;) {
      if (accept('*')) {
        const AffineForm g = unary(depth);
        if (!is_constant(f) && !is_constant(g))
          fail("a product of parameters is not affine (the uncertainty must enter linearly)");
        const AffineForm& c = is_constant(f) ? f : g;
        const AffineForm& a = is_constant(f) ? g : f;
        f = AffineForm{c.constant * a.constant, c.constant * a.coefficients};
      } else if (accept('/')) {
        const AffineForm g = unary(depth);
        if (!is_constant(g)) fail("dividing by a parameter is not affine");
        if (g.constant == 0) fail("division by zero");
        f = AffineForm{f.constant / g.constant, f.coefficients / g.constant};
      } else {
        return f;
      }
    }
  }

  AffineForm unary(int depth) {
    if (depth > kMaxNesting) fail("nested deeper than " + std::to_string(kMaxNesting) + " levels");
    if (accept('-')) {
      AffineForm f = unary(depth + 1);
      return AffineForm{-f.constant, -f.coefficients};
    }
    if (accept('+')) return unary(depth + 1);
    return factor(depth);
  }

  AffineForm factor(int depth) {
    skip_space();
    if (pos_ >= text_.size()) fail("expected a number, a name or '(' at the end");
    const char c = text_[pos_];
    if (c == '(') {
      ++pos_;
      AffineForm f = expr(depth + 1);
      if (!accept(')')) fail("missing ')'");
      return f;
    }
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') return number();
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') return name();
    fail("expected a number, a name or '(', got '" + std::string(1, c) + "'");
  }

  AffineForm number() {
    const char* begin = text_.c_str() + pos_;
    char* end = nullptr;
    const double v = std::strtod(begin, &end);
    if (end == begin) fail("not a number");
    const std::string token(begin, static_cast<std::size_t>(end - begin));
    if (!is_decimal_number(token))
      fail("'" + excerpt(token, 0) + "' is not a decimal number (hexadecimal is refused here as everywhere in the file)");
    pos_ += static_cast<std::size_t>(end - begin);
    if (!std::isfinite(v)) fail("the number is not finite");
    return constant(v);
  }

  AffineForm name() {
    const std::size_t start = pos_;
    while (pos_ < text_.size() &&
           (std::isalnum(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '_'))
      ++pos_;
    const std::string word = text_.substr(start, pos_ - start);
    if (const auto it = symbols_.constants.find(word); it != symbols_.constants.end()) return constant(it->second);
    for (std::size_t i = 0; i < symbols_.parameters.size(); ++i)
      if (symbols_.parameters[i] == word) {
        AffineForm f = constant(0);
        f.coefficients(static_cast<Eigen::Index>(i)) = 1;
        return f;
      }
    std::vector<std::string> names = symbols_.parameters;
    for (const auto& [n, v] : symbols_.constants) names.push_back(n);
    std::string msg = "unknown name '" + excerpt(word, 0) + "'";
    if (const auto guess = closest_match(word, names)) msg += " (did you mean '" + *guess + "'?)";
    pos_ = start;
    fail(msg + "; names are declared under 'constants' and 'parameters'");
  }

  const std::string& text_;
  const ExpressionSymbols& symbols_;
  std::size_t pos_ = 0;
};

}  // namespace

AffineForm parse_affine_expression(const std::string& text, const ExpressionSymbols& symbols) {
  return AffineParser(text, symbols).parse();
}

}  // namespace hinf::synth
