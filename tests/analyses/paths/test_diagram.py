"""Branch switching and bifurcation diagrams (``switch_branch``, ``bifurcation_diagram``) against the independent
references: the bifurcating branch leaves along the reference's buckling mode, the diagram holds the trivial branch
and the branches born at its branch points (``tests/support/branch_checks.py``)."""

from __future__ import annotations

import numpy as np
import pytest
from branch_checks import check_branch, check_name, events_of, lib, load_control, modes, ref, straight_branch

from tensegrity_opt import bifurcation_diagram, switch_branch


@pytest.mark.parametrize("boundary, side", [("guided", +1), ("free", -1)])
def test_switch_branch_at_the_first_branch_point(boundary, side):
    """The bifurcating branch of the paper chain: bent along the first buckling mode,
    supercritical (the load grows past P as it bends) and stable near the branch point."""
    c = ref("paper4")
    P, V = modes("paper4", boundary)
    br = straight_branch("paper4", boundary)
    e = events_of(br, "branch_point")[0]
    sb = switch_branch(br, e, side=side)
    check_branch(c, sb, check_name(boundary), direction=(-1.0, 0.0), tip0=c.tip(np.zeros(4)),
                 from_start=False)
    q = np.asarray(sb.q, float)
    amp = np.linalg.norm(q, axis=1)
    assert amp.max() > 1e-2, "the switched branch never leaves the straight configuration"
    # the reference's post-buckling shapes stay within cos > 0.9999 of the first mode up to
    # |q| = 0.4 (guided and free)
    near = (amp > 1e-4) & (amp < 0.4)
    assert near.any()
    cos = np.abs(q[near] @ V[:, 0]) / amp[near]
    assert np.all(cos > 0.999), "the switched branch does not leave along the buckling mode"
    small = amp < 0.2
    assert np.all(np.asarray(sb.t)[small] >= P[0] - 1e-7), "subcritical? the reference pitchfork is supercritical"
    assert np.all(np.asarray(sb.morse_index)[small & (amp > 1e-3)] == 0)


@pytest.mark.slow
def test_bifurcation_diagram_two_segment_guided():
    """n = 2, guided: one branch point at P = 5/3; the diagram holds the trivial branch and
    the branch(es) bifurcating there, every point a reference equilibrium."""
    c = ref("paper2")
    P, _ = modes("paper2", "guided")
    assert P[0] == pytest.approx(5.0 / 3.0, rel=1e-12)
    branches = bifurcation_diagram(lib("paper2"), None, load_control("guided"), depth=2, t_max=2.0)
    assert isinstance(branches, list) and len(branches) >= 2
    primary = branches[0]
    bps = events_of(primary, "branch_point")
    assert [e.t for e in bps] == pytest.approx([P[0]], rel=1e-6)
    bent = 0
    for k, br in enumerate(branches):
        check_branch(c, br, "guided", direction=(-1.0, 0.0), tip0=c.tip(np.zeros(2)), from_start=(k == 0))
        if np.max(np.abs(br.q)) > 1e-2:
            bent += 1
            assert br.t[0] == pytest.approx(P[0], abs=0.05) and np.max(np.abs(br.q[0])) < 0.1
    assert bent >= 1
