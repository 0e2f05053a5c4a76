// progress.h - the progress line of a run on stderr (every 2 s, and at the end): step, time, dt, particles,
// particle-steps per second and the estimated wall time left, then `extra` (a distributed run: the particle
// imbalance); rewritten in place on a terminal.
#pragma once

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

namespace cdmpm {

inline std::string format_duration(double s) {
  if (!std::isfinite(s) || s < 0) return "--:--:--";
  char buf[32];
  const long t = std::lround(s);
  std::snprintf(buf, sizeof buf, "%02ld:%02ld:%02ld", t / 3600, (t / 60) % 60, t % 60);
  return buf;
}

class Progress {
 public:
  Progress(bool enabled, double t_begin, double end) : enabled_(enabled), tty_(isatty(fileno(stderr))), t_begin_(t_begin), end_(end) {}
  bool tty() const { return tty_; }
  // The simulated time the run starts from (the remaining-time estimate extrapolates from it).
  void start_at(double t_begin) {
    t_begin_ = t_begin;
    last_ = std::chrono::steady_clock::now();
  }
  // Prints the line if enabled and (unless final) 2 s have passed since the last one.
  void update(long long step, double t, double dt, size_t particles, double particle_steps, double wall, bool final,
              const std::string& extra = "") {
    if (!enabled_ || (!final && std::chrono::steady_clock::now() - last_ < std::chrono::seconds(2))) return;
    last_ = std::chrono::steady_clock::now();
    const double rate = particle_steps / std::max(wall, 1e-9);
    const double left = (end_ - t) / std::max(t - t_begin_, 1e-300) * wall;
    std::fprintf(stderr, "%sstep %lld  t = %.5g / %.5g s  dt = %.3e s  particles %zu  %.3g particle-steps/s  left %s%s%s",
                 tty_ ? "\r" : "", step, t, end_, dt, particles, rate, format_duration(left).c_str(), extra.c_str(),
                 final || !tty_ ? "\n" : "   ");
  }

 private:
  bool enabled_, tty_;
  double t_begin_, end_;
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

}  // namespace cdmpm
