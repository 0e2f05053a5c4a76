// scene_reader.cpp - the generic scene checks (see scene_reader.h).
#include "scene/scene_reader.h"

#include <algorithm>
#include <cctype>
#include <climits>
#include <cmath>
#include <sstream>

namespace cdmpm {
namespace {
std::string show(const nlohmann::json& v) {
  std::string s = v.dump();
  return s.size() > 60 ? s.substr(0, 57) + "..." : s;
}
std::string box_text(const std::vector<double>& lo, const std::vector<double>& hi) {
  std::string s;
  for (size_t a = 0; a < lo.size(); ++a) s += (a ? " x [" : "[") + format_number(lo[a]) + ", " + format_number(hi[a]) + "]";
  return s;
}
}  // namespace

std::string format_number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

std::string join(const Strings& items, bool quote) {
  std::string out;
  for (const auto& it : items) out += (out.empty() ? "" : ", ") + (quote ? '"' + it + '"' : it);
  return out;
}

bool contains(const Strings& items, const std::string& s) {
  return std::find(items.begin(), items.end(), s) != items.end();
}

bool is_identifier(const std::string& s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isalnum(c) || c == '_'; });
}

std::string Range::describe() const {
  if (lo == -inf && hi == inf) return "";
  if (hi == inf) return (lo_open ? " > " : " >= ") + format_number(lo);
  if (lo == -inf) return (hi_open ? " < " : " <= ") + format_number(hi);
  return std::string(" in ") + (lo_open ? "(" : "[") + format_number(lo) + ", " + format_number(hi) + (hi_open ? ")" : "]");
}

void SceneReader::fail(const std::string& path, const std::string& msg) const {
  throw SceneError(file_ + ": " + (path.empty() ? "(root)" : path) + ": " + msg);
}

void SceneReader::expected(const Node& n, const std::string& what) const {
  fail(n.path, "expected " + what + ", got " + show(n.j));
}

void SceneReader::object(const Node& n, const Strings& allowed) const {
  if (!n.j.is_object()) expected(n, "an object");
  for (const auto& item : n.j.items())
    if (!contains(allowed, item.key())) fail(n.child(item.key()), "unknown key (allowed: " + join(allowed) + ")");
}

Node SceneReader::required(const Node& n, const std::string& key) const {
  if (!n.has(key)) fail(n.child(key), "required key missing");
  return n[key];
}

size_t SceneReader::array(const Node& n, size_t min_size, const std::string& what) const {
  if (!n.j.is_array() || n.j.size() < min_size) expected(n, what);
  return n.j.size();
}

double SceneReader::number(const Node& n, Range r, const std::string& note) const {
  if (!n.j.is_number() || !std::isfinite(n.j.get<double>()) || !r.contains(n.j.get<double>()))
    expected(n, "a number" + r.describe() + note);
  return n.j.get<double>();
}

double SceneReader::number(const Node& parent, const std::string& key, Range r, double fallback) const {
  return parent.has(key) ? number(parent[key], r) : fallback;
}

int SceneReader::integer(const Node& n, Range r) const {
  if (!n.j.is_number_integer() || !r.contains(n.j.get<double>()) || std::abs(n.j.get<double>()) > INT_MAX)
    expected(n, "an integer" + r.describe());
  return n.j.get<int>();
}

bool SceneReader::boolean(const Node& n) const {
  if (!n.j.is_boolean()) expected(n, "true or false");
  return n.j.get<bool>();
}

bool SceneReader::boolean(const Node& parent, const std::string& key, bool fallback) const {
  return parent.has(key) ? boolean(parent[key]) : fallback;
}

std::string SceneReader::string(const Node& n, const Strings& choices) const {
  if (!n.j.is_string() || (!choices.empty() && !contains(choices, n.j.get<std::string>())))
    expected(n, choices.empty() ? "a string" : "one of " + join(choices, true));
  return n.j.get<std::string>();
}

std::vector<double> SceneReader::numbers(const Node& n, size_t count, Range r) const {
  const std::string what = "an array of " + std::to_string(count) + " numbers" + r.describe();
  if (array(n, 0, what) != count) expected(n, what);
  std::vector<double> v(count);
  for (size_t i = 0; i < count; ++i) v[i] = number(n[i], r);
  return v;
}

std::vector<std::array<double, 2>> SceneReader::pairs(const Node& n, size_t min_count) const {
  size_t count = array(n, min_count, "an array of at least " + std::to_string(min_count) + " [x, y] pairs");
  std::vector<std::array<double, 2>> v(count);
  for (size_t i = 0; i < count; ++i) {
    auto p = numbers(n[i], 2);
    v[i] = {p[0], p[1]};
  }
  return v;
}

void SceneReader::min_max(const Node& n, std::vector<double>& lo, std::vector<double>& hi) const {
  lo = numbers(required(n, "min"), dim_);
  hi = numbers(required(n, "max"), dim_);
  for (int a = 0; a < dim_; ++a)
    if (!(hi[a] > lo[a])) expected(n["max"], "max > min on every axis (min = " + show(n["min"].j) + ")");
}

void SceneReader::inside(const Node& n, const std::vector<double>& lo, const std::vector<double>& hi,
                         const std::string& what) const {
  std::vector<double> zero(lo.size(), 0.0), size(domain_.begin(), domain_.begin() + lo.size());
  for (size_t a = 0; a < lo.size(); ++a) {
    double tol = 1e-12 * size[a];
    if (lo[a] < -tol || hi[a] > size[a] + tol)
      fail(n.path, "expected " + what + " inside the domain " + box_text(zero, size) + ", got " +
                       (lo == hi ? show(n.j) : "bounding box " + box_text(lo, hi)));
  }
}

}  // namespace cdmpm
