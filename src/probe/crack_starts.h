// crack_starts.h - the crack-start record: where and how ice first breaks.
//
// An event is recorded when a breakable particle's damage (material/ice.h: d = 1 - p0(alpha) / p0_initial)
// crosses output.icebergs.damage_threshold in a step: below it before the constitutive update, at or above it
// after. Each event holds the step, the time at the end of that step, the particle id and position, and the
// Cauchy stress state after the update (sigma = tau / det F_e):
//   p = -tr(sigma) / d,  q = sqrt(3/2) |dev sigma|  (in 3D the invariants of material/cohesive_cam_clay.h; in 2D those
//   of the in-plane 2x2 stress, a record of the plane's stress: the yield surface of plane-strain ice sees the 3x3
//   state, sigma_zz included),  sigma_1 = the largest principal stress (positive in tension).
// MODE. The Cam Clay return mapping softens only on the tensile side of its ellipse (p below the centre
// p_c = (1 - beta) p0 / 2, or at the tensile tip), so "which side softened it" cannot tell tension from shear:
// a simple shear (p = 0 < p_c) softens on that side too. The rule is the stress triaxiality eta = -p / q
// (positive in tension) of the state that broke, against its value in the two reference tests:
//   pure shear:          p = 0                          => eta = 0,
//   uniaxial tension:    tau = diag(sigma, 0(, 0))      => eta_t = 1/sqrt(3) in 2D (p = -sigma/2,
//                        q = sqrt(3)/2 sigma), 1/3 in 3D (p = -sigma/3, q = sigma);
//   the tensile tip:     q = 0, p < 0                   => eta = +infinity.
//   mode = "tension" if eta >= eta_t / 2 (i.e. -p >= q eta_t / 2), else "shear".
// The dividing line lies halfway between the two reference states; in 2D it is sigma_2 = -sigma_1 / 3
// (principal stresses sigma_1 >= sigma_2). A bending crack (top fibre in uniaxial tension) is "tension", the
// shear crack at a support (near the neutral axis, p ~ 0) is "shear"; compression-side shear (p > 0) is "shear".
// BOUNDED AND DEDUPLICATED. At most `capacity` events are kept, the first crossing in each grid cell (the cell
// of the particle's position at the crossing, cell size dx): later crossings in a cell that already holds an
// event are not kept, so a damaged strip that keeps breaking at one place (e.g. the ice passing a bed edge)
// holds a few cells, and a crack running through new ice records its path, one event per cell. Once full, the
// record costs nothing more.
// DETERMINISTIC. The crossings of a step are found in parallel, collected per thread, then sorted by particle id
// and kept in that order (a distributed run first concatenates every rank's crossings); steps are in order. The
// record is the same for any thread count and rank count, and it is saved in the
// checkpoint (save / load), so a resumed run continues it.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <ostream>
#include <string>
#include <vector>

#include <Eigen/Eigenvalues>

#include "core/particles.h"
#include "material/stress.h"
#include "parallel/reduction.h"

namespace cdmpm {

enum class CrackMode : int { tension = 0, shear = 1 };

inline const char* crack_mode_name(CrackMode m) { return m == CrackMode::tension ? "tension" : "shear"; }

// Triaxiality of uniaxial tension in the invariants of material/cohesive_cam_clay.h.
inline double uniaxial_tension_triaxiality(int dim) { return dim == 2 ? 1 / std::sqrt(3.0) : 1.0 / 3; }

// The mode rule (see the header): tension iff -p >= q eta_t / 2.
inline CrackMode crack_mode(double p, double q, int dim) {
  return -p >= 0.5 * uniaxial_tension_triaxiality(dim) * q ? CrackMode::tension : CrackMode::shear;
}

template <int dim>
struct CrackStart {
  long long step = 0;
  double time = 0;
  uint64_t id = 0;
  Vec<dim> x = Vec<dim>::Zero();
  double p = 0, q = 0, sigma_1 = 0;
  CrackMode mode = CrackMode::tension;

  static constexpr size_t doubles = 7 + dim;  // size of one event in save()
};

// p, q and the largest principal value of a Cauchy stress.
template <int dim>
inline void stress_state(const Mat<dim>& s, double& p, double& q, double& sigma_1) {
  const double tr = s.trace();
  p = -tr / dim;
  q = std::sqrt(1.5) * (s - (tr / dim) * Mat<dim>::Identity()).norm();
  if constexpr (dim == 2) {
    const double h = 0.5 * (s(0, 0) - s(1, 1));
    sigma_1 = 0.5 * tr + std::sqrt(h * h + double(s(0, 1)) * s(0, 1));
  } else {
    sigma_1 = Eigen::SelfAdjointEigenSolver<Mat<dim>>(s, Eigen::EigenvaluesOnly).eigenvalues()(dim - 1);
  }
}

template <int dim>
class CrackStartRecord {
 public:
  static constexpr size_t capacity = 64;

  // Active when a material is breakable (ice); threshold = output.icebergs.damage_threshold; dx = cell size.
  void configure(const std::vector<Material>& materials, Real threshold, Real dx) {
    active_ = std::any_of(materials.begin(), materials.end(), [](const Material& m) { return m.traits().breakable; });
    threshold_ = threshold;
    dx_ = dx;
  }
  bool active() const { return active_; }
  bool full() const { return events_.size() >= capacity; }
  const std::vector<CrackStart<dim>>& events() const { return events_; }

  // Before the constitutive update: remember alpha (the damage variable) of the solids.
  void before_update(const Particles<dim>& P) {
    if (active_ && !full()) alpha_.assign(P.alpha.begin(), P.alpha.end());
  }

  // After it: the crossings of this step (see the header). step and time are those at the end of the step.
  void after_update(const Particles<dim>& P, const std::vector<Material>& materials, long long step, double time) {
    if (!active_ || full()) return;
    const size_t ns = std::min(P.solid_count(), alpha_.size());
    std::vector<CrackStart<dim>> found;
#pragma omp parallel
    {
      std::vector<CrackStart<dim>> mine;
#pragma omp for schedule(static) nowait
      for (size_t k = 0; k < ns; ++k) {
        const Material& m = materials[P.material[k]];
        if (!m.traits().breakable || !(damage_at(m, alpha_[k]) < threshold_) || !(particle_damage(m, P, k) >= threshold_))
          continue;
        CrackStart<dim> e;
        e.step = step;
        e.time = time;
        e.id = P.id[k];
        e.x = P.x[k];
        stress_state<dim>(cauchy_stress(m, P, k), e.p, e.q, e.sigma_1);
        e.mode = crack_mode(e.p, e.q, dim);
        mine.push_back(e);
      }
#pragma omp critical(cdmpm_crack_starts)
      found.insert(found.end(), mine.begin(), mine.end());
    }
    global::concatenate(found);  // a distributed run: every rank's crossings of this step (parallel/reduction.h)
    std::sort(found.begin(), found.end(), [](const CrackStart<dim>& a, const CrackStart<dim>& b) { return a.id < b.id; });
    for (const CrackStart<dim>& e : found) {
      if (full()) break;
      if (std::none_of(events_.begin(), events_.end(), [&](const CrackStart<dim>& o) { return same_cell(o.x, e.x); }))
        events_.push_back(e);
    }
  }

  // Checkpoint form: per event (step, time, id, x[dim], p, q, sigma_1, mode).
  std::vector<double> save() const {
    std::vector<double> v;
    for (const CrackStart<dim>& e : events_) {
      v.insert(v.end(), {double(e.step), e.time, double(e.id)});
      for (int a = 0; a < dim; ++a) v.push_back(e.x[a]);
      v.insert(v.end(), {e.p, e.q, e.sigma_1, double(static_cast<int>(e.mode))});
    }
    return v;
  }
  // False (record unchanged) if v is not a record of this dimension: wrong length, too many events, a
  // non-finite value or a mode other than 0 / 1.
  bool load(const std::vector<double>& v) {
    const size_t n = CrackStart<dim>::doubles;
    if (v.size() % n != 0 || v.size() / n > capacity) return false;
    if (!std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); })) return false;
    std::vector<CrackStart<dim>> events;
    for (size_t k = 0; k < v.size(); k += n) {
      CrackStart<dim> e;
      e.step = static_cast<long long>(v[k]);
      e.time = v[k + 1];
      e.id = static_cast<uint64_t>(v[k + 2]);
      for (int a = 0; a < dim; ++a) e.x[a] = static_cast<Real>(v[k + 3 + a]);
      e.p = v[k + 3 + dim];
      e.q = v[k + 4 + dim];
      e.sigma_1 = v[k + 5 + dim];
      const double mode = v[k + 6 + dim];
      if (mode != 0 && mode != 1) return false;
      e.mode = static_cast<CrackMode>(static_cast<int>(mode));
      events.push_back(e);
    }
    events_ = std::move(events);
    return true;
  }

  static std::string csv_header() {
    return std::string("step,time,id,x,y") + (dim == 3 ? ",z" : "") + ",p,q,sigma_1,mode";
  }
  void write_csv(std::ostream& os) const {
    os.precision(10);
    os << csv_header() << '\n';
    for (const CrackStart<dim>& e : events_) {
      os << e.step << ',' << e.time << ',' << e.id;
      for (int a = 0; a < dim; ++a) os << ',' << e.x[a];
      os << ',' << e.p << ',' << e.q << ',' << e.sigma_1 << ',' << crack_mode_name(e.mode) << '\n';
    }
  }

 private:
  static Real damage_at(const Material& m, Real alpha) {
    return m.visit([&](const auto& model) {
      if constexpr (requires { model.damage(alpha); }) return model.damage(alpha);
      else return Real(0);
    });
  }
  bool same_cell(const Vec<dim>& a, const Vec<dim>& b) const {
    for (int k = 0; k < dim; ++k)
      if (std::floor(a[k] / dx_) != std::floor(b[k] / dx_)) return false;
    return true;
  }

  bool active_ = false;
  Real threshold_ = Real(0.5), dx_ = 1;
  std::vector<Real> alpha_;
  std::vector<CrackStart<dim>> events_;
};

}  // namespace cdmpm
