#!/usr/bin/python3
"""Independent check of the bulk eigenvalue bound of the time step (docs/time_step.md).

Assembles the lumped mass M and the stiffness K of uGIMP (theory E3-E5, plane strain) for a free
square block of N x N cells with ppc x ppc particles per cell, in numpy, and prints for several
Poisson ratios the largest eigenvalue of M^-1 K and the largest Gershgorin row sum, both in
units of (2 c_D / h)^2. rupture's bulk_eigen_bound (solver/time_step.cpp) computes the row sum;
the power iteration of tests/verification/test_time_step.cpp the eigenvalue on the code itself.
Usage: scripts/bulk_eigen_check.py [N] [ppc]   (Debian's python3-numpy)
"""
import sys

import numpy as np


def weight(d, h, lp):  # theory E3, uniform axis: (S, dS/dx_p)
    a = abs(d)
    if a < lp:
        return 1 - (d * d + lp * lp) / (2 * h * lp), -d / (h * lp)
    if a < h - lp:
        return 1 - a / h, -np.sign(d) / h
    if a < h + lp:
        return (h + lp - a) ** 2 / (4 * h * lp), -np.sign(d) * (h + lp - a) / (2 * h * lp)
    return 0.0, 0.0


def block(nu, n, ppc):
    h, lp = 1.0, 0.5 / ppc
    lam, mu = nu / ((1 + nu) * (1 - 2 * nu)), 1 / (2 * (1 + nu))  # E = 1
    C = np.array([[lam + 2 * mu, lam, 0], [lam, lam + 2 * mu, 0], [0, 0, mu]])
    axis = np.arange(-1, n + 2)  # nodes; GIMP tails reach one node past the edge
    na = len(axis)
    M, K = np.zeros(na * na), np.zeros((2 * na * na, 2 * na * na))
    vp = (h / ppc) ** 2
    for cx in range(n):
        for cy in range(n):
            for a in range(ppc):
                for b in range(ppc):
                    x, y = cx + (a + 0.5) / ppc, cy + (b + 0.5) / ppc
                    wx = np.array([weight(x - i, h, lp) for i in axis])
                    wy = np.array([weight(y - j, h, lp) for j in axis])
                    nodes = [(i, j) for i in range(na) for j in range(na) if wx[i, 0] * wy[j, 0] != 0 or
                             wx[i, 1] * wy[j, 0] != 0 or wx[i, 0] * wy[j, 1] != 0]
                    B = np.zeros((3, 2 * len(nodes)))
                    dofs = []
                    for k, (i, j) in enumerate(nodes):
                        M[i * na + j] += vp * wx[i, 0] * wy[j, 0]  # rho = 1
                        gx, gy = wx[i, 1] * wy[j, 0], wx[i, 0] * wy[j, 1]
                        B[:, 2 * k] = (gx, 0, gy)
                        B[:, 2 * k + 1] = (0, gy, gx)
                        dofs += [2 * (i * na + j), 2 * (i * na + j) + 1]
                    K[np.ix_(dofs, dofs)] += vp * B.T @ C @ B
    m = np.repeat(M, 2)
    keep = m > 1e-12
    Kk, mk = K[np.ix_(keep, keep)], m[keep]
    eig = np.linalg.eigvalsh(Kk / np.sqrt(np.outer(mk, mk)))[-1]
    rowsum = (np.abs(Kk).sum(axis=1) / mk).max()
    scale = 4 * (lam + 2 * mu)  # (2 c_D / h)^2 with rho = h = 1
    return eig / scale, rowsum / scale


if __name__ == "__main__":
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 10
    ppc = int(sys.argv[2]) if len(sys.argv) > 2 else 2
    for nu in (0.0, 0.25, 0.34, 0.45):
        e, r = block(nu, n, ppc)
        print(f"nu = {nu:.2f}: lambda_max = {e:.4f} (2 c_D/h)^2, Gershgorin row sum = {r:.4f} (2 c_D/h)^2")
