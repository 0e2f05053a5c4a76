"""scaling_projection.py - the projection of strong and weak scaling of a distributed run to 8, 64 and 512 ranks
of a 32-core node (docs/performance.md, "Scaling"), from the figures measured on this machine. The model of one
step on P ranks (one rank per node, OpenMP inside): compute (N/P) / (r_core * 32 * e_omp), times (1 + f_dist + 0.4
min(1, boundary/own)) for the measured overhead of a distributed step and the boundary bins that p2g scatters twice;
halo: a rank sends the patches of one cross-section of blocks and receives their velocities over a 100 Gb/s link;
collectives: 4 all-to-all exchanges ((P - 1) messages of 2 us each) and 6 reductions (2 log2 P latencies) a step.
The partition is a slab decomposition (contiguous ranges of the row-major block order, x slowest), so a rank's
boundary is one y-z cross-section whatever P.

    /usr/bin/python3 tools/scaling_projection.py
"""
r_core = 0.6e6          # measured particle-steps/s per core here (loaded)
f_dist = 0.04           # measured: 2 ranks x 1 thread per step 4 % slower than 1 x 2 (median stepping rates)
cores = 32; e_omp = 0.8 # OpenMP efficiency within a 32-core node (assumed)
R_node = r_core * cores * e_omp
ppc = 8; bw = 12.5e9; lat = 2e-6  # bytes/s per node (100 Gb/s) and latency per message
patch = 6**3 * 32 + 4; vel = 4**3 * 24
n_alltoall = 4; n_allreduce = 6
def step(N, P, A_blocks):
    comp = N / P / R_node
    ratio = A_blocks * 4 * 4 * 4 * ppc / (N / P)  # boundary bins' particles / own particles (1 layer of blocks)
    if P > 1: comp *= 1 + f_dist + 0.4 * min(ratio, 1.0)  # boundary bins scattered twice (p2g is ~40 % of a step)
    halo = 0 if P == 1 else A_blocks * (patch + vel) / bw   # send own patches + receive velocities
    coll = 0 if P == 1 else n_alltoall * (P - 1) * lat + n_allreduce * 2 * lat * max(1, (P).bit_length())
    return comp, halo, coll
# strong: N = 100 M particles, a fjord box 8a x a x a cells (slab decomposition across x, the slowest axis)
N = 100e6
cells = N / ppc
a = (cells / 8) ** (1 / 3)
A = (a / 4) ** 2  # blocks in a y-z cross-section
print(f"strong: N = {N:.3g}, box {8*a:.0f} x {a:.0f} x {a:.0f} cells, cross-section {A:.0f} blocks, {(8*a)/4:.0f} block layers")
t1 = sum(step(N, 1, A))
for P in (1, 8, 64, 512):
    c, h, k = step(N, P, A)
    t = c + h + k
    layers = 8 * a / 4 / P
    print(f"P={P:4d}: compute {c*1e3:8.2f} ms, halo {h*1e3:6.3f} ms, collectives {k*1e3:6.3f} ms, step {t*1e3:8.2f} ms, "
          f"speed-up {t1/t:6.1f}, efficiency {t1/t/P:5.2f}, block layers per rank {layers:5.2f}, halo/own data {A*4*4*4*ppc/(N/P):.2f}")
# weak: 12.5 M particles per node, the box grows along x (cross-section fixed)
n = 12.5e6
a = ((n / ppc) / 8) ** (1 / 3)
A = (a / 4) ** 2
t1 = sum(step(n, 1, A))
print(f"weak: {n:.3g} particles per node, cross-section {A:.0f} blocks")
for P in (1, 8, 64, 512):
    c, h, k = step(n * P, P, A)
    t = c + h + k
    print(f"P={P:4d}: N = {n*P:.3g}, step {t*1e3:8.2f} ms (compute {c*1e3:.2f}, halo {h*1e3:.3f}, collectives {k*1e3:.3f}), efficiency {t1/t:5.2f}")
