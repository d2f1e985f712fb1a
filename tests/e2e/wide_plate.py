"""The wide plate of the inclined-crack checks (check_stress_intensity.py, check_crack_kink.py,
check_closed_crack.py, check_growth_nested.py): examples/centre_crack_tension.toml widened to
160 x 200 mm (a / b = 0.125), its crack 2a turned by beta about a centre 0.1 mm above the plate's
(a line through particle centres, as y = x is at 45 degrees on this lattice, would put particles
on the crack). `rupture run` --set arguments."""
import math

# The plate, its body and its loaded edges, 160 mm wide.
WIDE = ["--set", "grid.min=[-0.08, -0.1]", "--set", "grid.max=[0.08, 0.1]",
        "--set", "bodies.plate.min=[-0.08, -0.1]", "--set", "bodies.plate.max=[0.08, 0.1]",
        "--set", "loads.top.from=[-0.08, 0.1]", "--set", "loads.top.to=[0.08, 0.1]",
        "--set", "loads.bottom.from=[0.08, -0.1]", "--set", "loads.bottom.to=[-0.08, -0.1]"]
CENTRE_Y = 1e-4  # m


def crack(a, beta_deg):
    """--set of the crack's points: half-length a (m) turned by beta_deg about (0, CENTRE_Y)."""
    c, s = math.cos(math.radians(beta_deg)), math.sin(math.radians(beta_deg))
    y0 = CENTRE_Y
    return ["--set", f"interface.crack.points=[[{-a * c!r}, {y0 - a * s!r}], [{a * c!r}, {y0 + a * s!r}]]"]
