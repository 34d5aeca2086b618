"""The numbers docs/python.md quotes are the module's: a page that goes stale fails here."""

import linkwright


def test_the_thesis_crank_rockers_figures():
    crank_rocker = linkwright.example("thesis-crank-rocker")
    assert crank_rocker.classify()["grashof"]["class"] == "crank-rocker"
    assert round(crank_rocker.classify()["transmission"]["minimum_deg"], 2) == 25.21
    t = crank_rocker.sweep(start_deg=0, stop_deg=360, samples=721)
    omega = t["rocker_omega_rad_s"]
    assert (round(float(omega.max()), 4), float(t["crank_angle_deg"][omega.argmax()])) == (0.6189, 92.0)
    assert round(float(t["rocker_alpha_rad_s2"].min()), 4) == -0.9211


def test_the_seed_arms_joint_angles():
    t = linkwright.example("seed-arm").sweep()
    assert len(t["time_s"]) == 101
    shoulder = t["upper_angle_deg"]
    elbow = t["forearm_angle_deg"] - shoulder
    assert (round(float(shoulder[0]), 3), round(float(shoulder[-1]), 3)) == (-38.942, 51.058)
    assert (round(float(elbow.min()), 3), round(float(elbow.max()), 3)) == (109.471, 135.099)
