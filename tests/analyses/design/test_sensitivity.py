"""Sensitivities (analyses/design/sensitivity.py) against central finite differences of the forward
computations."""

import numpy as np
import pytest

import tensegrity_opt as to
from tensegrity_opt.analyses.design.sensitivity import critical_load_sensitivity, equilibrium_sensitivity

NONUNIFORM = to.Manipulator([to.Segment(1, 1, 1, 1), to.Segment(0.9, 1.3, 2, 1.5), to.Segment(1.1, 0.8, 0.7, 0.9),
                             to.Segment(1, 1.1, 1.5, 1.2)])


@pytest.mark.parametrize("boundary", ["guided", "free"])
def test_critical_load_sensitivity_by_finite_differences(boundary):
    s = critical_load_sensitivity(NONUNIFORM, boundary)
    h = 1e-6
    for name in ("a", "b", "k", "L0"):
        for i in range(NONUNIFORM.n):
            segs = list(NONUNIFORM.segments)
            val = getattr(segs[i], name)
            up = to.Manipulator(segs[:i] + [segs[i].replace(**{name: val + h})] + segs[i + 1:])
            dn = to.Manipulator(segs[:i] + [segs[i].replace(**{name: val - h})] + segs[i + 1:])
            fd = (to.critical_force(up, boundary).loads[0] - to.critical_force(dn, boundary).loads[0]) / (2 * h)
            assert s[name][i] == pytest.approx(fd, rel=1e-5, abs=1e-8)


def test_equilibrium_sensitivity_by_finite_differences():
    m = to.Manipulator([to.Segment(1, 1, (1, 1.2), (1, 0.9)), to.Segment(0.9, 1.3, 2, 1.5),
                        to.Segment(1.1, 0.8, 0.7, (0.9, 1.0))])
    eq = to.solve_equilibrium(m, 0.4, 0.3)
    s = equilibrium_sensitivity(m, eq)
    h = 1e-6
    for j, pname in enumerate(("a", "b", "k1", "k2", "L1_0", "L2_0")):
        for i in range(m.n):
            def perturbed(delta):
                seg = m.segments[i]
                if pname in ("a", "b"):
                    new = seg.replace(**{pname: getattr(seg, pname) + delta})
                elif pname in ("k1", "k2"):
                    k = [seg.k1, seg.k2]
                    k[pname == "k2"] += delta
                    new = seg.replace(k=tuple(k))
                else:
                    L0 = [seg.L1_0, seg.L2_0]
                    L0[pname == "L2_0"] += delta
                    new = seg.replace(L0=tuple(L0))
                mm = to.Manipulator(list(m.segments[:i]) + [new] + list(m.segments[i + 1:]))
                # the tip stays where it is (same absolute target)
                dx = mm.straight_length - eq.tip[0]
                return to.solve_equilibrium(mm, dx, eq.tip[1], q0=eq.q, local=True)
            up, dn = perturbed(h), perturbed(-h)
            col = j * m.n + i
            assert np.allclose(s["dq"][:, col], (up.q - dn.q) / (2 * h), rtol=1e-5, atol=1e-7), (pname, i)
            assert np.allclose(s["dF"][:, col], (up.force - dn.force) / (2 * h), rtol=1e-5, atol=1e-7)
