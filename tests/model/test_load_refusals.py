"""Every public verb honours a chain's dead loads or refuses them by name (issue "weights and loads anywhere").

A loaded chain (gravity on its masses, or a joint force) must never be answered as if it carried nothing: each verb
either includes the loads (its answer differs from the unloaded chain's and says ``loads``) or raises
:class:`UnsupportedError` naming ``gravity`` / ``joint_forces``. The list of verbs is read from ``to.__all__``, so a
new verb without an entry here fails :func:`test_every_public_verb_is_listed`.
"""

from __future__ import annotations

import inspect

import numpy as np
import pytest

import tensegrity_opt as to
from tensegrity_opt.errors import UnsupportedError
from tensegrity_opt.model.loads import LOAD_ANALYSES

HEAVY = to.Manipulator.uniform(3, mass=0.05, payload=0.02, gravity=(0.0, -9.81))
PUSHED = to.Manipulator.uniform(3, joint_forces=[(2, (0.0, 0.3))])
BARE = to.Manipulator.uniform(3, mass=0.05, payload=0.02)        # masses without gravity: no load


def _bare_eq():
    return to.solve_equilibrium(BARE, 0.3)


#: The verbs that refuse a loaded chain, each called on ``m``.
REFUSED = {
    "find_equilibria_under_force": lambda m: to.find_equilibria_under_force(m, -0.1, 0.0),
    "critical_force": lambda m: to.critical_force(m),
    "energy_lower_bound": lambda m: to.energy_lower_bound(m, 0.3),
    "solve_equilibria_batch": lambda m: to.solve_equilibria_batch(m, [0.1, 0.2]),
    "Tracker": lambda m: to.Tracker(m),
    "trace_branch": lambda m: to.trace_branch(m, _bare_eq(), "displacement", t_max=0.1),
    "bifurcation_diagram": lambda m: to.bifurcation_diagram(m, _bare_eq(), to.Control.displacement(), t_max=0.1),
    "limit_load": lambda m: to.limit_load(m),
    "imperfection_sensitivity": lambda m: to.imperfection_sensitivity(m, [0.01, 0.02]),
    "stability_boundary": lambda m: to.stability_boundary(m, "displacement", "k"),
    "stability_atlas": lambda m: to.stability_atlas(m, [0.1, 0.2], [0.0]),
    "simulate": lambda m: to.simulate(m, loads=np.zeros((3, 2))),
    "maximize_critical_force": lambda m: to.maximize_critical_force(m),
    "preloads_for_pose": lambda m: to.preloads_for_pose(m, (5.5, 0.3)),
    "preloads_for_critical_force": lambda m: to.preloads_for_critical_force(m, 0.5),
    "preloads_for_stiffness": lambda m: to.preloads_for_stiffness(m, (5.5, 0.3), K_desired=np.eye(2)),
    "plan_preloads": lambda m: to.plan_preloads(m, [[5.5, 0.3]]),
    "PreloadController": lambda m: to.PreloadController(m),
    "PreloadFollower": lambda m: to.PreloadFollower(m),
    "load_capacity (guided)": lambda m: to.load_capacity(m, boundary="guided"),
    "estimate_tip_force": lambda m: to.estimate_tip_force(m, _bare_eq().q),
    "critical_load_sensitivity": lambda m: to.critical_load_sensitivity(m),
    "equilibrium_sensitivity": lambda m: to.equilibrium_sensitivity(m, _bare_eq()),
    "critical_load_map": lambda m: to.critical_load_map(m, "k", [1.0, 2.0], "L0", [1.0, 1.1]),
    "solve_equilibrium (certify)": lambda m: to.solve_equilibrium(m, 0.3, certify=True),
    "solve_equilibrium (homotopy)": lambda m: to.solve_equilibrium(m, 0.3, method="homotopy"),
    "find_equilibria (homotopy)": lambda m: to.find_equilibria(m, 0.3, 0.1, method="homotopy"),
    "force_deflection (from rest)": lambda m: to.force_deflection(m, [0.1, 0.2], reference="rest"),
}

#: The verbs that honour the loads: each returns an answer under them (checked against the unloaded one below).
HONOURED = {
    "solve_equilibrium": lambda m: to.solve_equilibrium(m, 0.6, 0.2),
    "find_equilibria": lambda m: to.find_equilibria(m, 0.6, 0.2)[0],
    "solve_equilibrium_under_force": lambda m: to.solve_equilibrium_under_force(m, -0.05, 0.0),
    "rest_configuration": lambda m: to.rest_configuration(m),
    "find_equilibria_under_force (stable)": lambda m: to.find_equilibria_under_force(m, stable_only=True)[0],
}

#: Public names that are not analyses of a chain (types, helpers, errors) or take a result, not a chain.
NOT_VERBS = {"Segment", "Manipulator", "shape_label", "sign_string", "time_limit", "sweep", "switch_branch",
             "limit_arms", "Control"}


def test_every_public_verb_is_listed():
    listed = {name.split(" ")[0] for name in (*REFUSED, *HONOURED)} | {"cartesian_stiffness", "modes",
                                                                      "energy_landscape", "force_deflection",
                                                                      "load_capacity", "preloads_for_holding",
                                                                      "holding_map", "weight_capacity"}
    verbs = {name for name in to.__all__ if (inspect.isfunction(getattr(to, name)) or
                                             (inspect.isclass(getattr(to, name)) and
                                              not issubclass(getattr(to, name), Exception) and
                                              name[0].isupper() and name in ("Tracker", "PreloadController",
                                                                             "PreloadFollower")))}
    missing = verbs - listed - NOT_VERBS
    assert not missing, f"public verbs that neither honour nor refuse the loads here: {sorted(missing)}"


@pytest.mark.parametrize("name", sorted(REFUSED))
@pytest.mark.parametrize("m, field", [(HEAVY, "gravity"), (PUSHED, "joint_forces")], ids=["gravity", "joint"])
def test_a_verb_that_does_not_honour_the_loads_refuses_them_by_name(name, m, field):
    with pytest.raises(UnsupportedError) as e:
        REFUSED[name](m)
    # the free-tip set under loads has its stable members only: the refusal names the option that asks for them
    want = {"find_equilibria_under_force": "stable_only"}.get(name, field)
    assert e.value.field == want, (name, e.value)
    assert "dead loads" in str(e.value) or "stable_only" in str(e.value)


def test_the_refusal_names_what_honours_the_loads():
    with pytest.raises(UnsupportedError) as e:
        to.critical_force(HEAVY)
    for name in LOAD_ANALYSES:
        assert name in str(e.value)


@pytest.mark.parametrize("name", sorted(HONOURED))
def test_a_verb_that_honours_the_loads_answers_under_them(name):
    loaded, bare = HONOURED[name](HEAVY), HONOURED[name](BARE)
    assert loaded.loads is not None and bare.loads is None
    assert loaded.to_dict()["loads"] == {"gravity": [0.0, -9.81], "payload": 0.02, "joint_forces": []}
    assert float(np.abs(loaded.q - bare.q).max()) > 1e-3          # the weights bend the chain
    # the answer balances the loads: grad(E + V) = J^T F on the free joints, checked in numpy
    r = HEAVY.potential_gradient(loaded.q) - HEAVY.jacobian(loaded.q).T @ loaded.force
    assert np.abs(r[~loaded.at_stop]).max() < 1e-9 * HEAVY.torque_scale


def test_stiffness_modes_and_the_landscape_include_the_loads():
    eq = to.solve_equilibrium(HEAVY, 0.6, 0.2)
    K = to.cartesian_stiffness(HEAVY, eq)
    # the tangent stiffness by differences of the loaded solves (the tip force's change per tip displacement)
    h = 1e-5
    cols = []
    for d in ((h, 0.0), (0.0, h)):
        up = to.solve_equilibrium(HEAVY, 0.6 - d[0], 0.2 + d[1], q0=eq.q, local=True)
        dn = to.solve_equilibrium(HEAVY, 0.6 + d[0], 0.2 - d[1], q0=eq.q, local=True)
        cols.append((up.force - dn.force) / (2 * h))
    np.testing.assert_allclose(K, np.column_stack(cols), rtol=1e-5, atol=1e-7)
    md = to.modes(HEAVY, eq)
    assert md.to_dict()["loads"]["gravity"] == [0.0, -9.81]
    assert not np.allclose(md.stiffness_matrix, to.modes(BARE, to.solve_equilibrium(BARE, 0.6, 0.2)).stiffness_matrix)
    m4 = to.Manipulator.uniform(4, mass=0.05, gravity=(0.0, -9.81))
    land = to.energy_landscape(m4, 2.0, grid=5)
    finite = np.isfinite(land.energy)
    E = np.array([m4.potential_energy(q) for q in land.q[finite]])
    np.testing.assert_allclose(land.energy[finite], E, rtol=1e-12)
    assert land.to_dict()["loads"]["gravity"] == [0.0, -9.81]
    c = to.force_deflection(HEAVY, [0.3, 0.6], 0.2)
    assert c.success and c.to_dict()["loads"]["payload"] == 0.02
    for i, dx in enumerate((0.3, 0.6)):                 # each point is the least-potential equilibrium there
        assert c.energy[i] == pytest.approx(to.solve_equilibrium(HEAVY, dx, 0.2).energy, rel=1e-9)
    assert to.force_deflection(BARE, [0.3]).to_dict()["loads"] is None


def test_masses_without_gravity_and_gravity_without_masses_change_nothing():
    plain = to.Manipulator.uniform(3)
    for m in (BARE, to.Manipulator.uniform(3, gravity=(0.0, -9.81))):
        assert not m.loaded
        a, b = to.solve_equilibrium(m, 0.6, 0.2), to.solve_equilibrium(plain, 0.6, 0.2)
        assert a.q.tolist() == b.q.tolist() and a.energy == b.energy and a.force.tolist() == b.force.tolist()
        assert a.loads is None and to.critical_force(m).force == to.critical_force(plain).force
