// parameters.cpp - recursive-descent evaluation of "=expression" scene values (see parameters.h).
//   expr   := term (('+' | '-') term)*
//   term   := factor (('*' | '/') factor)*
//   factor := unary ('^' factor)?            (right associative)
//   unary  := '-' unary | primary
//   primary:= number | name | name '(' expr (',' expr)* ')' | '(' expr ')'
#include "scene/parameters.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <numbers>

#include "scene/scene_loader.h"

namespace cdmpm {
namespace {

using json = nlohmann::json;

class Expression {
 public:
  Expression(const std::string& text, const std::map<std::string, double>& vars) : s_(text), vars_(vars) {}

  // Returns the value, or throws std::runtime_error with a short reason.
  double evaluate() {
    const double v = expr();
    skip();
    if (i_ != s_.size()) error("unexpected '" + s_.substr(i_, 1) + "'");
    if (!std::isfinite(v)) error("the value is not finite");
    return v;
  }

 private:
  [[noreturn]] void error(const std::string& why) const {
    throw std::runtime_error(why + " at position " + std::to_string(i_ + 1));
  }
  void skip() {
    while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_]))) ++i_;
  }
  bool accept(char c) {
    skip();
    if (i_ < s_.size() && s_[i_] == c) return ++i_, true;
    return false;
  }
  double expr() {
    double v = term();
    while (true) {
      if (accept('+')) v += term();
      else if (accept('-')) v -= term();
      else return v;
    }
  }
  double term() {
    double v = factor();
    while (true) {
      if (accept('*')) v *= factor();
      else if (accept('/')) v /= factor();
      else return v;
    }
  }
  // Every recursion (parentheses, function arguments, '^' chains, unary minus) holds a Nesting while it
  // runs, so the depth of the C++ stack is bounded by kMaxExpressionDepth.
  struct Nesting {
    Expression& e;
    explicit Nesting(Expression& ex) : e(ex) {
      if (++e.depth_ > kMaxExpressionDepth)
        e.error("expression nested more than " + std::to_string(kMaxExpressionDepth) + " levels deep (the limit)");
    }
    ~Nesting() { --e.depth_; }
  };
  double factor() {
    const double base = unary();
    if (!accept('^')) return base;
    const Nesting n(*this);
    return std::pow(base, factor());
  }
  double unary() {
    if (!accept('-')) return primary();
    const Nesting n(*this);
    return -unary();
  }
  double primary() {
    skip();
    if (accept('(')) {
      const Nesting n(*this);
      const double v = expr();
      if (!accept(')')) error("expected ')'");
      return v;
    }
    if (i_ < s_.size() && (std::isdigit(static_cast<unsigned char>(s_[i_])) || s_[i_] == '.')) {
      size_t used = 0;
      const double v = std::stod(s_.substr(i_), &used);
      i_ += used;
      return v;
    }
    const size_t start = i_;
    while (i_ < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[i_])) || s_[i_] == '_')) ++i_;
    const std::string name = s_.substr(start, i_ - start);
    if (name.empty()) error(i_ < s_.size() ? "unexpected '" + s_.substr(i_, 1) + "'" : "unexpected end");
    if (accept('(')) {
      const Nesting n(*this);
      std::vector<double> args{expr()};
      while (accept(',')) args.push_back(expr());
      if (!accept(')')) error("expected ')'");
      return call(name, args);
    }
    if (name == "pi") return std::numbers::pi;
    const auto it = vars_.find(name);
    if (it == vars_.end()) error("unknown parameter '" + name + "'");
    return it->second;
  }
  double call(const std::string& f, const std::vector<double>& a) {
    const bool one = a.size() == 1, two = a.size() == 2;
    if (f == "sqrt" && one) return std::sqrt(a[0]);
    if (f == "sin" && one) return std::sin(a[0]);
    if (f == "cos" && one) return std::cos(a[0]);
    if (f == "tan" && one) return std::tan(a[0]);
    if (f == "abs" && one) return std::abs(a[0]);
    if (f == "min" && two) return std::min(a[0], a[1]);
    if (f == "max" && two) return std::max(a[0], a[1]);
    error("unknown function '" + f + "' with " + std::to_string(a.size()) + " argument(s)");
  }

  const std::string& s_;
  const std::map<std::string, double>& vars_;
  size_t i_ = 0;
  size_t depth_ = 0;
};

bool is_expression(const json& v) { return v.is_string() && !v.get<std::string>().empty() && v.get<std::string>()[0] == '='; }

double evaluate(const json& v, const std::map<std::string, double>& vars, const std::string& file,
                const std::string& path) {
  const std::string text = v.get<std::string>().substr(1);
  try {
    return Expression(text, vars).evaluate();
  } catch (const std::exception& e) {
    const std::string& all = v.get<std::string>();
    const std::string shown = all.size() > 80 ? all.substr(0, 77) + "..." : all;
    throw SceneError(file + ": " + path + ": expected a number or an expression \"= ...\" of parameters, got \"" +
                     shown + "\" (" + e.what() + ")");
  }
}

void substitute(json& j, const std::map<std::string, double>& vars, const std::string& file, const std::string& path) {
  if (is_expression(j)) {
    // An integral result is stored as a JSON integer, so that keys that take an integer (particles_per_cell,
    // min_cells, ...) accept an expression such as "= (cells_per_H / 2)^2"; a literal 2.0 stays a float.
    const double x = evaluate(j, vars, file, path);
    if (std::abs(x) < 0x1p53 && x == std::nearbyint(x))
      j = static_cast<int64_t>(x);
    else
      j = x;
  } else if (j.is_object()) {
    for (auto& item : j.items()) substitute(item.value(), vars, file, path.empty() ? item.key() : path + "." + item.key());
  } else if (j.is_array()) {
    for (size_t k = 0; k < j.size(); ++k) substitute(j[k], vars, file, path + "[" + std::to_string(k) + "]");
  }
}

}  // namespace

void substitute_parameters(json& j, const std::string& file, std::map<std::string, double>* resolved) {
  std::map<std::string, double> vars;
  if (j.is_object() && j.contains("parameters")) {
    const json& p = j["parameters"];
    if (!p.is_object()) throw SceneError(file + ": parameters: expected an object of named numbers, got " + p.dump());
    // In file order (nlohmann::ordered_json would keep it; json sorts keys, so resolve by repeated passes).
    std::map<std::string, json> pending;
    for (const auto& item : p.items()) pending.emplace(item.key(), item.value());
    while (!pending.empty()) {
      bool progressed = false;
      for (auto it = pending.begin(); it != pending.end();) {
        const std::string path = "parameters." + it->first;
        const bool ok_name = !it->first.empty() && !std::isdigit(static_cast<unsigned char>(it->first[0])) &&
                             std::all_of(it->first.begin(), it->first.end(),
                                         [](unsigned char c) { return std::isalnum(c) || c == '_'; });
        if (!ok_name) throw SceneError(file + ": " + path + ": expected a parameter name of letters, digits and '_'");
        if (it->second.is_number()) {
          vars[it->first] = it->second.get<double>();
        } else if (is_expression(it->second)) {
          try {
            vars[it->first] = Expression(it->second.get<std::string>().substr(1), vars).evaluate();
          } catch (const std::exception&) {
            ++it;  // may depend on a parameter not resolved yet
            continue;
          }
        } else {
          throw SceneError(file + ": " + path + ": expected a number or an expression \"= ...\", got " + it->second.dump());
        }
        it = pending.erase(it);
        progressed = true;
      }
      if (!progressed) {  // report the first unresolvable one with its reason
        const auto& [name, v] = *pending.begin();
        evaluate(v, vars, file, "parameters." + name);
        throw SceneError(file + ": parameters." + name + ": circular definition");
      }
    }
    j.erase("parameters");
  }
  substitute(j, vars, file, "");
  if (resolved) *resolved = vars;
}

}  // namespace cdmpm
