"""Self-tests of tests/support/reference_equilibria_tension.py (every equilibrium with the tip held, stops included).

The reference's closed forms are checked against reference_tension_only (energy, force-vector torques,
stiffness, tip, tip Jacobian); its enumeration against the paper's published count (Zhao et al., Table 2: six
equilibria of the linear paper chain, two minima, two saddles, two maxima, with Table 2's sign patterns),
against an independent many-start Newton written here (scipy's ``root`` on reference_tension_only's torques,
Morse indices from finite differences of its energy), against the module's own batched multistart, and against
reference_tension_only's brute-force least energy (the least stable record). ``tensegrity_opt`` is used only as
a container of parameters. The fast lane takes about 30 s on one core; the default 801 x 801 grid and the larger
multistarts are ``slow``.
"""

from __future__ import annotations

import functools
import itertools
import math

import numpy as np
import pytest
import reference_equilibria_tension as RE
import reference_tension_only as RT
import scipy.linalg as sl
import scipy.optimize as so

FAST_GRID = 401       # n = 4 interior search, the fast lane (the default is 801)


def seg(a=1.0, b=1.0, k1=1.0, k2=1.0, L10=1.0, L20=1.0, law="tension_only"):
    return dict(a=a, b=b, k1=k1, k2=k2, L10=L10, L20=L20, law=law)


def paper(law, n=4):
    from tensegrity_opt import Manipulator  # a container of parameters only

    return RT.segs_of(Manipulator.uniform(n, spring=law))


def uniform(n, a, b, k, L0, law):
    return [seg(a, b, k, k, L0, L0, law)] * n


HETERO3 = [seg(0.8, 1.2, 2.5, 1.5, 1.7, 1.4, "tension_only"), seg(1.0, 1.0, 1.0, 1.0, 1.0, 1.0, "linear"),
           seg(1.1, 0.8, 0.7, 0.9, 1.2, 0.6, "tension_only")]
HETERO4 = HETERO3 + [seg(0.9, 1.1, 1.3, 0.8, 1.6, 1.5, "tension_only")]


@functools.lru_cache(maxsize=None)
def eq(name, dx, dy=0.0, grid2=FAST_GRID):
    return RE.equilibria(CHAINS[name], dx, dy, grid2=grid2)


CHAINS = {
    "paper4-linear": paper("linear"),
    "paper4-tension": paper("tension_only"),
    "paper3-tension": paper("tension_only", 3),
    "paper2-tension": paper("tension_only", 2),
    "hetero3": HETERO3,
    "hetero4": HETERO4,
}


def counts(records):
    c = RE.count_by_kind(records)
    return c["interior"], c["stop"]


# ---------------------------------------------------------------------------- independent pieces
def hess_fd(segs, q, F, h=1e-4):
    """Hessian of E - F . tip by central differences of reference_tension_only's energy and tip."""
    n = len(segs)

    def L(x):
        return RT.energy(segs, x) - float(F @ RT.tip(segs, x))

    H = np.empty((n, n))
    for i, j in itertools.product(range(n), repeat=2):
        ei, ej = np.eye(n)[i] * h, np.eye(n)[j] * h
        H[i, j] = (L(q + ei + ej) - L(q + ei - ej) - L(q - ei + ej) + L(q - ei - ej)) / (4 * h * h)
    return H


def reduced_eigs(segs, q, F, stops):
    free = np.flatnonzero(stops == 0)
    Z = sl.null_space(RT.tip_jacobian(segs, q)[:, free])
    if Z.shape[1] == 0:
        return np.zeros(0)
    H = hess_fd(segs, q, F)[np.ix_(free, free)]
    return np.linalg.eigvalsh(Z.T @ H @ Z)


def independent_equilibria(segs, dx, dy=0.0, starts=120, seed=0):
    """Interior equilibria and one-stop (rigid, n = 3) equilibria by many-start ``scipy.optimize.root`` on
    reference_tension_only's torques / tip / Jacobian; returns ``[(q, stops, morse_index)]``."""
    n = len(segs)
    lim = RT.limits(segs)
    tgt = RT.target(segs, dx, dy)
    rng = np.random.default_rng(seed)
    out = []

    def add(q, stops, F):
        if any(np.max(np.abs(q - o[0])) < 1e-7 for o in out):
            return
        eig = reduced_eigs(segs, q, F, stops)
        out.append((q, stops, int(np.sum(eig < 0))))

    def kkt(x):
        q, F = x[:n], x[n:]
        return np.concatenate([-RT.torques(segs, q) - RT.tip_jacobian(segs, q).T @ F, RT.tip(segs, q) - tgt])

    for _ in range(starts):
        q0 = rng.uniform(-lim, lim)
        p = so.least_squares(lambda q: RT.tip(segs, q) - tgt, q0, xtol=1e-15, ftol=1e-15, gtol=1e-15)
        F0 = np.linalg.lstsq(RT.tip_jacobian(segs, p.x).T, -RT.torques(segs, p.x), rcond=None)[0]
        s = so.root(kkt, np.concatenate([p.x, F0]), method="hybr", tol=1e-14)
        q = s.x[:n]
        if np.max(np.abs(kkt(s.x))) < 1e-10 and np.all(np.abs(q) < lim - 1e-9):
            add(q, np.zeros(n, int), s.x[n:])
    if n == 3:                          # one joint at a stop, the other two fixed by the tip: rigid
        for i, sgn in itertools.product(range(3), (-1, 1)):
            free = [j for j in range(3) if j != i]
            for _ in range(24):
                def tipres(x, i=i, sgn=sgn, free=free):
                    q = np.empty(3)
                    q[i], q[free] = sgn * lim[i], x
                    return RT.tip(segs, q) - tgt
                s = so.root(tipres, rng.uniform(-lim[free], lim[free]), method="hybr", tol=1e-14)
                q = np.empty(3)
                q[i], q[free] = sgn * lim[i], s.x
                if np.max(np.abs(tipres(s.x))) > 1e-11 or np.any(np.abs(q[free]) >= lim[free] - 1e-9):
                    continue
                g, J = -RT.torques(segs, q), RT.tip_jacobian(segs, q)
                F = np.linalg.solve(J[:, free].T, g[free])
                if -sgn * (g[i] - J[:, i] @ F) > 0:
                    stops = np.zeros(3, int)
                    stops[i] = sgn
                    add(q, stops, F)
    return out


# ---------------------------------------------------------------------------- 1. closed forms
@pytest.mark.parametrize("name", ["paper4-tension", "hetero4", "hetero3"])
def test_closed_forms_match_reference_tension_only(name):
    segs = CHAINS[name]
    ch = RE._chain(segs)
    rng = np.random.default_rng(1)
    assert np.allclose(ch.lim, RT.limits(segs))
    for _ in range(30):
        q = rng.uniform(-1, 1, len(segs)) * ch.lim
        E, dE, d2E = RE._energy_derivs(ch, q)
        assert E == pytest.approx(RT.energy(segs, q), abs=1e-13)
        assert np.allclose(dE, -RT.torques(segs, q), atol=1e-12)
        if np.min(np.abs(RT.lengths(segs, q) - ch.L0)) > 1e-3:          # away from a tension-only kink
            assert np.allclose(d2E, RT.stiffness(segs, q), atol=1e-6)
        tip, J, _, _ = RE._kin(ch, q)
        assert np.allclose(tip, RT.tip(segs, q), atol=1e-13)
        assert np.allclose(J, RT.tip_jacobian(segs, q), atol=1e-13)
        F = rng.normal(size=2)
        H = RE._hess_L(ch, q, F)
        Ht = H - np.diag(d2E)
        h = 1e-5
        fd = np.column_stack([(-(RT.tip_jacobian(segs, q + h * e) - RT.tip_jacobian(segs, q - h * e)).T @ F)
                              / (2 * h) for e in np.eye(len(segs))])
        assert np.allclose(Ht, fd, atol=1e-8)
    # at the stops: the one-sided limit from inside
    for sgn in (-1, 1):
        assert np.allclose(RE._energy_derivs(ch, sgn * ch.lim)[1], -RT.torques(segs, sgn * ch.lim), atol=1e-9)


@pytest.mark.parametrize("name", ["paper4-tension", "hetero4"])
def test_inverse_kinematics_of_every_chart_hits_the_target(name):
    segs = CHAINS[name]
    ch = RE._chain(segs)
    rng = np.random.default_rng(2)
    Q = rng.uniform(-1, 1, (200, 4)) * ch.lim
    tips = RE._kin(ch, Q)[0]
    for i, j in itertools.combinations(range(4), 2):
        hit = np.zeros(200, bool)
        for sigma in (1.0, -1.0):
            for t in range(20):
                S, ok = RE._ik(ch, Q[t:t + 1], i, j, sigma, tips[t])
                assert ok[0]
                assert np.allclose(RE._kin(ch, S)[0], tips[t], atol=1e-12)
                keep = [p for p in range(4) if p not in (i, j)]
                assert np.allclose(S[0, keep], Q[t, keep])
                hit[t] |= np.allclose(RE._wrap(S[0] - Q[t]), 0.0, atol=1e-9)
        assert hit[:20].all()                          # one of the two elbows is the configuration itself


# ---------------------------------------------------------------------------- 2. the paper's count
@pytest.mark.slow
def test_paper_chain_linear_has_the_six_equilibria_of_table_2():
    r = eq("paper4-linear", 0.1)
    interior, stop = counts(r)
    assert interior == {0: 2, 1: 2, 2: 2} and stop == {}
    assert len(r) == 6 and not any(x.degenerate for x in r)
    pattern = {0: {"+---", "-+++"}, 1: {"+-++", "-+--"}, 2: {"+-+-", "-+-+"}}        # U, ZU, Z
    for x in r:
        assert "".join("+" if v > 0 else "-" for v in x.q) in pattern[x.morse_index]
    E = [x.energy for x in r]
    assert E == sorted(E)
    assert E[0] == pytest.approx(E[1], abs=1e-12) and r[0].morse_index == r[1].morse_index == 0
    assert np.allclose(r[0].q, -r[1].q, atol=1e-10)                                   # the mirror pair


@pytest.mark.slow
def test_paper_chain_linear_at_the_default_grid():
    r = RE.equilibria(CHAINS["paper4-linear"], 0.1, 0.0)
    assert counts(r) == ({0: 2, 1: 2, 2: 2}, {})
    assert not RE.missing(r, eq("paper4-linear", 0.1)) and not RE.missing(eq("paper4-linear", 0.1), r)


def test_two_segments_closed_form():
    segs = CHAINS["paper2-tension"]
    dx = 0.7
    r = RE.equilibria(segs, dx)
    tgt = RT.target(segs, dx)
    l1, l2 = 2.0, 1.0
    px, py = tgt[0] - 1.0, tgt[1]
    q2 = math.acos((px * px + py * py - l1 * l1 - l2 * l2) / (2 * l1 * l2))
    want = []
    for s in (1, -1):
        q1 = math.atan2(py, px) - math.atan2(l2 * math.sin(s * q2), l1 + l2 * math.cos(s * q2))
        want.append(np.array([q1, s * q2]))
    assert len(r) == 2
    for x in r:
        assert x.morse_index == 0 and x.kind == "interior"
        assert min(np.max(np.abs(x.q - w)) for w in want) < 1e-12


def test_unreachable_target_has_no_equilibrium():
    segs = uniform(3, 1.0, 1.0, 1.0, 1.0, "linear")
    assert RE.equilibria(segs, 4.0) == []
    with pytest.raises(ValueError):
        RT.least_energy(segs, 4.0)


# ---------------------------------------------------------------------------- 3. n = 3 against an independent search
N3_CASES = [((1.0, 1.0, 1.0, 1.0), 0.1), ((1.0, 1.0, 1.0, 1.0), 1.0), ((0.8, 1.2, 2.5, 1.7), 0.5),
            ((0.5, 1.0, 1.0, 1.0), 0.5), ((0.6, 1.0, 1.0, 1.0), 1.5), ((1.0, 1.0, 1.0, 1.0), 2.0)]


@pytest.mark.slow
@pytest.mark.parametrize("params,dx", N3_CASES, ids=[f"{p}-dx{d}" for p, d in N3_CASES])
def test_n3_uniform_linear_counts_match_an_independent_multistart(params, dx):
    segs = uniform(3, *params, "linear")
    r = RE.equilibria(segs, dx)
    ind = independent_equilibria(segs, dx, 0.0, starts=150, seed=3)
    by_index = {}
    for q, stops, m in ind:
        key = ("stop" if stops.any() else "interior", m)
        by_index[key] = by_index.get(key, 0) + 1
    mine = {(x.kind, x.morse_index): 0 for x in r}
    for x in r:
        mine[(x.kind, x.morse_index)] += 1
    assert mine == by_index
    for q, stops, m in ind:                                    # and point by point
        twin = [x for x in r if np.max(np.abs(x.q - q)) < 1e-7]
        assert len(twin) == 1 and twin[0].morse_index == m and np.array_equal(twin[0].stops, stops)


@pytest.mark.slow
@pytest.mark.parametrize("dx", [1.0, 2.0])
def test_n3_tension_only_against_an_independent_multistart(dx):
    segs = CHAINS["paper3-tension"]
    r = RE.equilibria(segs, dx)
    ind = independent_equilibria(segs, dx, 0.0, starts=150, seed=4)
    assert len(ind) == len(r)
    for q, stops, m in ind:
        twin = [x for x in r if np.max(np.abs(x.q - q)) < 1e-7]
        assert len(twin) == 1 and twin[0].morse_index == m and np.array_equal(twin[0].stops, stops)


# ---------------------------------------------------------------------------- 4. every record's equations
RECORD_CASES = [("paper3-tension", 1.0, 0.0), ("paper3-tension", 2.0, 0.0), ("hetero3", 1.2, 0.3),
                ("paper4-tension", 2.0, 0.0), ("paper4-tension", 1.5, 0.0), ("hetero4", 2.5, -0.4),
                ("paper4-linear", 0.1, 0.0)]


@pytest.mark.slow_cases(keep=3)
@pytest.mark.parametrize("name,dx,dy", RECORD_CASES, ids=[f"{c[0]}-{c[1]}-{c[2]}" for c in RECORD_CASES])
def test_every_record_satisfies_its_equations(name, dx, dy):
    segs = CHAINS[name]
    r = eq(name, dx, dy)
    assert r, "no equilibrium"
    lim = RT.limits(segs)
    tgt = RT.target(segs, dx, dy)
    for x in r:
        q, F, stops = x.q, x.F, x.stops
        g = -RT.torques(segs, q)
        res = g - RT.tip_jacobian(segs, q).T @ F
        free = stops == 0
        assert np.max(np.abs(RT.tip(segs, q) - tgt)) < 1e-10
        assert np.max(np.abs(res[free])) < 1e-10
        assert np.all(np.abs(q[free]) < lim[free])
        assert np.array_equal(q[~free], stops[~free] * lim[~free])
        assert free.sum() >= 2 or "tip force not unique" in x.reasons      # three stops: F only bounded
        assert np.all(x.contact_torques >= 0) and np.all(x.contact_torques[free] == 0)
        assert np.allclose(x.contact_torques[~free], -stops[~free] * res[~free], atol=1e-10)
        if not x.degenerate:
            assert np.all(x.contact_torques[~free] > 0)
        assert x.energy == pytest.approx(RT.energy(segs, q), abs=1e-12)
        eig = reduced_eigs(segs, q, F, stops)
        assert eig.size == max(free.sum() - 2, 0)
        if eig.size and np.min(np.abs(eig)) > 1e-3:
            assert int(np.sum(eig < 0)) == x.morse_index
            assert np.allclose(np.sort(eig), np.sort(x.eigenvalues), atol=1e-5)
    assert [x.energy for x in r] == sorted(x.energy for x in r)
    assert len({tuple(np.round(x.q, 6)) for x in r}) == len(r)                   # distinct
    if dy == 0.0 and name.startswith("paper"):                                   # mirror images
        for x in r:
            assert any(np.max(np.abs(y.q + x.q)) < 1e-8 for y in r)


# ---------------------------------------------------------------------------- 5. least energy
LEAST_CASES = [("paper3-tension", 1.0, 0.0), ("paper3-tension", 2.0, 0.0), ("hetero3", 1.2, 0.3),
               ("paper4-tension", 2.0, 0.0), ("paper4-tension", 1.5, 0.0), ("hetero4", 2.5, -0.4),
               ("paper4-tension", 3.0, 0.0)]


@pytest.mark.slow_cases(keep=3)
@pytest.mark.parametrize("name,dx,dy", LEAST_CASES, ids=[f"{c[0]}-{c[1]}-{c[2]}" for c in LEAST_CASES])
def test_least_stable_record_is_the_least_energy(name, dx, dy):
    segs = CHAINS[name]
    stable = [x for x in eq(name, dx, dy) if x.morse_index == 0]
    le = RT.least_energy(segs, dx, dy)
    assert stable[0].energy == pytest.approx(le.energy, abs=1e-8)
    assert min(np.max(np.abs(x.q - le.q)) for x in stable if abs(x.energy - le.energy) < 1e-8) < 1e-5
    # and nothing below it, stable or not: the global minimum is an equilibrium
    assert min(x.energy for x in eq(name, dx, dy)) == pytest.approx(le.energy, abs=1e-8)


@pytest.mark.slow
def test_paper_chain_tension_only_at_dx_2_least_energy_on_joint_3_stop():
    r = eq("paper4-tension", 2.0)
    best = r[0]
    assert best.energy == pytest.approx(4.8601351, abs=1e-7)
    assert best.morse_index == 0 and abs(best.stops[2]) == 1 and np.count_nonzero(best.stops) == 1
    assert best.contact_torques[2] > 0.1
    assert r[1].energy == pytest.approx(best.energy, abs=1e-12) and r[1].stops[2] == -best.stops[2]


# ---------------------------------------------------------------------------- 6. against the batched multistart
@pytest.mark.slow
def test_paper_chain_tension_only_multistart_finds_nothing_else():
    r = eq("paper4-tension", 2.0)
    m = RE.multistart(CHAINS["paper4-tension"], 2.0, 0.0, starts=1500, seed=7)
    assert not RE.missing(r, m)
    assert RE.count_by_kind(r) == {"interior": {1: 4, 2: 4}, "stop": {0: 16, 1: 12}, "degenerate": 2, "total": 36}


@pytest.mark.slow
@pytest.mark.parametrize("dx", [0.5, 1.5, 2.0, 3.0])
def test_paper_chain_tension_only_default_grid_and_3000_starts(dx):
    segs = CHAINS["paper4-tension"]
    r = RE.equilibria(segs, dx, 0.0)
    m = RE.multistart(segs, dx, 0.0, starts=3000, seed=11)
    assert not RE.missing(r, m)
    assert not RE.missing(r, eq("paper4-tension", dx)) and not RE.missing(eq("paper4-tension", dx), r)


def test_count_by_kind_and_records():
    r = eq("paper3-tension", 1.0)
    c = RE.count_by_kind(r)
    assert c["total"] == len(r) == sum(c["interior"].values()) + sum(c["stop"].values())
    assert {x.kind for x in r} == {"interior", "stop"}
    assert all(x.stable == (x.morse_index == 0) for x in r)
