#!/usr/bin/python3
"""An independent spectral boundary-integral (SBI) solver for a 2D in-plane (mode II) fault in a
homogeneous elastic full space with rate-and-state friction: the method of the TPV101/103-2D
references (uguca), written here from its equations, so that the references' own method can be
run on finer grids than the one stored (docs/faults.md, TPV103-2D).

Usage:  scripts/sbi_mode2.py tpv103|tpv101 CELL_M [END_S] [OUT.csv]
Needs numpy and mpmath (Debian: python3-numpy, python3-mpmath; the kernel is computed once, about
4 minutes, and cached in /tmp).
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
1/eta^2) = 1/(1 - nu) is the static stiffness and G(s) -> s the radiation damping). C is
inverted with mpmath's Talbot method on 0 <= T <= 100 and cut there, as uguca's tables are.

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
T_CUT = 100.0


def kernel_table(eta, dT=0.01):
    """C(T) on [0, T_CUT] (rows T, C), computed once and cached in /tmp."""
    cache = f"/tmp/sbi_mode2_kernel_eta{eta:.6f}_dT{dT}.npy"
    if os.path.exists(cache):
        return np.load(cache)
    import mpmath as mp

    def G_minus_s(s):
        # beta = sqrt(1 + s^2) and alpha written as s sqrt(1 + 1/s^2) (and alike), whose
        # principal branches put the cuts on the imaginary segments [-i, i] and [-i eta, i eta]:
        # analytic right of them, as Talbot's contour needs.
        e = mp.sqrt(mp.mpf(eta) ** 2)
        b = s * mp.sqrt(1 + 1 / (s * s))
        a = (s / e) * mp.sqrt(1 + e * e / (s * s))
        R = (2 + s * s) ** 2 - 4 * a * b
        return R / (s * s * b) - s

    # Talbot's sum loses digits to cancellation as T grows: 20 + 1.5 T digits (checked: the
    # values at T = 50, 75, 100 agree to 10 digits between 150 and 200 digits).
    Tc = np.arange(0.0, T_CUT + 1e-9, 0.05)
    Cc = np.empty_like(Tc)
    for i, t in enumerate(Tc):
        mp.mp.dps = int(30 + 1.5 * t)
        Cc[i] = float(mp.invertlaplace(G_minus_s, max(t, 1e-9), method="talbot"))
    T = np.arange(0.0, T_CUT + 1e-9, dT)
    C = np.interp(T, Tc, Cc)
    table = np.vstack([T, C])
    np.save(cache, table)
    return table


def cumulative(T, C):
    I = np.zeros_like(C)
    I[1:] = np.cumsum(0.5 * (C[1:] + C[:-1]) * np.diff(T))
    return I


def main():
    case = sys.argv[1]
    dx = float(sys.argv[2])
    t_end = float(sys.argv[3]) if len(sys.argv) > 3 else 12.0
    out = sys.argv[4] if len(sys.argv) > 4 else None
    eta = CP / CS
    T, C = kernel_table(eta)
    I = cumulative(T, C)
    print(f"kernel: C(0) = {C[0]:.6f}, int_0^{T_CUT:g} C dT = {I[-1]:.6f} "
          f"(G(0) = 2 (1 - 1/eta^2) = {2 * (1 - 1 / eta**2):.6f}, the static stiffness)")

    N = int(round(L_PERIOD / dx))
    x = (np.arange(N) - N // 2) * dx  # hypocentre on node N // 2
    ax = np.abs(x)
    dt = 0.1 * dx / CS
    nt = int(math.ceil(t_end / dt))
    k = 2 * np.pi * np.fft.rfftfreq(N, d=dx)  # >= 0
    nk = k.size
    # Step weights W[m, j] = int over the m-th step of C(k c_s tau) k c_s dtau (0 past T_CUT).
    M = nt + 1
    W = np.zeros((M, nk))
    for j in range(1, nk):
        Tm = k[j] * CS * dt * np.arange(M + 1)
        Im = np.interp(Tm, T, I, right=I[-1])
        w = np.diff(Im)
        w[Tm[1:] > T_CUT] = 0.0
        W[:, j] = w
    # The modes whose kernels are cut early need only their own history: columns grouped in
    # blocks, each summed over its longest history.
    hist_len = np.array([np.count_nonzero(W[:, j]) for j in range(nk)])
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
            # sum_{m=0}^{m_top-1} W[m] * 0.5 (hist[n+1-m] + hist[n-m]); hist[n+1] is the new one:
            # its share is 0.5 W[0] (added below); the rest is known.
            w = W[:m_top, j0:j1]
            older = hist[n - np.arange(m_top), j0:j1]  # hist[n-m]
            newer = hist[n + 1 - np.arange(1, m_top), j0:j1]  # hist[n+1-m], m >= 1
            conv_hist[j0:j1] = 0.5 * np.einsum("mj,mj->j", w, older)
            if m_top > 1:
                conv_hist[j0:j1] += 0.5 * np.einsum("mj,mj->j", w[1:], newer)
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
