"""Critical loads and modes against the paper (Table 1, eq. 19-26) and ``docs/model.md``."""

import numpy as np
import pytest

from tensegrity_opt import (
    InvalidParameterError,
    Manipulator,
    Segment,
    StraightNotEquilibriumError,
    UnstableStraightError,
    critical_force,
)

PAPER = Manipulator.uniform(4, a=1, b=1, k=1, L0=1)
RTOL = 1e-4

# docs/model.md, "Figures checked" (unrounded values)
EIG_B_INV_A = [-1.74583, -0.73373, -0.52044]
LOADS = [0.572793, 1.362906, 1.921444]
MU_EQ = [1.145586, 2.725813, 3.842887]
TABLE1 = np.array([[0.525, -0.227, -0.719, -0.388, -0.075],
                   [0.352, -0.707, 0.162, 0.590, -0.050],
                   [0.124, -0.387, 0.589, -0.699, -0.018]])


@pytest.mark.parametrize("method", ["reduced", "paper"])
def test_paper_critical_loads(method):
    bk = critical_force(PAPER, method=method)
    assert bk.force == pytest.approx(-LOADS[0], rel=RTOL)
    assert bk.force < 0
    assert np.allclose(bk.loads, LOADS, rtol=RTOL)
    assert np.allclose(-1.0 / bk.loads, EIG_B_INV_A, rtol=RTOL)


@pytest.mark.parametrize("method", ["reduced", "paper"])
def test_table1_vectors_and_energy_factors(method):
    bk = critical_force(PAPER, method=method)
    for mode, row, mu in zip(bk.modes, TABLE1, MU_EQ):
        assert np.allclose(mode.vector, row, atol=1.5e-3)        # Table 1 prints 3 digits
        assert mode.energy_factor == pytest.approx(mu, rel=RTOL)
        # eq. 25 from the rounded Table 1 vectors gives the paper's printed 1.1447 / 2.7272
    rounded = TABLE1[:2, :4]
    G = np.array([[7, 5, 3, 1], [5, 5, 3, 1], [3, 3, 3, 1], [1, 1, 1, 1]], float)
    printed = [(a @ a) / (0.5 * a @ G @ a) for a in rounded]
    assert printed == pytest.approx([1.1447, 2.7272], abs=1e-4)


def test_table2_shapes_and_stability():
    bk = critical_force(PAPER)
    assert [m.shape for m in bk.modes] == ["U", "ZU", "Z"]
    assert [m.stable for m in bk.modes] == [True, False, False]
    # Table 2 case #2 (q1 > 0): U +---, ZU +-++, Z +-+-
    assert [m.signs for m in bk.modes] == ["+---", "+-++", "+-+-"]


def test_energy_factor_equals_twice_load_over_K():
    """dE/d(dx) on a branch is the load (envelope theorem), so eq. 24 gives mu_eq = 2 b P / K."""
    m = Manipulator.uniform(5, a=0.8, b=1.2, k=2.5, L0=1.7)
    K = 2.5 * (1.2 * 1.7 - 2 * (1.2 ** 2 - 0.8 ** 2))
    for mode in critical_force(m).modes:
        assert mode.energy_factor == pytest.approx(2 * 1.2 * mode.load / K, rel=1e-9)


def test_eq26_fy_coefficient_matches_conventions_figure():
    mode = critical_force(PAPER).modes[0]
    # |Fy| = 0.00806 at dx = 0.01 on the U branch (docs/model.md); eq. 26 is the leading term
    assert abs(mode.fy_coefficient) * np.sqrt(0.01) == pytest.approx(0.00806, rel=1e-2)
    assert mode.fy_coefficient == pytest.approx(0.075044 / np.sqrt(0.868), rel=1e-4)


def test_free_tip_critical_load():
    bk = critical_force(PAPER, "free")
    assert bk.loads[0] == pytest.approx(0.0761205, rel=RTOL)
    assert bk.loads.size == 4
    assert all(m.fy == 0.0 for m in bk.modes)
    assert np.allclose(critical_force(PAPER, "free", method="paper").loads, bk.loads, rtol=1e-10)


@pytest.mark.parametrize("n", [2, 3, 5, 8, 13])
def test_both_formulations_agree_and_count(n):
    m = Manipulator.uniform(n, a=0.9, b=1.1, k=1.7, L0=1.5)
    red = critical_force(m, method="reduced")
    pap = critical_force(m, method="paper")
    assert red.loads.size == n - 1          # "exactly n - 1 nonzero eigenvalues"
    assert np.allclose(red.loads, pap.loads, rtol=1e-9)
    for a, b in zip(red.modes, pap.modes):
        assert np.allclose(a.vector, b.vector, atol=1e-7)


def test_nonuniform_segments_both_forms_and_euler_check():
    segs = [Segment(1.0, 1.0, 1.0, 1.0), Segment(0.9, 1.3, 2.0, 1.5), Segment(1.1, 0.8, 0.7, 0.9)]
    m = Manipulator(segs)
    red, pap = critical_force(m), critical_force(m, method="paper")
    assert np.allclose(red.loads, pap.loads, rtol=1e-9)
    # independent check: det [[K - P G, S0], [S0^T, 0]] vanishes at each load
    K = np.array([s.stiffness for s in segs])
    b = np.array([s.b for s in segs])
    links = np.array([b[0] + b[1], b[1] + b[2], b[2]])
    G = np.array([[sum(links[max(i, j):]) for j in range(3)] for i in range(3)])
    S0 = np.array([links[i:].sum() for i in range(3)])
    for P in red.loads:
        M = np.block([[np.diag(K) - P * G, S0[:, None]], [S0[None, :], np.zeros((1, 1))]])
        assert abs(np.linalg.det(M)) < 1e-8 * np.linalg.norm(M) ** 3


def test_errors():
    with pytest.raises(StraightNotEquilibriumError) as ei:
        critical_force(Manipulator([Segment(1, 1), Segment(1, 1, (1, 2), 1)]))
    assert isinstance(ei.value, ValueError) and ei.value.field == "segments[1]"
    with pytest.raises(UnstableStraightError) as ei:
        critical_force(Manipulator.uniform(3, a=0.5, b=1, L0=0.5))
    assert isinstance(ei.value, ValueError) and "K" in str(ei.value)
    with pytest.raises(InvalidParameterError) as ei:
        critical_force(PAPER, "clamped")
    assert ei.value.field == "boundary"
    with pytest.raises(InvalidParameterError) as ei:
        critical_force(Manipulator.uniform(1))
    assert ei.value.field == "n"
    # unpreloaded asymmetric stiffness: straight is an equilibrium (L0 = 2b)
    bk = critical_force(Manipulator.uniform(3, a=1, b=1, k=(1, 2), L0=2.0))
    assert bk.loads.size == 2
