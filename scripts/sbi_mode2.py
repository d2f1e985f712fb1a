#!/usr/bin/python3
"""An independent spectral boundary-integral (SBI) solver for a 2D in-plane (mode II) fault in a
homogeneous elastic full space with rate-and-state friction: the method of the TPV101/103-2D
references (uguca), written here from its equations, so that the references' own method can be
run on finer grids than the one stored (docs/faults.md, TPV103-2D).

Usage:  scripts/sbi_mode2.py tpv103|tpv101 CELL_M [END_S] [OUT.csv] [--tail full|static|cut]
                             [--tcut 100] [--check-kernel]
Needs numpy and scipy (Debian: python3-numpy, python3-scipy; mpmath only for --check-kernel).
Prints the rupture time (slip rate above 1 mm/s), peak slip rate and final slip at the stations
0, 2.5, 5, 7.5, 9, 12, 15, 18 km and the arrest position; OUT.csv gets the rupture-time profile
and OUT_stations.csv every step's time, slip (m), slip rate (m/s) and shear traction (Pa) at
each station.

Method (Geubelle & Rice 1995; Lapusta et al. 2000). The fault y = 0 is periodic in x over
L = 72 km. The shear traction is
    tau(x, t) = tau0 + dtau_nuc(x, t) + f(x, t) - mu / (2 c_s) V(x, t),
with the dynamic functional, per Fourier mode k of the slip delta,
    f_k(t) = -(mu |k| / 2) int_0^t C(|k| c_s t') delta_k(t - t') |k| c_s dt'.
The kernel C(T) is the inverse Laplace transform of G(s) - s, where G(s) = R(s) / (s^2 beta(s))
is the full space's mode II stiffness in the scaled Laplace variable s = p / (|k| c_s):
    R(s) = (2 + s^2)^2 - 4 alpha beta, alpha = sqrt(1 + s^2 / eta^2), beta = sqrt(1 + s^2),
eta = c_P / c_S (derived in the docs from the half-space y > 0 with the tangential displacement
delta/2 and no normal-traction change, which is the antisymmetry of mode II; G(0) = 2 (1 -
1/eta^2) = 1/(1 - nu) is the static stiffness and G(s) -> s the radiation damping).

The kernel in closed form. G(s) - s = (beta - s) + 3/beta + 4 (1/beta - alpha)/s^2, and term by
term (beta - s <-> J1(T)/T, 1/beta <-> J0(T), alpha - s/eta <-> J1(eta T)/T, 1/s^2 <-> T):
    C(T) = J1(T)/T + 3 J0(T) - 4 J0(eta T)/eta + 4 T [A(T) - A(eta T) - J1(T) + J1(eta T)],
with A(x) = int_0^x J0 and C(0) = 3.5 - 4/eta. It agrees with mpmath's numerical inversion
(Talbot; --check-kernel) to 3e-13 on 0 <= T <= 100 (the earlier version of this script tabulated
that inversion). Its tail is slow: C(T) ~ -J0(T) ~ -sqrt(2/(pi T)) cos(T - pi/4), so
int_0^T C oscillates about G(0) with the amplitude sqrt(2/(pi T)) (0.08 at T = 100):
int_0^100 C = 1.412 against G(0) = 1.333 (eta = 6000/3464).

The tail (--tail). Cut at T_cut (--tail cut, this script's earlier behaviour; uguca's tables
are cut at 100 too), each mode keeps, once |k| c_s t > T_cut, the stiffness int_0^T_cut C
(1.41) instead of G(0) (1.33): 6 % too stiff late in the run for the short waves (wavelengths
below about 2.6 km by 12 s at T_cut = 100). --tail full (the default) keeps the whole kernel and
every mode's whole history: no cut; the cost grows as the square of the number of steps (TPV103
to 12 s: 1 min at 100 m on 2 cores). --tail static keeps the kernel exact to T_cut and adds the
rest of its integral, G(0) - int_0^T_cut C, to the step that crosses T_cut (the convolution of
the slip rate with the step response G(0) - int_0^T C, cut there, as Lapusta et al. 2000): the
static stiffness is exact, but the slip-rate history older than T_cut / (|k| c_s) is left out,
and with this slowly decaying kernel that is not small. TPV103-2D at 100 m, slip at 9 s against
the converged reference (tests/data/validation/tpv103-2d-converged, 25 m) at 0 / 9 / 15 km and
the arrest (24.95 km there): full -0.1 / +0.5 / +2.5 %, 25.9 km; static +3.9 / +5.2 / +8.2 %,
27.7 km; cut +6.5 / +8.4 / +10.9 %, no arrest by 12 s (docs/faults.md, TPV103-2D).
uguca's in-plane kernels (H00, H01, H11, tabulated to T = 100) decay faster: with its tables
the static stiffness of the mode II combination, int H00 - ((2 - eta) + int H01)^2 / int H11 with
each integral to T = 100, is 1.3342, 0.07 % above G(0).

Time step: dt = 0.1 dx / c_S (uguca's choice). Each step, predictor-corrector (Heun): the slip
and the state move over dt with the slip rate V* (V_n, then (V_n + V_n+1)/2), the functional is
the convolution of the slip history with the kernel integrated over each step, and V_n+1 solves
    tau0 + dtau_nuc + f - mu/(2 c_s) V = sigma a asinh[V / (2 V0) exp(psi / a)]
(monotone in V: bisection in log V, then Newton). State: flash heating (slip law with strong
rate weakening, TPV103) or the aging law (TPV101), each integrated exactly for a constant V
over the step.
"""
import math
import os
import sys

import numpy as np

RHO, CP, CS = 2670.0, 6000.0, 3464.0
MU = RHO * CS * CS
SIGMA, TAU0 = 120e6, 40e6
V0, F0 = 1e-6, 0.6
L_PERIOD = 72e3


def int_j0(x):
    """A(x) = int_0^x J0, elementwise for x >= 0. scipy's itj0y0 is off by up to 5e-10 near
    x = 20, where it changes method (the kernel multiplies A by 4 T), so below 40: 16-point
    Gauss-Legendre on pieces 0.05 wide (1e-15)."""
    from scipy import special as sp
    x = np.asarray(x, dtype=float)
    out = np.array(sp.itj0y0(x)[0], dtype=float)
    low = x < 40.0
    if np.any(low):
        g, w = np.polynomial.legendre.leggauss(16)
        h = 0.05
        edges = np.arange(0.0, 40.0 + h, h)
        mids = 0.5 * (edges[1:] + edges[:-1])
        pieces = (0.5 * h * w[None, :] * sp.j0(mids[:, None] + 0.5 * h * g[None, :])).sum(1)
        A_edge = np.concatenate([[0.0], np.cumsum(pieces)])
        xl = x[low]
        i = np.minimum((xl / h).astype(int), edges.size - 1)
        a = edges[i]
        part = (0.5 * (xl - a)[:, None] * w[None, :]
                * sp.j0(0.5 * (a + xl)[:, None] + 0.5 * (xl - a)[:, None] * g[None, :])).sum(1)
        out[low] = A_edge[i] + part
    return out


def kernel_C(T, eta):
    """The mode II kernel C(T) in closed form (module docstring)."""
    from scipy import special as sp
    T = np.asarray(T, dtype=float)
    Ts = np.where(T > 1e-6, T, 1.0)
    eT = eta * Ts
    C = (sp.j1(Ts) / Ts + 3 * sp.j0(Ts) - 4 * sp.j0(eT) / eta
         + 4 * Ts * (int_j0(Ts) - int_j0(eT) - sp.j1(Ts) + sp.j1(eT)))
    return np.where(T > 1e-6, C, 3.5 - 4 / eta)


def kernel_table(eta, T_max, dT=0.01):
    """Rows T, I(T) = int_0^T C on 0 <= T <= T_max (Simpson on each dT; cached in /tmp)."""
    n = int(math.ceil(T_max / dT))
    cache = f"/tmp/sbi_mode2_kernel_closed_eta{eta:.6f}_dT{dT}_n{n}.npy"
    if os.path.exists(cache):
        return np.load(cache)
    T = np.arange(n + 1) * dT
    C = kernel_C(T, eta)
    Cm = kernel_C(T[:-1] + 0.5 * dT, eta)
    I = np.concatenate([[0.0], np.cumsum(dT / 6 * (C[:-1] + 4 * Cm + C[1:]))])
    table = np.vstack([T, I])
    np.save(cache, table)
    return table


def check_kernel(eta):
    """The closed form against mpmath's Talbot inversion of G(s) - s (the earlier table)."""
    import mpmath as mp

    def G_minus_s(s):
        # beta and alpha written as s sqrt(1 + 1/s^2) (and alike): branch cuts on the imaginary
        # segments [-i, i] and [-i eta, i eta], analytic right of them, as Talbot's contour needs.
        e = mp.mpf(eta)
        b = s * mp.sqrt(1 + 1 / (s * s))
        a = (s / e) * mp.sqrt(1 + e * e / (s * s))
        return ((2 + s * s) ** 2 - 4 * a * b) / (s * s * b) - s

    worst = 0.0
    for t in (0.0, 0.5, 1.0, 2.0, 5.0, 10.0, 20.0, 35.0, 50.0, 75.0, 100.0):
        mp.mp.dps = int(30 + 1.5 * t)  # Talbot loses digits to cancellation as T grows
        ref = float(mp.invertlaplace(G_minus_s, max(t, 1e-9), method="talbot"))
        c = float(kernel_C(np.array([t]), eta)[0])
        worst = max(worst, abs(c - ref))
        print(f"T = {t:6.1f}: closed form {c:+.12f}, Talbot {ref:+.12f}")
    print(f"largest difference {worst:.2e}")


def main():
    import argparse
    ap = argparse.ArgumentParser(description="spectral BI solver, mode II (module docstring)")
    ap.add_argument("case", choices=("tpv103", "tpv101"))
    ap.add_argument("dx", type=float)
    ap.add_argument("t_end", type=float, nargs="?", default=12.0)
    ap.add_argument("out", nargs="?", default=None)
    ap.add_argument("--tail", choices=("full", "static", "cut"), default="full")
    ap.add_argument("--tcut", type=float, default=100.0)
    ap.add_argument("--check-kernel", action="store_true")
    args = ap.parse_args()
    case, dx, t_end, out = args.case, args.dx, args.t_end, args.out
    eta = CP / CS
    G0 = 2 * (1 - 1 / eta**2)  # the static stiffness
    if args.check_kernel:
        check_kernel(eta)
        return

    N = int(round(L_PERIOD / dx))
    x = (np.arange(N) - N // 2) * dx  # hypocentre on node N // 2
    ax = np.abs(x)
    dt = 0.1 * dx / CS
    nt = int(math.ceil(t_end / dt))
    k = 2 * np.pi * np.fft.rfftfreq(N, d=dx)  # >= 0
    nk = k.size
    M = nt + 1
    T_cut = args.tcut
    T_max = k[-1] * CS * dt * (M + 1) if args.tail == "full" else T_cut
    T, I = kernel_table(eta, T_max)
    I_cut = np.interp(T_cut, T, I) if args.tail != "full" else math.nan
    print(f"kernel (closed form): C(0) = {3.5 - 4 / eta:.6f}, int_0^{T_cut:g} C dT = "
          f"{np.interp(T_cut, T, I) if T[-1] >= T_cut else math.nan:.6f}, G(0) = 2 (1 - 1/eta^2) "
          f"= {G0:.6f} (the static stiffness); tail: {args.tail}")
    # Step weights W[m, j] = int over the m-th step of C(k c_s tau) k c_s dtau.
    #   cut: 0 for the steps that end past T_cut (the earlier behaviour);
    #   static: the step that crosses T_cut gets G(0) - int_0^{T_m} C, the later ones 0;
    #   full: no cut.
    W = np.zeros((M, nk))
    for j in range(1, nk):
        Tm = k[j] * CS * dt * np.arange(M + 1)
        if args.tail == "full":
            W[:, j] = np.diff(np.interp(Tm, T, I))
            continue
        Im = np.interp(Tm, T, I, right=I_cut)
        w = np.diff(Im)
        past = Tm[1:] > T_cut
        if args.tail == "static" and past.any():
            first = int(np.argmax(past))
            w[first] = G0 - Im[first]
            past[first] = False
        w[past] = 0.0
        W[:, j] = w
    # Each step's convolution is sum_m Wa[m] hist[n - m], Wa[m] = (W[m] + W[m + 1]) / 2: the
    # slip averaged over each step (the m = 0 term's newer half, delta_{n+1}, is added apart).
    Wn = np.vstack([W[1:], np.zeros((1, nk))])
    Wa = 0.5 * (W + Wn)
    # The modes whose kernels are cut early need only their own history: columns grouped in
    # blocks, each summed over its longest history.
    nz = W != 0.0
    hist_len = np.where(nz.any(0), M - np.argmax(nz[::-1], axis=0), 0)
    blocks = [(j0, min(j0 + 16, nk)) for j0 in range(0, nk, 16)]
    block_len = [int(hist_len[j0:j1].max()) for j0, j1 in blocks]
    fac = -0.5 * MU * k  # f_k = fac * conv

    # Friction parameters along the fault: the benchmarks' taper B(x) (1 within W = 15 km, 0
    # beyond W + w = 18 km) raises a (and, TPV103, V_w) outside.
    if case not in ("tpv101", "tpv103"):
        sys.exit(f"unknown case {case}")
    B, DC = (0.014, 0.4) if case == "tpv103" else (0.012, 0.02)
    Bx = np.zeros(N)
    W_, w_ = 15e3, 3e3
    Bx[ax <= W_] = 1.0
    mid = (ax > W_) & (ax < W_ + w_)
    Bx[mid] = 0.5 * (1 + np.tanh(w_ / (ax[mid] - W_ - w_) + w_ / (ax[mid] - W_)))
    if case == "tpv103":
        a = 0.01 + 0.01 * (1 - Bx)
        Vw = 0.1 + 0.9 * (1 - Bx)
        fw = 0.2
    else:
        a = 0.008 + 0.008 * (1 - Bx)
    V_ini = 1e-12 if case == "tpv101" else 1e-16
    eta_rad = MU / (2 * CS)
    R_nuc, T_nuc, dtau_nuc = 3e3, 1.0, (25e6 if case == "tpv101" else 45e6)
    if case == "tpv101":
        TAU, SIG = 75e6, 120e6
    else:
        TAU, SIG = TAU0, SIGMA
    F = np.where(ax < R_nuc, np.exp(np.minimum(ax * ax / (ax * ax - R_nuc * R_nuc + 1e-300), 0.0)), 0.0)

    def Gt(t):
        return math.exp((t - T_nuc) ** 2 / (t * (t - 2 * T_nuc))) if 0 < t < T_nuc else (1.0 if t >= T_nuc else 0.0)

    # Initial state balancing the initial stress at V_ini.
    if case == "tpv103":
        psi = a * np.log(2 * V0 / V_ini * np.sinh(TAU / (a * SIG)))
    else:
        # aging law: f = a asinh[V/(2V0) exp((f0 + b ln(V0 theta / L)) / a)]
        f_ini = TAU / SIG
        psi = a * np.log(2 * V0 / V_ini * np.sinh(f_ini / a))  # psi = f0 + b ln(V0 theta / L)

    def evolve(psi_n, V):
        Vs = np.maximum(np.abs(V), 1e-40)
        D = np.exp(-Vs * dt / DC)
        if case == "tpv103":
            f_lv = F0 - (B - a) * np.log(Vs / V0)
            f_ss = fw + (f_lv - fw) / (1 + (Vs / Vw) ** 8) ** 0.125
            psi_ss = a * np.log(2 * V0 / Vs * np.sinh(f_ss / a))
            return D * psi_n + (1 - D) * psi_ss
        theta = DC / V0 * np.exp((psi_n - F0) / B)
        theta = theta * D + DC / Vs * (1 - D)
        return F0 + B * np.log(V0 * theta / DC)

    def solve(tau_lock, psi_n):
        Z = np.exp(psi_n / a) / (2 * V0)
        s = np.sign(tau_lock)
        tl = np.abs(tau_lock)
        lo = np.full(N, -80.0)
        hi = np.log(np.maximum(tl / eta_rad, 1e-300))
        g = lambda V: tl - eta_rad * V - SIG * a * np.arcsinh(V * Z)
        for _ in range(60):
            mid = 0.5 * (lo + hi)
            pos = g(np.exp(mid)) > 0
            lo = np.where(pos, mid, lo)
            hi = np.where(pos, hi, mid)
        V = np.exp(0.5 * (lo + hi))
        for _ in range(3):
            dg = -eta_rad - SIG * a * Z / np.sqrt(1 + (V * Z) ** 2)
            V = np.maximum(V - g(V) / dg, 0.5 * V)
        return s * V

    delta = np.zeros(N)
    V = np.full(N, V_ini)
    hist = np.zeros((M + 1, nk), dtype=complex)  # slip modes, hist[n] at step n
    rupture_time = np.full(N, np.inf)
    peak = np.zeros(N)
    stations = [0, 2.5, 5, 7.5, 9, 12, 15, 18]
    idx = [N // 2 + int(round(s * 1e3 / dx)) for s in stations]
    series = np.zeros((nt, 1 + 3 * len(idx)))
    for n in range(nt):
        t1 = (n + 1) * dt
        # The history part of the convolution (steps before n+1), with slip averaged over each
        # step: 0.5 (delta_{n+1-m} + delta_{n-m}); the m = 0 term holds delta_{n+1}.
        conv_hist = np.zeros(nk, dtype=complex)
        for (j0, j1), Lb in zip(blocks, block_len):
            m_top = min(n + 1, Lb)
            if m_top <= 0:
                continue
            # sum_{m=0}^{m_top-1} W[m] * 0.5 (hist[n+1-m] + hist[n-m]) = sum Wa[m] hist[n-m]
            # (hist[0] = 0); hist[n+1] is the new one: its share is 0.5 W[0] (added below).
            conv_hist[j0:j1] = np.einsum("mj,mj->j", Wa[:m_top, j0:j1], hist[n::-1][:m_top, j0:j1])
        nuc = dtau_nuc * F * Gt(t1)
        Vstar = V
        for it in range(2):
            d1 = delta + dt * Vstar
            p1 = evolve(psi, Vstar)
            d1k = np.fft.rfft(d1)
            conv = conv_hist + 0.5 * W[0] * d1k
            f = np.fft.irfft(fac * conv, n=N)
            tau_lock = TAU + nuc + f
            V1 = solve(tau_lock, p1)
            Vstar = 0.5 * (V + V1)
        delta, psi, V = d1, p1, V1
        hist[n + 1] = d1k
        newly = (V > 1e-3) & np.isinf(rupture_time)
        rupture_time[newly] = t1
        peak = np.maximum(peak, V)
        series[n, 0] = t1
        series[n, 1::3], series[n, 2::3] = delta[idx], V[idx]
        series[n, 3::3] = (tau_lock - eta_rad * V)[idx]
        if (n + 1) % int(round(1.0 / dt)) == 0:
            front = x[np.isfinite(rupture_time)]
            print(f"t = {t1:.2f} s: ruptured to {front.max() / 1e3 if front.size else 0:.2f} km, "
                  f"peak V {V.max():.2f} m/s", flush=True)
    print(f"# {case}, dx = {dx:g} m, dt = {dt:.4e} s, {nt} steps, L = {L_PERIOD / 1e3:g} km periodic")
    print("x_km rupture_time_s peak_slip_rate final_slip")
    for s, i in zip(stations, idx):
        print(f"{s:5.1f} {rupture_time[i]:.3f} {peak[i]:.2f} {delta[i]:.3f}")
    ruptured = x[np.isfinite(rupture_time)]
    print(f"arrest (largest ruptured x): {ruptured.max() / 1e3:.2f} km" if ruptured.size else "no rupture")
    if out:
        np.savetxt(out, np.column_stack([x, rupture_time, peak, delta]), delimiter=",",
                   header="x_m,rupture_time_s,peak_slip_rate_m_s,slip_m", comments="")
        head = "time_s," + ",".join(f"slip_{s:g}km,slip_rate_{s:g}km,shear_{s:g}km" for s in stations)
        np.savetxt(out.replace(".csv", "") + "_stations.csv", series, delimiter=",", header=head, comments="")


if __name__ == "__main__":
    main()
