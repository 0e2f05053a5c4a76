// parameters.h - named scene parameters and arithmetic expressions in scene values.
//
// A scene may define "parameters": {"H": 100, "D_over_H": 0.4, ...} (numbers, or expressions of parameters
// defined before them) and use them anywhere a number is expected by writing a string that starts with '=':
//   "max": [1800, "= H + D_over_H * H"]
// Expressions have + - * / ^ (power), unary minus, parentheses, numbers, parameter names and the
// functions sqrt, sin, cos, tan, abs, min(a, b), max(a, b), and the constant pi. `--set parameters.D_over_H=0.6`
// then changes every value that depends on it, so a sweep needs no file editing.
// Evaluation happens before validation; the "parameters" key is removed from the scene json that the loader
// sees. Errors throw SceneError "<file>: <json.path>: <what is wrong>".
#pragma once

#include <map>
#include <nlohmann/json.hpp>
#include <string>

namespace cdmpm {

// Deepest nesting of an expression (each parenthesis, function call, '^' and unary minus counts one
// level); deeper expressions are refused, as the evaluator is recursive.
constexpr size_t kMaxExpressionDepth = 64;

// Replaces every "=expression" string in `j` by its value and removes j["parameters"]; the parameters' values
// go into *resolved if given.
void substitute_parameters(nlohmann::json& j, const std::string& file,
                           std::map<std::string, double>* resolved = nullptr);

}  // namespace cdmpm
