#!/usr/bin/python3
"""Freund's dynamic K_I(t) by superposition, for a crack cut into a prestressed body (docs/
fracture.md, "A prestressed body"): a plate under a uniform initial stress sigma_yy = sigma0
holds an edge crack from x = 0 to 20 mm drawn inside it (law = "contact": no cohesion), whose
faces are therefore released at t = 0. The uniform stress has no singularity, so the tip's
K_I(t) is that of the same crack with a pressure sigma0 suddenly applied to traction-free faces
(Freund, Dynamic Fracture Mechanics, 1990, sec. 2.5):
    K_I(t) = 2 sigma0 sqrt(c_D t (1 - 2 nu) / pi) / (1 - nu),
until a wave from the plate's free top and bottom edges (10 mm away, also released at t = 0)
reaches the crack (3.9 us). The domain points add the body's initial strain to the gradient of
u = x - X (fracture/tip_domain.hpp: InitialStrain); without it K_I reads the wrong field.
Geometry, material and resolution as examples/mode_I.toml (0.25 mm); checked at every sample
from 1.5 to 2.6 us on each of the three domains, within 5 %, and K_II within 1 % of K_I.
Usage: check_freund_prestress.py RUPTURE WORK_DIR"""
import os
import subprocess
import sys

import numpy as np

from freund import check_against_freund, prestressed_edge_crack

rupture, work = sys.argv[1], sys.argv[2]
os.makedirs(work, exist_ok=True)
E, nu, rho, s0 = 5.2e9, 0.34, 1246.0, 5e6
case = prestressed_edge_crack("edge crack cut into a prestressed plate (Freund by superposition)", E, nu, rho, s0,
                              0.03, 0.01, "stress_intensity = true\n", 2.6e-6, 0.02e-6)
path = os.path.join(work, "prestressed_edge_crack.toml")
open(path, "w").write(case)
out = os.path.join(work, "run")
subprocess.run([rupture, "run", path, "-o", out, "--overwrite", "--quiet"], check=True, stdout=subprocess.DEVNULL)
d = np.genfromtxt(os.path.join(out, "stress_intensity_crack.csv"), delimiter=",", names=True)
check_against_freund(d, s0, E, nu, rho, 3 * 20, "prestressed plate: ")
