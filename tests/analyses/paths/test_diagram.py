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


# ------------------------------------------------------------------------ a singular start: the straight chain
def test_the_straight_chain_held_at_full_reach_leaves_by_its_buckled_arms():
    """The straight chain held at dx = dy = 0 is the held tip's branch point: its reaction along the chain is free
    and the tip moves in only once the chain buckles, at the guided critical load (the paper's buckling)."""
    from reference_model import Chain, critical_loads_guided

    import tensegrity_opt as to
    from tensegrity_opt.analyses.paths.control import Control
    from tensegrity_opt.analyses.paths.diagram import branches_from
    from tensegrity_opt.errors import SingularStartError

    m = to.Manipulator.uniform(4, 1.0, 1.0, 1.0, 1.0)
    chain = Chain.uniform(4, 1.0, 1.0, 1.0, 1.0)
    p_cr = critical_loads_guided(chain)[0]
    assert p_cr == pytest.approx(0.572793, abs=1e-6)                # conventions.md, the paper's Fx0
    straight, inward = np.zeros(4), Control.displacement((1.0, 0.0))
    with pytest.raises(SingularStartError, match="singular point") as exc:
        to.trace_branch(m, straight, inward, t_max=0.5)
    assert isinstance(exc.value, ValueError) and exc.value.field == "start"
    assert "start nearby" not in str(exc.value) and "not defined" not in str(exc.value)
    arms = branches_from(m, straight, inward, t_max=0.5, stop_at="stability_loss")
    assert len(arms) == 2
    for arm in arms:
        assert arm.status == "t_max" and arm.t[-1] == pytest.approx(0.5) and arm.stable[1:].all()
        np.testing.assert_allclose(arm.force[0], [-p_cr, 0.0], atol=1e-7)
        np.testing.assert_allclose(arm.q[0], 0.0, atol=1e-12)
        ref = chain.local_min(chain.target(0.5, 0.0), arm.q[-1] + 0.01)          # the reference minimum there
        np.testing.assert_allclose(arm.q[-1], ref[0], atol=1e-7)
    np.testing.assert_allclose(arms[0].q[-1], -arms[1].q[-1], atol=1e-9)         # mirror images
    assert branches_from(m, straight, inward, orientation=-1, t_max=0.5) == []   # outward: beyond reach
    sideways = to.trace_branch(m, straight, Control.displacement((0.0, 1.0)), t_max=0.5)
    assert sideways.status == "workspace_boundary" and sideways.success and len(sideways) == 1
    diagram = bifurcation_diagram(m, straight, "displacement", t_max=0.5)
    assert len(diagram) == 2 and all(b.force[0][0] == pytest.approx(-p_cr, abs=1e-7) for b in diagram)
