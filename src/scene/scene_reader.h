// scene_reader.h - the checks every part of a scene is read with: a json value with its path, and a reader
// that checks keys, types and ranges, so every message has the form
//   <file>: <json.path>: expected <what>, got <value>
// The scene loader (scene_loader.cpp) reads the top-level sections with it; each material model, boundary,
// shape and probe reads its own keys with it (material/*.h, boundary/*.cpp, shape/*.h, probe/*.cpp), so a
// new kind of any of them brings its own validation and the messages stay uniform.
#pragma once

#include <array>
#include <limits>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

namespace cdmpm {

// Every problem found in a scene: the program reports it and exits with code 2, writing nothing.
struct SceneError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

using Strings = std::vector<std::string>;

// Interval of allowed numbers, open or closed at each end.
struct Range {
  static constexpr double inf = std::numeric_limits<double>::infinity();
  double lo = -inf, hi = inf;
  bool lo_open = false, hi_open = false;
  bool contains(double v) const { return (lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi); }
  std::string describe() const;
};
inline Range gt(double lo) { return {lo, Range::inf, true, false}; }
inline Range ge(double lo) { return {lo, Range::inf, false, false}; }

// A json value together with its path in the scene ("bodies[0].shape.min").
struct Node {
  const nlohmann::json& j;
  std::string path;
  std::string child(const std::string& key) const { return path.empty() ? key : path + "." + key; }
  bool has(const std::string& key) const { return j.contains(key); }
  Node operator[](const std::string& key) const { return {j.at(key), child(key)}; }
  Node operator[](size_t i) const { return {j.at(i), path + "[" + std::to_string(i) + "]"}; }
};

std::string format_number(double v);
std::string join(const Strings& items, bool quote = false);
bool contains(const Strings& items, const std::string& s);
// Letters, digits and '_' only (usable as a CSV column and as a --set path component).
bool is_identifier(const std::string& s);

class SceneReader {
 public:
  SceneReader(std::string file, int dim) : file_(std::move(file)), dim_(dim) {}
  const std::string& file() const { return file_; }
  int dim() const { return dim_; }
  // The domain extent, once the domain section is read (used by inside()).
  void set_domain(std::vector<double> size) { domain_ = std::move(size); }
  const std::vector<double>& domain() const { return domain_; }

  [[noreturn]] void fail(const std::string& path, const std::string& msg) const;
  [[noreturn]] void expected(const Node& n, const std::string& what) const;
  // `n` must be an object whose keys are all in `allowed`.
  void object(const Node& n, const Strings& allowed) const;
  Node required(const Node& n, const std::string& key) const;
  // `n` must be an array of at least min_size entries; returns its size.
  size_t array(const Node& n, size_t min_size, const std::string& what) const;
  double number(const Node& n, Range r = {}, const std::string& note = "") const;
  double number(const Node& parent, const std::string& key, Range r, double fallback) const;
  int integer(const Node& n, Range r) const;
  bool boolean(const Node& n) const;
  bool boolean(const Node& parent, const std::string& key, bool fallback) const;
  std::string string(const Node& n, const Strings& choices = {}) const;
  std::vector<double> numbers(const Node& n, size_t count, Range r = {}) const;
  std::vector<std::array<double, 2>> pairs(const Node& n, size_t min_count) const;
  // Reads "min" and "max" of `n` (dim numbers each) and checks min < max on every axis.
  void min_max(const Node& n, std::vector<double>& lo, std::vector<double>& hi) const;
  // Checks that the first lo.size() coordinates of the box [lo, hi] lie inside the domain.
  void inside(const Node& n, const std::vector<double>& lo, const std::vector<double>& hi,
              const std::string& what) const;

 private:
  std::string file_;
  int dim_;
  std::vector<double> domain_;
};

}  // namespace cdmpm
