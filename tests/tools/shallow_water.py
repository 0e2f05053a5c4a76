#!/usr/bin/python3
"""shallow_water.py - a small depth-averaged solver, written only as a test oracle for the hand-off of a cdmpm
snapshot to a far-field model (docs/handoff.md): the linear shallow-water (long-wave) equations on a flat bed of
still depth h in one horizontal dimension,

    eta_t + q_x = 0,     q_t + g h eta_x = 0      (Stoker 1957, Water Waves, ch. 10; q = d u the discharge),

on a staggered grid (eta at the points x_i, q at the faces between them, closed walls at both ends) stepped by
the forward-backward scheme (q first, then eta with the new q), which conserves volume exactly, is second-order
accurate and neutrally stable for c dt / dx <= 1, c = sqrt(g h) (Mesinger & Arakawa 1976, GARP 17, ch. 4).

    propagate(x, eta0, q0, h, t0, times, gauges) -> eta at the gauges at the given times

and d'Alembert's exact solution of the same equations on an unbounded flat bed, the solver's own check:
eta(x, t) = 1/2 [eta0 + q0/c](x - c t) + 1/2 [eta0 - q0/c](x + c t).
"""
import numpy as np

G = 9.81


def propagate(x, eta0, q0, h, t0, times, gauges, courant=0.5, g=G):
    """eta [len(times), len(gauges)] at the gauge positions (linear interpolation between points), for eta0 and q0
    given at the equally spaced points x at time t0; times >= t0."""
    x = np.asarray(x, dtype=float)
    dx = x[1] - x[0]
    c = np.sqrt(g * h)
    eta = np.asarray(eta0, dtype=float).copy()
    q = 0.5 * (np.asarray(q0[1:], dtype=float) + np.asarray(q0[:-1], dtype=float))  # at the faces x_i + dx/2
    times = np.asarray(times, dtype=float)
    steps = int(np.ceil((times.max() - t0) / (courant * dx / c))) if times.max() > t0 else 0
    dt = (times.max() - t0) / steps if steps else 0.0
    record_t, record = [t0], [np.interp(gauges, x, eta)]
    for n in range(steps):
        q -= dt * g * h * np.diff(eta) / dx
        flux = np.concatenate(([0.0], q, [0.0]))  # walls: no flux through the ends
        eta -= dt * np.diff(flux) / dx
        record_t.append(t0 + (n + 1) * dt)
        record.append(np.interp(gauges, x, eta))
    record = np.array(record)
    return np.array([[np.interp(t, record_t, record[:, j]) for j in range(len(gauges))] for t in times])


def dalembert(x, eta0, q0, h, dt, points, g=G):
    """The exact solution at `points` a time dt after (eta0, q0) on an unbounded flat bed (still water outside x)."""
    c = np.sqrt(g * h)
    right = 0.5 * (np.asarray(eta0) + np.asarray(q0) / c)
    left = 0.5 * (np.asarray(eta0) - np.asarray(q0) / c)
    return np.interp(points - c * dt, x, right, left=0, right=0) + np.interp(points + c * dt, x, left, left=0, right=0)
