// capsize.h - the inviscid estimate of how fast a floating rectangular slab capsizes (2D, per unit length), the
// reference of the capsizing tests (tests/validation/test_capsize.cpp, docs/validation.md#capsizing-slabs).
//
// Hydrostatics. A slab of width w (horizontal when upright) and height h, density rho_b < rho_w, floats with the
// submerged area A = rho_b w h / rho_w. Turned by theta about its centre G, the waterline is the height at which
// the turned rectangle's area below it is A (found by bisection); the buoyancy acts at the centroid B of that
// part. The hydrostatic moment about G is
//   M(theta) = rho_w g A (x_B - x_G)   (counter-clockwise positive),
// exact at every angle (heave in equilibrium: the displacement held at the body's weight). Upright, the metacentric
// height is GM = w^2 / (12 d) - (h - d) / 2 with the draft d = rho_b h / rho_w (Archimedes; e.g. Newman, Marine
// Hydrodynamics, sec. 6.16); GM < 0, an unstable slab, for w / h < sqrt(6 (d/h) (1 - d/h)), 0.752 for ice (917)
// in sea water (1025).
//
// Dynamics. Roll with the body free to sway and the heave in equilibrium: no horizontal force acts on body and
// water together, so their horizontal momentum stays zero. The water's inertia is that of the double body (the
// submerged part and its mirror image above the waterline, a rectangle w x 2d centred on the waterline point O
// under G), which is the free surface's high-frequency limit (phi = 0 on it); half of its infinite-fluid added
// sway mass m_s and rotary inertia I_O belong to the floating body. With l = z_O - z_G the height of O above G,
// the kinetic energy 1/2 (m + m_s) u_G^2 + m_s l u_G w + 1/2 (I_G + I_O + m_s l^2) w^2 at zero total horizontal
// momentum (u_G = -m_s l w / (m + m_s)) gives the roll inertia
//   I_eff = I_G + I_O + m m_s l^2 / (m + m_s),   I_G = m (w^2 + h^2) / 12,   m = rho_b w h,
// and the equation of motion I_eff theta'' = M(theta), integrated from rest (RK4, fixed step).
// The double body's added mass and inertia are those of the ellipse of the same area and axis ratio (semi-axes
// a_x = s w / 2 across, a_z = s d along its long side, s = 2 / sqrt(pi)): in infinite fluid an ellipse has
// m_s = rho pi a_z^2 moving along x and I_O = rho pi (a_z^2 - a_x^2)^2 / 8 turning about its centre
// (Lamb, Hydrodynamics, arts. 71-72; Newman, table 4.2); halved for the floating body. Not included: the waves
// the roll radiates (damping), viscosity, the heave's own inertia, the change of the added inertia with angle.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

namespace cdmpm::capsize {

struct Slab {
  double width, height;      // w (horizontal when upright), h [m]
  double rho_body, rho_water;  // [kg/m^3]
  double g = 9.81;             // [m/s^2]

  double mass() const { return rho_body * width * height; }
  double draft() const { return rho_body / rho_water * height; }
  double submerged_area() const { return mass() / rho_water; }
  double metacentric_height() const {
    const double d = draft();
    return width * width / (12 * d) - (height - d) / 2;
  }
  // The slab's own roll inertia about G, I_G = m (w^2 + h^2) / 12.
  double body_inertia() const { return mass() * (width * width + height * height) / 12; }
  // Roll inertia about G with the water's added inertia (see the header).
  double roll_inertia() const {
    const double m = mass(), d = draft(), w = width, h = height, rw = rho_water;
    const double s = 2 / std::sqrt(std::numbers::pi);
    const double ax = s * w / 2, az = s * d;
    const double m_s = 0.5 * rw * std::numbers::pi * az * az;
    const double i_o = 0.5 * rw * std::numbers::pi * std::pow(az * az - ax * ax, 2) / 8;
    const double l = d - h / 2;  // the waterline point O above G
    return body_inertia() + i_o + m * m_s * l * l / (m + m_s);
  }

  // Area and first moments of the part of the slab turned by theta (about G = origin) below the height zw.
  std::array<double, 3> below(double theta, double zw) const {
    const double c = std::cos(theta), sn = std::sin(theta), hw = width / 2, hh = height / 2;
    std::vector<std::array<double, 2>> poly;
    const std::array<std::array<double, 2>, 4> corners{{{-hw, -hh}, {hw, -hh}, {hw, hh}, {-hw, hh}}};
    std::array<std::array<double, 2>, 4> p;
    for (int i = 0; i < 4; ++i) p[i] = {c * corners[i][0] - sn * corners[i][1], sn * corners[i][0] + c * corners[i][1]};
    for (int i = 0; i < 4; ++i) {  // Sutherland-Hodgman clip against z <= zw
      const auto& a = p[i];
      const auto& b = p[(i + 1) % 4];
      const bool ain = a[1] <= zw, bin = b[1] <= zw;
      if (ain) poly.push_back(a);
      if (ain != bin) {
        const double t = (zw - a[1]) / (b[1] - a[1]);
        poly.push_back({a[0] + t * (b[0] - a[0]), zw});
      }
    }
    double area = 0, mx = 0, mz = 0;
    for (size_t i = 0; i < poly.size(); ++i) {
      const auto& a = poly[i];
      const auto& b = poly[(i + 1) % poly.size()];
      const double cr = a[0] * b[1] - b[0] * a[1];
      area += cr / 2;
      mx += (a[0] + b[0]) * cr / 6;
      mz += (a[1] + b[1]) * cr / 6;
    }
    return {area, mx, mz};
  }

  // The hydrostatic moment about G at the angle theta [N m per m], counter-clockwise positive.
  double moment(double theta) const {
    const double target = submerged_area();
    const double r = std::hypot(width, height) / 2;
    double lo = -r, hi = r;
    for (int it = 0; it < 200; ++it) {
      const double mid = (lo + hi) / 2;
      (below(theta, mid)[0] < target ? lo : hi) = mid;
    }
    const auto a = below(theta, (lo + hi) / 2);
    return rho_water * g * a[0] * (a[1] / a[0]);
  }

  // Time for the slab released at rest at theta0 to reach theta1 (radians, same sign, |theta1| > |theta0|),
  // integrating I_eff theta'' = M(theta); infinity if it turns back or takes longer than t_max.
  double time_to(double theta0, double theta1, double t_max = 1e3) const {
    const double inertia = roll_inertia();
    const double dt = 1e-4 * std::sqrt(height / g);
    double th = theta0, om = 0, t = 0;
    const double sign = theta1 > theta0 ? 1 : -1;
    const auto acc = [&](double a) { return moment(a) / inertia; };
    while (sign * (theta1 - th) > 0) {
      const double k1t = om, k1o = acc(th);
      const double k2t = om + dt / 2 * k1o, k2o = acc(th + dt / 2 * k1t);
      const double k3t = om + dt / 2 * k2o, k3o = acc(th + dt / 2 * k2t);
      const double k4t = om + dt * k3o, k4o = acc(th + dt * k3t);
      const double th_new = th + dt / 6 * (k1t + 2 * k2t + 2 * k3t + k4t);
      const double om_new = om + dt / 6 * (k1o + 2 * k2o + 2 * k3o + k4o);
      if (sign * (theta1 - th_new) <= 0) return t + dt * (theta1 - th) / (th_new - th);
      th = th_new;
      om = om_new;
      t += dt;
      if (sign * om < 0 || t > t_max) return std::numeric_limits<double>::infinity();
    }
    return t;
  }
};

}  // namespace cdmpm::capsize
