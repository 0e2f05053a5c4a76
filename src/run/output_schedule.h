// output_schedule.h - output times (frames, probe samples) on a regular grid, which the time loop lands on
// exactly (Simulation::step_until).
//
// The event after the one with index k is at origin + (k + 1 - origin_index) dt (origin 0, origin_index 0 for a
// fresh run, so the times are exactly (k + 1) dt). A resumed run keeps that grid when its interval is the one
// the checkpoint was written with; with another interval (a --set of time.frame_interval or probes.interval on
// --resume) the grid starts again at the resume time t, as the old grid would put the next event in the past
// (a negative step) or more than two intervals ahead.
#pragma once

namespace cdmpm {

struct OutputSchedule {
  double dt, origin = 0;
  long long origin_index = 0;
  double after(long long k) const { return origin + double(k + 1 - origin_index) * dt; }
  // The time of the event after k, no later than `end` (a grid time within 1e-9 dt of end is end itself, so
  // rounding of the grid cannot put a separate event a hair before the last one).
  double next(long long k, double end) const {
    const double t = after(k);
    return t > end - 1e-9 * dt ? end : t;
  }
  void resume_at(double t, long long k) {
    const double n = after(k);
    if (!(n > t && n <= t + 2 * dt)) {
      origin = t;
      origin_index = k;
    }
  }
};

}  // namespace cdmpm
