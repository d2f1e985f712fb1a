"""rupture.plot (the figures of `rupture plot`): units that fit the run's scale, reference-line
labels that do not overlap, the tau_max fringes drawn where the particles are (a hole stays a
hole, the coarse levels' gaps are filled) and every running tip marked where it is (an inclined
crack's tip on its line, not at y = 0). On small real runs made by the rupture executable."""
import os
import sys

import numpy as np
import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "python"))

import rupture  # noqa: E402
from rupture import plot  # noqa: E402

HOLE = os.path.join(ROOT, "tests", "inputs", "hole_and_inclined_crack.toml")
FAULT = os.path.join(ROOT, "examples", "slip_weakening_1d.toml")


@pytest.fixture(scope="module")
def hole_run(tmp_path_factory):
    return rupture.run(HOLE, tmp_path_factory.mktemp("hole") / "run")


def test_units_follow_the_scale():
    lab = plot.Scale(0.125, 40e-6)
    assert (lab.lname, lab.tname, lab.vname) == ("mm", "µs", "m/s")
    assert lab.time_label(12.3456e-6) == "t = 12.35 µs"
    fault = plot.Scale(40e3, 12.0)
    assert (fault.lname, fault.tname, fault.vname) == ("km", "s", "km/s")
    assert fault.lf * 40e3 == pytest.approx(40.0) and fault.vf * 3464.0 == pytest.approx(3.464)
    assert fault.time_label(3.0) == "t = 3.000 s"  # not "t = 3000000.00 µs"
    assert plot.Scale(2.0, 5e-3).tname == "ms"


def test_reference_labels_do_not_overlap():
    """c_R and c_S of Homalite differ by 7 %: their labels, one at each end, must not overlap."""
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(7.5, 3.75))
    ax.set_xlim(0, 10)
    ax.set_ylim(0, 1.1 * 2534)
    lines = [(1255.0, "$c_R$ = 1255 m/s", ":", "k"), (1350.0, "$c_S$ = 1350 m/s", "--", "k"),
             (1909.0, r"$\sqrt{2}\,c_S$ = 1909 m/s", "-.", "k"), (2534.0, "$c_D$ = 2534 m/s", "-", "k")]
    plot.label_lines(ax, lines)
    fig.canvas.draw()
    boxes = [t.get_window_extent() for t in ax.texts]
    assert len(boxes) == 4
    for i in range(4):
        for j in range(i + 1, 4):
            assert not boxes[i].overlaps(boxes[j]), (ax.texts[i].get_text(), ax.texts[j].get_text())
    plt.close(fig)


def test_coverage_keeps_holes_and_fills_coarse_levels():
    """Particles of a fine level (half-width 0.25) left of x = 8 and a coarse one (half-width 1)
    right of it, a hole of radius 3 at (4, 5): the covered pixels are the particles' own domains."""
    fine = np.arange(0.25, 8.0, 0.5)
    coarse = np.arange(9.0, 16.0, 2.0)
    fx, fy = np.meshgrid(fine, np.arange(0.25, 10.0, 0.5), indexing="ij")
    cx, cy = np.meshgrid(coarse, np.arange(1.0, 10.0, 2.0), indexing="ij")
    x = np.concatenate([fx.ravel(), cx.ravel()])
    y = np.concatenate([fy.ravel(), cy.ravel()])
    h = np.concatenate([np.full(fx.size, 0.25), np.full(cx.size, 1.0)])
    out = np.hypot(x - 4.0, y - 5.0) > 3.0
    x, y, h = x[out], y[out], h[out]
    xe, ye = np.linspace(0, 16, 65), np.linspace(0, 10, 41)  # 0.25 pixels
    covered, reach = plot.covered_pixels(x, y, h, h, xe, ye)
    xc, yc = np.meshgrid(0.5 * (xe[1:] + xe[:-1]), 0.5 * (ye[1:] + ye[:-1]), indexing="ij")
    r = np.hypot(xc - 4.0, yc - 5.0)
    assert not covered[r < 2.5].any(), "pixels well inside the hole are drawn"
    assert covered[(r > 3.6) & (xc < 8)].all(), "fine pixels beside the hole are left empty"
    assert covered[xc > 8].all(), "the coarse level's pixels between its particles are left empty"
    assert reach == 4  # a coarse particle covers 4 pixels either side of its own
    # The fill reaches every covered pixel and none outside.
    image = np.full(covered.shape, np.nan)
    count, _, _ = np.histogram2d(x, y, bins=(xe, ye))
    image[count > 0] = 1.0
    filled = np.where(covered, plot.fill_empty(image, covered, reach + 1), np.nan)
    assert np.isfinite(filled[covered]).all() and np.isnan(filled[~covered]).all()


def test_fringes_of_a_plate_with_a_hole_and_an_inclined_crack(hole_run):
    r = hole_run
    assert r.status == "completed", r.message
    snap = r.snapshots[-1]
    assert snap["half_size"].shape == (len(snap["id"]), 2)
    tracks = plot.tip_tracks(r)
    assert [name for name, _ in tracks] == ["weak_plane"]
    # The whole plate in one image (a window wider than the plate).
    t, tips, xe, ye, image = plot.fringe_panel(snap, tracks, 0.1)
    xc, yc = np.meshgrid(0.5 * (xe[1:] + xe[:-1]), 0.5 * (ye[1:] + ye[:-1]), indexing="ij")
    pixel = xe[1] - xe[0]
    rh = np.hypot(xc - 0.006, yc - 0.014)
    assert np.isnan(image[rh < 0.002 - 2 * pixel]).all(), "the hole is drawn filled"
    # Inside the plate, away from the hole, the particles have moved less than a pixel's worth
    # of a cell: everything is drawn.
    inside = (rh > 0.002 + 0.5e-3) & (xc > 0.5e-3) & (xc < 0.0195) & (yc > 0.5e-3) & (yc < 0.0195)
    assert np.isfinite(image[inside]).mean() > 0.99
    # The crack runs by the end (the case's own expectation) and its tip is on the 45 degree
    # line, within half a cell, not at y = 0.
    assert tips, "no running tip at the last snapshot"
    for name, tx, ty, running, _ in tips:
        assert running and abs(tx - ty) / np.sqrt(2.0) < 0.25e-3, (name, tx, ty)
        assert ty > 0.004
    # The figures themselves.
    plot.main([r.dir])
    for name in ("crack_tip.png", "tau_max_fringes.png", "crack_tip_weak_plane.png"):
        assert os.path.getsize(os.path.join(r.dir, "figures", name)) > 10000


def test_a_fault_run_is_drawn_in_km_and_s(tmp_path):
    r = rupture.run(FAULT, tmp_path / "fault", set={"time.end": 0.05})
    sc = plot.scale_of(r)
    assert (sc.lname, sc.tname, sc.vname) == ("km", "s", "km/s")
    plot.main([r.dir])
    assert os.path.exists(os.path.join(r.dir, "figures", "crack_tip.png"))


def test_fringes_follow_a_crack_that_grows(tmp_path):
    """examples/crack_growth_disc.toml to 12 us: each tip's path in the figure is the drawn end
    and then crack_path_crack.csv's vertices of that end up to the panel's time, and the panel's
    tips are where those paths end (running), both of them."""
    disc = os.path.join(ROOT, "examples", "crack_growth_disc.toml")
    r = rupture.run(disc, tmp_path / "disc", set={"time.end": 12e-6, "output.snapshot_interval": 6e-6})
    assert r.status == "completed", r.message
    rows = r.table("crack_path_crack.csv")
    assert len(rows["time"]) >= 4, "the crack grows by 12 us (the example's expectation)"
    paths = plot.crack_paths(r)
    drawn = np.array(r.case["interface"]["crack"]["points"])
    assert np.allclose(np.column_stack(paths[("crack", "drawn")]), drawn)
    ends = paths["crack"]
    assert len(ends) == 2
    for end, (times, xs, ys) in enumerate(ends):
        mine = rows["end"] == end
        assert (xs[0], ys[0]) == tuple(drawn[0 if end == 0 else -1])
        assert np.array_equal(xs[1:], rows["x"][mine]) and np.array_equal(ys[1:], rows["y"][mine])
        assert np.all(np.diff(times) >= 0)
    snap = r.snapshots[-1]
    t, tips, xe, ye, image = plot.fringe_panel(snap, plot.tip_tracks(r), 0.084, paths)
    assert len(tips) == 2
    for end, (name, tx, ty, running, _) in enumerate(tips):
        mine = (rows["end"] == end) & (rows["time"] <= t)
        assert running and (tx, ty) == (rows["x"][mine][-1], rows["y"][mine][-1]), (end, tx, ty)
    plot.main([r.dir])
    assert os.path.getsize(os.path.join(r.dir, "figures", "tau_max_fringes.png")) > 10000
