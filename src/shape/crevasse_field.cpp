// crevasse_field.cpp - surface crevasses from seeded simplex noise (crevasse_field.h).
#include "shape/crevasse_field.h"

#include <algorithm>
#include <cmath>

namespace cdmpm {
namespace {

// The positions' noise gets its own permutation: the seed moved by a fixed odd constant.
constexpr uint64_t kPositionSeedOffset = 0x632BE59BD9B4E019ULL;
constexpr double kMaxSamples = 1e6;

}  // namespace

CrevasseField CrevasseField::parse(const SceneReader& r, const Node& n, const Shape& shape) {
  if (!n.j.is_object()) r.expected(n, "an object");
  const int dim = r.dim();
  Strings keys = {"seed", "spacing", "spacing_std", "depth", "depth_std", "width", "region", "surface", "max_depth",
                  "water_depth", "water_material"};
  if (dim == 3) keys.push_back("length");
  r.object(n, keys);
  CrevasseField c;
  c.dim = dim;
  c.seed = static_cast<uint64_t>(r.integer(r.required(n, "seed"), ge(0)));
  c.spacing = r.number(r.required(n, "spacing"), gt(0));
  c.width = r.number(r.required(n, "width"), {0, c.spacing, true, true}, " (0 < width < spacing)");
  c.spacing_std = r.number(n, "spacing_std", ge(0), 0.0);
  const int up = dim - 1;
  c.x_min = shape.lower(0);
  c.x_max = shape.upper(0);
  if (n.has("region")) {
    Node reg = n["region"];
    const auto v = r.numbers(reg, 2);
    if (!(v[0] < v[1])) r.expected(reg, "[x_min, x_max] with x_min < x_max [m]");
    r.inside(reg, {v[0]}, {v[1]}, "a crevasse region");
    c.x_min = v[0];
    c.x_max = v[1];
  }
  if (c.x_max - c.x_min < c.spacing)
    r.expected(n["spacing"], "a spacing at most the length of the region (" + format_number(c.x_max - c.x_min) +
                                 " m) [m]");
  if (n.has("surface")) c.surface = r.number(n["surface"], gt(shape.lower(up)), " (above the body's bottom)");
  const double height = (c.surface ? *c.surface : shape.upper(up)) - shape.lower(up);
  c.max_depth = r.number(n, "max_depth", {0, height, true, true}, 0.9 * height);  // below the body's height
  c.depth = r.number(r.required(n, "depth"), {0, c.max_depth}, " (0 <= depth <= max_depth = " +
                                                                 format_number(c.max_depth) + " m)");
  c.depth_std = r.number(n, "depth_std", ge(0), 0.0);
  if (dim == 3) {
    c.y_min = shape.lower(1);
    c.y_max = shape.upper(1);
    c.length = r.number(n, "length", gt(0), 5 * c.spacing);
  }
  c.water_depth = r.number(n, "water_depth", {0, c.max_depth, false, false}, 0.0);
  // water_material is required with water; a dry field may name it too (a scene whose crevasse water is a parameter).
  if (c.water_depth > 0 || n.has("water_material")) c.water_material = r.string(r.required(n, "water_material"));
  // A bound on the work and on crevasses.csv (a spacing or length far below the particle spacing is a mistake).
  const double samples = std::floor((c.x_max - c.x_min) / c.spacing) * static_cast<double>(c.station_ys().size());
  if (samples > kMaxSamples)
    r.fail(n.path, "expected at most " + format_number(kMaxSamples) + " crevasses (times stations along y in 3D), got " +
                       format_number(samples) + ": use a larger spacing" + (dim == 3 ? " or length" : ""));
  c.realise();
  return c;
}

double CrevasseField::sample(const SimplexNoise& noise, int i, double y) const {
  const double v = dim == 3 ? y / length : 0.0;
  return noise(1.9 * i + 0.37, v + 0.61);
}

std::vector<double> CrevasseField::station_ys() const {
  if (dim != 3) return {0.0};
  const double extent = y_max - y_min;
  const int m = std::max(1, static_cast<int>(std::ceil(extent / (0.25 * length))));
  std::vector<double> ys(m);
  for (int j = 0; j < m; ++j) ys[j] = y_min + (j + 0.5) * extent / m;
  return ys;
}

void CrevasseField::realise() {
  depth_noise_ = SimplexNoise(seed);
  position_noise_ = SimplexNoise(seed + kPositionSeedOffset);
  count_ = static_cast<int>(std::floor((x_max - x_min) / spacing));
  // Sample mean and standard deviation of both noises over every crevasse and station, summed serially in a
  // fixed order (the same bits on every thread count).
  const std::vector<double> ys = station_ys();
  double sd = 0, sdd = 0, sp = 0, spp = 0;
  for (int i = 0; i < count_; ++i)
    for (double y : ys) {
      const double a = sample(depth_noise_, i, y), b = sample(position_noise_, i, y);
      sd += a, sdd += a * a, sp += b, spp += b * b;
    }
  const double n = static_cast<double>(count_) * static_cast<double>(ys.size());
  mean_d_ = sd / n;
  mean_p_ = sp / n;
  const double var_d = sdd / n - mean_d_ * mean_d_, var_p = spp / n - mean_p_ * mean_p_;
  // A single sample (one crevasse in 2D) has no spread: it takes the mean depth and no offset.
  std_d_ = var_d > 0 ? std::sqrt(var_d) : 0;
  std_p_ = var_p > 0 ? std::sqrt(var_p) : 0;
}

double CrevasseField::raw_offset(int i, double y) const {
  if (std_p_ == 0) return 0;
  return spacing_std / std::sqrt(2.0) * (sample(position_noise_, i, y) - mean_p_) / std_p_;
}

double CrevasseField::raw_depth(int i, double y) const {
  if (std_d_ == 0) return depth;
  return depth + depth_std * (sample(depth_noise_, i, y) - mean_d_) / std_d_;
}

double CrevasseField::centre(int i, double y) const {
  const double reach = 0.5 * (spacing - width);
  const double nominal = 0.5 * (x_min + x_max) + (i - 0.5 * (count_ - 1)) * spacing;
  return nominal + std::clamp(raw_offset(i, y), -reach, reach);
}

double CrevasseField::depth_at(int i, double y) const { return std::clamp(raw_depth(i, y), 0.0, max_depth); }

double CrevasseField::cut_depth(double x, double y) const {
  const double k = (x - 0.5 * (x_min + x_max)) / spacing + 0.5 * (count_ - 1);
  const int nearest = static_cast<int>(std::lround(k));
  for (int i = std::max(0, nearest - 1); i <= std::min(count_ - 1, nearest + 1); ++i)
    if (std::abs(x - centre(i, y)) < 0.5 * width) return depth_at(i, y);
  return 0;
}

std::vector<CrevasseField::Station> CrevasseField::stations() const {
  std::vector<Station> out;
  const double reach = 0.5 * (spacing - width);
  for (int i = 0; i < count_; ++i)
    for (double y : station_ys()) {
      const double d = raw_depth(i, y), e = raw_offset(i, y);
      out.push_back({i, y, centre(i, y), depth_at(i, y), d < 0 || d > max_depth || std::abs(e) > reach});
    }
  return out;
}

std::string CrevasseField::csv_header(int dim) {
  return dim == 3 ? "body,crevasse,y,x,depth,width,clipped,water_depth" : "body,crevasse,x,depth,width,clipped,water_depth";
}

void CrevasseField::write_csv(std::ostream& out, size_t body) const {
  for (const Station& s : stations()) {
    out << body << ',' << s.crevasse << ',';
    if (dim == 3) out << s.y << ',';
    out << s.x << ',' << s.depth << ',' << width << ',' << (s.clipped ? 1 : 0) << ',' << std::min(water_depth, s.depth) << '\n';
  }
}

}  // namespace cdmpm
