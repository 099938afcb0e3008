#!/usr/bin/env python3
# Copyright (C) 2026 The lafortune developers
# SPDX-License-Identifier: GPL-3.0-or-later
#
# bench_fit_scipy.py: the peer of lafortune_fit in `make bench` (run by
# scripts/bench_fit.m, not a dependency of the package).  Fits the same
# isotropic Lafortune model, per RGB channel, with
# scipy.optimize.least_squares (method "lm": MINPACK's Levenberg-Marquardt)
# and an analytic Jacobian, from lafortune_fit's "plain" start
# (rho_d = 0.1, lobe k: Cxy = -1, Cz = 1, e = 10 k).
#
# usage: bench_fit_scipy.py TABLE LOBES REPS
#   TABLE  text file, one sample per row: sxy sz r g b
#          (sxy = ux vx + uy vy, sz = uz vz)
#   LOBES  largest lobe count (fits 1 .. LOBES)
#   REPS   repetitions; the median times are printed
# prints one line per lobe count:
#   lobes wall_seconds rmse_r rmse_g rmse_b nfev(total) cpu_seconds
# (times for all 3 channels; cpu = this process's processor time)
# or one line "skipped: <reason>" when scipy is absent.

import sys
import time

try:
    import numpy as np
    from scipy.optimize import least_squares
except ImportError as err:
    print("skipped: scipy is absent (%s); install Debian's python3-scipy" % err)
    sys.exit(0)

LOGMAX = 300.0
REALMIN = np.finfo(float).tiny


def model(p, sxy, sz, jac=False):
    """The model as inst/private/lafortune_core.m evaluates it."""
    n = sxy.size
    nl = (p.size - 1) // 3
    f = np.full(n, p[0] / np.pi)
    J = np.empty((n, p.size)) if jac else None
    if jac:
        J[:, 0] = 1.0 / np.pi
    for k in range(nl):
        cxy, cz, e = p[3 * k + 1], p[3 * k + 2], p[3 * k + 3]
        b = cxy * sxy + cz * sz
        on = b > 0
        lb = np.log(np.maximum(b, REALMIN))
        if e == 0:
            L = on.astype(float)
        else:
            t = e * lb
            L = np.exp(np.clip(t, -700.0, LOGMAX)) * on
        f += L
        if jac:
            if e == 0:
                dLdb = np.zeros(n)
                dLde = lb * on
            else:
                live = on & (t <= LOGMAX)
                dLdb = e * np.exp(np.clip(t - lb, -700.0, LOGMAX)) * live
                dLde = L * lb * live
            J[:, 3 * k + 1] = dLdb * sxy
            J[:, 3 * k + 2] = dLdb * sz
            J[:, 3 * k + 3] = dLde
    return f, J


def plain_start(nlobes):
    p = np.zeros(1 + 3 * nlobes)
    p[0] = 0.1
    for k in range(nlobes):
        p[3 * k + 1:3 * k + 4] = [-1.0, 1.0, 10.0 * (k + 1)]
    return p


def fit_channel(sxy, sz, y, nlobes):
    res = lambda p: model(p, sxy, sz)[0] - y
    jac = lambda p: model(p, sxy, sz, True)[1]
    r = least_squares(res, plain_start(nlobes), jac=jac, method="lm")
    return r.x, r.nfev


def main():
    if len(sys.argv) != 4:
        print("usage: bench_fit_scipy.py TABLE LOBES REPS", file=sys.stderr)
        sys.exit(2)
    T = np.loadtxt(sys.argv[1], ndmin=2)
    if T.shape[1] != 5:
        print("bench_fit_scipy.py: TABLE must have 5 columns, got %d" % T.shape[1],
              file=sys.stderr)
        sys.exit(2)
    sxy, sz, rgb = T[:, 0].copy(), T[:, 1].copy(), T[:, 2:5]
    lobes, reps = int(sys.argv[2]), int(sys.argv[3])
    for k in range(1, lobes + 1):
        wall, cpu = [], []
        for _ in range(reps):
            t0 = time.perf_counter()
            c0 = time.process_time()
            out = [fit_channel(sxy, sz, rgb[:, c].copy(), k) for c in range(3)]
            cpu.append(time.process_time() - c0)
            wall.append(time.perf_counter() - t0)
        best, cbest = np.median(wall), np.median(cpu)
        rmse = [np.sqrt(np.mean((model(p, sxy, sz)[0] - rgb[:, c]) ** 2))
                for c, (p, _) in enumerate(out)]
        nfev = sum(n for _, n in out)
        print("%d %.6f %.17g %.17g %.17g %d %.6f" % (k, best, rmse[0], rmse[1], rmse[2], nfev, cbest))


if __name__ == "__main__":
    main()
