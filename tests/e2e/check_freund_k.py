#!/usr/bin/python3
"""Freund's dynamic K_I(t) of a stationary crack whose faces are suddenly loaded by a pressure
sigma* (Freund, Dynamic Fracture Mechanics, 1990, sec. 2.5; theory E18), from the interaction
integral with the loaded-face term (docs/fracture.md): examples/mode_I.toml (the pre-crack's
tip at x = 20 mm, sigma* = 5 MPa on both faces from t = 0, a Xu-Needleman weak plane ahead) with
stress_intensity = true, 0.25 mm, to 2.6 us (before t_F = 2.59 us, when Freund's K_I reaches
K_c and the cohesive zone ahead starts to soften; before any edge wave reaches the tip):
    K_I(t) = 2 sigma* sqrt(c_D t (1 - 2 nu) / pi) / (1 - nu).
Checked at every sample from 1.5 us (when c_D t = 3.8 mm, about twice the largest domain: the
near-tip field has formed over the domains) to 2.6 us, on each of the three domains: within
5 % (measured over every row: 0.965-1.018 at 0.25 mm; at 0.125 mm with the same domains
in mm, read at 1.5, 2 and 2.5 us: 0.959-0.983).
Without the face term K_I comes out negative (the faces' pressure is then taken for a stress
the free faces cannot carry), so this checks that term too.
Usage: check_freund_k.py RUPTURE WORK_DIR"""
import os
import subprocess
import sys

import numpy as np

from freund import check_against_freund

rupture, work = sys.argv[1], sys.argv[2]
here = os.path.dirname(os.path.abspath(__file__))
example = os.path.join(here, "..", "..", "examples", "mode_I.toml")
subprocess.run([rupture, "run", example, "-o", work, "--overwrite", "--quiet",
                "--set", "interface.weak_plane.stress_intensity=true", "--set", "time.end=2.6e-6"],
               check=True, stdout=subprocess.DEVNULL)
d = np.genfromtxt(os.path.join(work, "stress_intensity_weak_plane.csv"), delimiter=",", names=True)
E, nu, rho, p = 5.2e9, 0.34, 1246.0, 5e6
check_against_freund(d, p, E, nu, rho, 3 * 40, "")
