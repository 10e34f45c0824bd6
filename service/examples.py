"""Request and response examples for the OpenAPI document (values from the paper's chain, rounded)."""

from __future__ import annotations

from typing import Any

PAPER_CHAIN = {"n": 4, "a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0}

EQUILIBRIUM = {
    "success": True, "status": "converged", "message": "converged (Newton_Converged, 3 iterations)",
    "q": [0.178155, -0.076587, -0.245053, -0.131183], "energy": 4.057381,
    "force": {"fx": -0.574823, "fy": 0.025785}, "morse_index": 0, "stable": True, "kind": "minimum",
    "shape": "U", "signs": "+---", "tip": [7.9, 0.0],
    "solver": {"status": "Newton_Converged", "iterations": 3},
}
FORCE_EQUILIBRIUM = {
    "success": True, "status": "converged", "message": "converged (Solve_Succeeded, 10 iterations)",
    "q": [-1.532346, -0.809098, -0.358652, -0.100399], "energy": 5.509784,
    "force": {"fx": -0.3, "fy": 0.0}, "morse_index": 0, "stable": True, "kind": "minimum",
    "shape": "C", "signs": "----", "tip": [-3.066931, -4.62255],
    "solver": {"status": "Solve_Succeeded", "iterations": 10},
}


def _eq(q, energy, fx, fy, mi, kind, shape, signs) -> dict[str, Any]:
    return {"success": True, "status": "converged", "message": "converged (Newton_Converged, 5 iterations)",
            "q": q, "energy": energy, "force": {"fx": fx, "fy": fy}, "morse_index": mi, "stable": mi == 0,
            "kind": kind, "shape": shape, "signs": signs, "tip": [7.9, 0.0],
            "solver": {"status": "converged", "iterations": 5}}


EQUILIBRIA = {
    "success": True, "status": "certified",
    "message": "phc (1 run): 456 paths, 0 failed, 0 at infinity, 0 singular; 6 real roots in range",
    "equilibria": [
        _eq([0.178155, -0.076587, -0.245053, -0.131183], 4.057381, -0.574823, 0.025785, 0, "minimum", "U", "+---"),
        _eq([-0.178155, 0.076587, 0.245053, 0.131183], 4.057381, -0.574823, -0.025785, 0, "minimum", "U", "-+++"),
        _eq([0.183914, -0.370084, 0.085087, 0.308833], 4.1364, -1.365098, 0.026617, 1, "saddle", "ZU", "+-++"),
        _eq([-0.183914, 0.370084, -0.085087, -0.308833], 4.1364, -1.365098, -0.026617, 1, "saddle", "ZU", "-+--"),
        _eq([0.076358, -0.239509, 0.365593, -0.434349], 4.192165, -1.921865, 0.011064, 2, "maximum", "Z", "+-+-"),
        _eq([-0.076358, 0.239509, -0.365593, 0.434349], 4.192165, -1.921865, -0.011064, 2, "maximum", "Z", "-+-+"),
    ], "method": "homotopy", "certified": True, "paths": 456, "failed_paths": 0}
_PROVEN = ("Krawczyk's test in ball arithmetic proved 6 of 6 equilibria (each the only one in its box, real, inside "
           "the joint range, the boxes pairwise disjoint) and 6 Morse indices")
EQUILIBRIA["message"] += "; " + _PROVEN
EQUILIBRIA["certificate"] = {
    "success": True, "status": "proven", "message": _PROVEN,
    "method": "krawczyk (arb)", "control": "displacement", "paths": 456, "roots_proven": True, "morse_proven": True,
    "nonreal_checked": 0, "nonreal_proven": 0, "outside_checked": 0, "outside_proven": 0, "seconds": 0.003,
    "boxes": [{"lower": [round(v - 1e-9, 10) for v in e["q"] + [e["force"]["fx"], e["force"]["fy"]]],
               "upper": [round(v + 1e-9, 10) for v in e["q"] + [e["force"]["fx"], e["force"]["fy"]]],
               "proven": True, "morse_index": e["morse_index"], "morse_proven": True, "reason": ""}
              for e in EQUILIBRIA["equilibria"]]}

BUCKLING = {
    "success": True, "status": "solved",
    "message": "all 3 critical loads of the straight chain, tip guided (reduced eigenproblem)",
    "boundary": "guided", "critical_force": -0.572793, "loads": [0.572793, 1.362906, 1.921444],
    "modes": [
        {"load": 0.572793, "q": [0.525309, -0.226566, -0.71889, -0.387664], "fy": 0.075044,
         "energy_factor": 1.145586, "mu_x": 0.868, "fy_coefficient": 0.080548, "shape": "U", "signs": "+---",
         "stable": True},
        {"load": 1.362906, "q": [0.351521, -0.707094, 0.161697, 0.589732], "fy": 0.050217,
         "energy_factor": 2.725813, "mu_x": 0.365938, "fy_coefficient": 0.083014, "shape": "ZU", "signs": "+-++",
         "stable": False},
        {"load": 1.921444, "q": [0.123572, -0.386608, 0.588903, -0.698674], "fy": 0.017653,
         "energy_factor": 3.842887, "mu_x": 0.26014, "fy_coefficient": 0.034611, "shape": "Z", "signs": "+-+-",
         "stable": False},
    ],
}

FORCE_DEFLECTION = {
    "success": True, "status": "complete", "message": "all 3 requested points computed",
    "points": [
        {"dx": 0.0, "dy": 0.0, "fx": 0.0, "fy": 0.0, "energy": 4.0, "q": [0.0, 0.0, 0.0, 0.0], "stable": True,
         "morse_index": 0, "shape": "I", "branch": -1, "status": "straight",
         "solver": {"status": "straight", "iterations": 0}},
        {"dx": 0.05, "dy": 0.0, "fx": -0.57381, "fy": 0.018121, "energy": 4.028665,
         "q": [0.126027, -0.054267, -0.172908, -0.092902], "stable": True, "morse_index": 0, "shape": "U",
         "branch": 0, "status": "converged", "solver": {"status": "Newton_Converged", "iterations": 2}},
        {"dx": 0.1, "dy": 0.0, "fx": -0.574823, "fy": 0.025785, "energy": 4.057381,
         "q": [0.178155, -0.076587, -0.245053, -0.131183], "stable": True, "morse_index": 0, "shape": "U",
         "branch": 0, "status": "converged", "solver": {"status": "Newton_Converged", "iterations": 4}},
    ],
    "jumps": [{"kind": "buckling", "dx_before": 0.0, "dx_after": 0.05, "force_before": {"fx": 0.0, "fy": 0.0},
               "force_after": {"fx": -0.572793, "fy": 0.0}, "branch_before": -1, "branch_after": 0,
               "delta": {"fx": -0.572793, "fy": 0.0},
               "label": "buckling of the straight chain: F_x 0 -> -0.573 (compressive)"}],
    "branches": [],
    "reference": "straight", "origin": [0.0, 0.0],
    "ended_at": None, "requested": 3,
}

MODES = {"success": True, "status": "solved",
         "message": "2 modes with the tip held; lowest frequency 4.14815 rad/s (0.660198 Hz)",
         "frequencies": [4.148146, 12.167975], "eigenvalues": [17.207114, 148.059609],
         "shapes": [[-1.964038, 3.982533, -1.119163, -2.904969], [-1.336268, 4.686772, -8.292312, 10.911387]],
         "tip": "held", "held_joints": [False, False, False, False], "total_mass": 0.4, "equilibrium": EQUILIBRIUM}
STIFFNESS = {"matrix": [[0.020242, -0.132106], [-0.132106, -0.06731]], "equilibrium": EQUILIBRIUM}

SEGMENT_TORQUE = {"q": [-0.5, 0.0, 0.5], "torque": [0.494808, 0.0, -0.494808],
                  "dtorque": [-0.968912, -1.0, -0.968912], "energy": [1.12435, 1.0, 1.12435],
                  "stiffness": 1.0, "monotonic": True, "joint_limit": 1.570796}

ENERGY_LANDSCAPE = {"success": True, "status": "evaluated",
                    "message": "the energy on a 3 x 3 grid of (q1, q4), both elbow branches: 2 of 18 points "
                               "inside the reach and the physical range",
                    "pair": [0, 3], "qi": [-1.569226, 0.0, 1.569226], "qj": [-1.569226, 0.0, 1.569226],
                    "energy": [[[None, None, None], [None, 4.113585, None], [None, None, None]],
                               [[None, None, None], [None, 4.113585, None], [None, None, None]]]}

BATCH = {"results": [
    {"index": 0, "dx": 0.1, "dy": 0.0, "equilibrium": EQUILIBRIUM, "error": None},
    {"index": 1, "dx": 20.0, "dy": 0.0, "equilibrium": None,
     "error": {"code": "unreachable_target", "message": "target (-12, 0) for dx=20, dy=0 is beyond the chain's "
               "reach: distance 13 from joint 1 exceeds the total link length 7", "field": "targets[1].dx",
               "details": {"distance": 13.0, "reach": 7.0}}},
], "succeeded": 1, "failed": 1}

DESIGN = {
    "success": True, "status": "optimal",
    "message": "optimal design: critical load 0.691429, recomputed by critical_force (IPOPT Solve_Succeeded, 17 "
               "iterations)",
    "manipulator": {"segments": [{"a": 1.0, "b": 1.0, "k": 1.768, "L0": 1.0}, {"a": 1.0, "b": 1.0, "k": 0.2, "L0": 1.0},
                                 {"a": 1.0, "b": 1.0, "k": 1.178286, "L0": 1.0},
                                 {"a": 1.0, "b": 1.0, "k": 0.853714, "L0": 1.0}]},
    "critical_force": -0.691429, "loads": [0.691429, 0.846986, 1.751871], "multiplicity": 1,
    "active": ["k[1] >= 0.2", "sum(k) <= 4"], "initial_critical_force": -0.572793, "feasible": True,
    "solver": {"status": "Solve_Succeeded", "iterations": 17}}

PRELOADS = {
    "success": True, "status": "optimal",
    "message": "optimal rest lengths: the tip on the target, stable with margin 0.977663 (IPOPT Solve_Succeeded, 5 "
               "iterations)",
    "manipulator": {"segments": [{"a": 1.0, "b": 1.0, "k": 1.0, "L0": [1.041489, 0.944056]},
                                 {"a": 1.0, "b": 1.0, "k": 1.0, "L0": [0.736705, 1.198028]},
                                 {"a": 1.0, "b": 1.0, "k": 1.0, "L0": [0.468097, 1.248362]},
                                 {"a": 1.0, "b": 1.0, "k": 1.0, "L0": [0.785856, 1.154345]}]},
    "preloads": [[1.041489, 0.944056], [0.736705, 1.198028], [0.468097, 1.248362], [0.785856, 1.154345]],
    "q": [-0.294564, 0.281086, 0.697109, 0.321762], "margin": 0.977663, "tip": [7.0, 1.5], "energy": 4.215705,
    "solver": {"status": "Solve_Succeeded", "iterations": 5}}

#: ``/v1/design/holding``'s example chain: six segments in a vertical plane pointing up (gravity along -x).
UPRIGHT_ARM = {"n": 6, "a": 0.04, "b": 0.05, "k": 300.0, "L0": 0.05, "mass": 0.05, "payload": 0.1,
               "gravity": [-9.81, 0.0]}

#: ``/v1/control/weight-capacity``'s example chain: the upright arm stiff enough to stand.
UPRIGHT_STIFF_ARM = {**UPRIGHT_ARM, "k": 5000.0}

WEIGHT_CAPACITY = {
    "success": True, "status": "complete",
    "message": "the rest pose buckles (a bifurcation) when the weights are 1.25927 times theirs",
    "factor": 1.25927, "kind": "bifurcation", "reason": None, "end_factor": 1.25927,
    "q": [0.0, 0.0, 0.0, 0.0, 0.0, 0.0], "max_factor": 10.0}

HOLDING = {
    "success": True, "status": "optimal",
    "message": "the least stiffness (total 36033.9) holding the chain under gravity (-9.81, 0), payload 0.1: largest "
               "joint angle 9.687e-13 rad, margin 0.001 (Solve_Succeeded)",
    "manipulator": {"segments": [{"a": 0.04, "b": 0.05, "k": k, "L0": 0.05, "mass": 0.05}
                                 for k in (5046.571429, 4556.071429, 3715.214286, 2664.142857, 1543.0, 491.928571)],
                    "payload": 0.1, "gravity": [-9.81, 0.0]},
    "vary": ["k"], "change": [16.821905, 15.186905, 12.384048, 8.880476, 5.143333, 1.639762],
    "q": [0.0, 0.0, 0.0, 0.0, 0.0, 0.0], "margin": 0.001, "tension": 1801.692857, "stiffness": 36033.857143,
    "solver": {"status": "Solve_Succeeded", "iterations": 189}}

# ---------------------------------------------------------------------------- loading paths
#: ``/v1/rest-configurations`` of the paper's chain unloaded: the straight chain, exactly.
REST_CONFIGURATIONS = {
    "success": True, "status": "exact", "message": "the product of the segments' unloaded critical points: 1 point",
    "equilibria": [
        {"success": True, "status": "exact",
         "message": "exact: the unloaded chain, a product of its segments' critical points",
         "q": [0.0, 0.0, 0.0, 0.0], "energy": 4.0, "force": {"fx": 0.0, "fy": 0.0}, "morse_index": 0, "stable": True,
         "kind": "minimum", "shape": "I", "signs": "0000", "tip": [8.0, 0.0],
         "solver": {"status": "exact", "iterations": 0}}],
    "method": "exact", "certified": True, "paths": 0, "failed_paths": 0, "certificate": None}

#: ``/v1/branch``, ``/v1/bifurcation-diagram``, ``/v1/limit-load``: the paper's chain under a guided load from
#: the straight chain (``trace_branch(m, zeros(4), "guided", t_max=0.7, max_points=12)``; the diagram with
#: ``depth=1, max_branches=3, t_min=-0.05``, whose first branch is that branch; ``limit_load(m, (-1, 0), "guided",
#: start=zeros(4))``).
BRANCH = {'success': True,
 'status': 'max_points',
 'message': 'max_points = 12 reached',
 'control': {'kind': 'guided', 'direction': [-1.0, 0.0], 'base': [0.0, 0.0]},
 'points': 12,
 't': [0.0, 0.014142, 0.033941, 0.06166, 0.100466, 0.154794, 0.225505, 0.296216, 0.366926, 0.437637, 0.508348,
       0.579058],
 'q': [[0.0, 0.0, 0.0, 0.0], [0.0, 0.0, 0.0, 0.0], [0.0, 0.0, 0.0, 0.0], [0.0, 0.0, 0.0, 0.0], [0.0, 0.0, 0.0, 0.0],
       [0.0, 0.0, 0.0, 0.0], [0.0, 0.0, 0.0, 0.0], [0.0, 0.0, 0.0, 0.0], [0.0, 0.0, 0.0, 0.0], [0.0, 0.0, 0.0, 0.0],
       [0.0, 0.0, 0.0, 0.0], [0.0, 0.0, 0.0, 0.0]],
 'force': [{'fx': 0.0, 'fy': 0.0}, {'fx': -0.014142, 'fy': 0.0}, {'fx': -0.033941, 'fy': 0.0},
           {'fx': -0.06166, 'fy': 0.0}, {'fx': -0.100466, 'fy': 0.0}, {'fx': -0.154794, 'fy': 0.0},
           {'fx': -0.225505, 'fy': 0.0}, {'fx': -0.296216, 'fy': 0.0}, {'fx': -0.366926, 'fy': 0.0},
           {'fx': -0.437637, 'fy': 0.0}, {'fx': -0.508348, 'fy': 0.0}, {'fx': -0.579058, 'fy': 0.0}],
 'tip': [[8.0, 0.0], [8.0, 0.0], [8.0, 0.0], [8.0, 0.0], [8.0, 0.0], [8.0, 0.0], [8.0, 0.0], [8.0, 0.0], [8.0, 0.0],
         [8.0, 0.0], [8.0, 0.0], [8.0, 0.0]],
 'deflection': [[0.0, 0.0], [0.0, 0.0], [0.0, 0.0], [0.0, 0.0], [0.0, 0.0], [0.0, 0.0], [0.0, 0.0], [0.0, 0.0],
                [0.0, 0.0], [0.0, 0.0], [0.0, 0.0], [0.0, 0.0]],
 'energy': [4.0, 4.0, 4.0, 4.0, 4.0, 4.0, 4.0, 4.0, 4.0, 4.0, 4.0, 4.0],
 'morse_index': [0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1],
 'stable': [True, True, True, True, True, True, True, True, True, True, True, False],
 's': [0.0, 0.02, 0.048, 0.0872, 0.14208, 0.218912, 0.318912, 0.418912, 0.518912, 0.618912, 0.718912, 0.818912],
 'events': [{'kind': 'branch_point',
             'index': 10,
             't': 0.572793,
             'q': [0.0, 0.0, 0.0, 0.0],
             'force': {'fx': -0.572793, 'fy': 0.0},
             'tip': [8.0, 0.0],
             'energy': 4.0,
             'null_vector': [-0.730722, 0.315161, 1.0, 0.539254],
             'morse_before': 0,
             'morse_after': 1,
             'stability': 'lost',
             'method': 'test_function',
             'residual': 0.0,
             'joint': None}]}

BIFURCATION_DIAGRAM = {'branches': [BRANCH,
              {'success': True,
               'status': 't_min',
               'message': 't reached t_min = -0.05',
               'control': {'kind': 'guided', 'direction': [-1.0, 0.0], 'base': [0.0, 0.0]},
               'points': 4,
               't': [0.0, -0.014142, -0.033941, -0.05],
               'q': [[0.0, 0.0, 0.0, 0.0], [0.0, 0.0, 0.0, 0.0], [0.0, 0.0, 0.0, 0.0], [0.0, 0.0, 0.0, 0.0]],
               'force': [{'fx': 0.0, 'fy': 0.0}, {'fx': 0.014142, 'fy': 0.0}, {'fx': 0.033941, 'fy': 0.0},
                         {'fx': 0.05, 'fy': 0.0}],
               'tip': [[8.0, 0.0], [8.0, 0.0], [8.0, 0.0], [8.0, 0.0]],
               'deflection': [[0.0, 0.0], [0.0, 0.0], [0.0, 0.0], [0.0, 0.0]],
               'energy': [4.0, 4.0, 4.0, 4.0],
               'morse_index': [0, 0, 0, 0],
               'stable': [True, True, True, True],
               's': [0.0, 0.02, 0.048, 0.070711],
               'events': []},
              {'success': True,
               'status': 'max_points',
               'message': 'max_points = 12 reached',
               'control': {'kind': 'guided', 'direction': [-1.0, 0.0], 'base': [0.0, 0.0]},
               'points': 12,
               't': [0.572793, 0.5728, 0.572821, 0.572875, 0.572996, 0.573257, 0.573799, 0.574812, 0.576165,
                     0.577849, 0.579852, 0.582156],
               'q': [[0.0, 0.0, 0.0, 0.0], [-0.010506, 0.004531, 0.014378, 0.007753],
                     [-0.021012, 0.009062, 0.028757, 0.015506], [-0.035718, 0.015403, 0.04889, 0.026356],
                     [-0.056301, 0.024275, 0.077087, 0.041539], [-0.085099, 0.036676, 0.116593, 0.062769],
                     [-0.125363, 0.053982, 0.171992, 0.092414], [-0.177633, 0.076364, 0.244327, 0.1308],
                     [-0.229689, 0.098526, 0.317021, 0.168877], [-0.281461, 0.120399, 0.39018, 0.206548],
                     [-0.332877, 0.141917, 0.463911, 0.243711], [-0.383856, 0.163011, 0.538318, 0.280263]],
               'force': [{'fx': -0.572793, 'fy': 0.0}, {'fx': -0.5728, 'fy': -0.001501},
                         {'fx': -0.572821, 'fy': -0.003002}, {'fx': -0.572875, 'fy': -0.005105},
                         {'fx': -0.572996, 'fy': -0.008053}, {'fx': -0.573257, 'fy': -0.012193},
                         {'fx': -0.573799, 'fy': -0.018025}, {'fx': -0.574812, 'fy': -0.025708},
                         {'fx': -0.576165, 'fy': -0.033538}, {'fx': -0.577849, 'fy': -0.041562},
                         {'fx': -0.579852, 'fy': -0.049831}, {'fx': -0.582156, 'fy': -0.0584}],
               'tip': [[8.0, 0.0], [7.999653, 0.0], [7.998611, 0.0], [7.995987, 0.0], [7.990028, 0.0],
                       [7.977213, 0.0], [7.950526, 0.0], [7.900586, 0.0], [7.83359, 0.0], [7.74974, 0.0],
                       [7.64929, 0.0], [7.532547, 0.0]],
               'deflection': [[0.0, 0.0], [0.000347, 0.0], [0.001389, 0.0], [0.004013, 0.0], [0.009972, 0.0],
                              [0.022787, 0.0], [0.049474, 0.0], [0.099414, 0.0], [0.16641, 0.0], [0.25026, 0.0],
                              [0.35071, 0.0], [0.467453, 0.0]],
               'energy': [4.0, 4.000199, 4.000795, 4.002299, 4.005713, 4.013058, 4.028363, 4.057044, 4.095599,
                          4.143982, 4.202128, 4.269956],
               'morse_index': [0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0],
               'stable': [False, True, True, True, True, True, True, True, True, True, True, True],
               's': [0.0, 0.02, 0.04, 0.068, 0.1072, 0.16208, 0.238912, 0.338913, 0.438914, 0.538915, 0.638916,
                     0.738918],
               'events': []}]}

LIMIT_LOAD = {'success': True,
 'status': 'stability_lost',
 'message': 'stability is lost at a bifurcation at load 0.5727928',
 'load': 0.572793,
 'kind': 'bifurcation',
 'force': {'fx': -0.572793, 'fy': 0.0},
 'q': [0.0, 0.0, 0.0, 0.0],
 'null_vector': [-0.730722, 0.315161, 1.0, 0.539254],
 'quasi_buckling_load': None,
 'quasi_buckling_force': None,
 'quasi_buckling_stiffness': None,
 'end_load': 0.572793,
 'direction': [-1.0, 0.0],
 'boundary': 'guided',
 'start': {'success': True,
           'status': 'converged',
           'message': 'converged (Solve_Succeeded, 7 iterations)',
           'q': [0.0, 0.0, 0.0, 0.0],
           'energy': 4.0,
           'force': {'fx': 0.0, 'fy': 0.0},
           'morse_index': 0,
           'stable': True,
           'kind': 'minimum',
           'shape': 'I',
           'signs': '0000',
           'tip': [8.0, 0.0],
           'solver': {'status': 'Solve_Succeeded', 'iterations': 7}},
 'branch_status': 'stability_loss',
 'branch_points': 12}

#: ``/v1/imperfection-sensitivity``: the paper's chain, guided
#: (``imperfection_sensitivity(m, [0, 0.01, 0.02851, 0.061])``, rounded).
IMPERFECTION_SENSITIVITY = {
    "success": True, "status": "complete", "message": "4 amplitudes: 3 fold, 1 bifurcation",
    "imperfection": "asymmetry", "direction": [-1.0, 0.0], "boundary": "guided", "max_load": None,
    "amplitudes": [0.0, 0.01, 0.02851, 0.061], "loads": [0.572793, 0.584089, 0.527429, 0.424701],
    "kinds": ["bifurcation", "fold", "fold", "fold"], "statuses": ["stability_lost"] * 4,
    "messages": ["stability is lost at a bifurcation at load 0.5727928",
                 "stability is lost at a fold at load 0.5840895", "stability is lost at a fold at load 0.527429",
                 "stability is lost at a fold at load 0.4247007"],
    "perfect_load": 0.572793, "perfect_kind": "bifurcation", "bifurcation": "stable_symmetric", "law": None}

#: ``/v1/stability-boundary``: the shape of ``StabilityBoundary.to_dict()`` (illustrative numbers).
STABILITY_BOUNDARY = {
    "success": True, "status": "p_range", "message": "p up: p left [-0.1, 0.1]; p down: p left [-0.1, 0.1]",
    "kind": "fold", "parameter": "asymmetry",
    "control": {"kind": "guided", "direction": [-1.0, 0.0], "base": [0.0, 0.0]}, "points": 2,
    "p": [0.01, 0.02], "t": [0.55, 0.54], "q": [[0.3, -0.13, -0.41, -0.22], [0.35, -0.15, -0.48, -0.26]],
    "force": [{"fx": -0.55, "fy": 0.0}, {"fx": -0.54, "fy": 0.0}],
    "null_vectors": [[-0.73, 0.32, 1.0, 0.54], [-0.74, 0.31, 1.0, 0.55]], "cusps": []}

#: ``/v1/atlas`` of the bistable chain n = 3, a = 0.5 on dx [0.2, 0.8] x dy [0.3] (rounded): two folds on the edge.
ATLAS = {
    "success": True, "status": "complete", "message": "all 2 targets computed and every edge analysed",
    "dx": [0.2, 0.8], "dy": [0.3], "method": "search", "seconds": 0.42,
    "count": [[4, 8]], "n_stable": [[2, 4]], "n_saddle": [[0, 0]], "n_maximum": [[2, 4]],
    "least_energy": [[2.828188, 2.438335]], "least_signs": [["+-+", "+-+"]], "certified": [[False, False]],
    "targets": [[
        {"success": True, "status": "solved", "message": "4 equilibria (2 stable, 0 saddles, 2 maxima), measured",
         "dx": 0.2, "dy": 0.3, "reachable": True, "count": 4, "n_stable": 2, "n_saddle": 0, "n_maximum": 2,
         "least_energy": 2.828188, "least_signs": "+-+", "tie": False,
         "stable_q": [[0.247659, -0.522279, 0.634424], [-0.094876, 0.487538, -0.672113]],
         "stable_energy": [2.828188, 2.838758], "certified": False, "method": "search", "error": None},
        {"success": True, "status": "solved", "message": "8 equilibria (4 stable, 0 saddles, 4 maxima), measured",
         "dx": 0.8, "dy": 0.3, "reachable": True, "count": 8, "n_stable": 4, "n_saddle": 0, "n_maximum": 4,
         "least_energy": 2.438335, "least_signs": "+-+", "tie": False,
         "stable_q": [[0.509477, -1.151775, 1.192233], [-0.349738, 1.133449, -1.224354],
                      [0.652228, -0.714746, -0.846602], [-0.454423, 0.590352, 0.999857]],
         "stable_energy": [2.438335, 2.466582, 2.635382, 2.669858], "certified": False, "method": "search",
         "error": None}]],
    "crossings": [
        {"kind": "branch_end", "dx": 0.648693, "dy": 0.3, "edge": [[0, 0], [1, 0]], "fraction": 0.747822,
         "energy": 2.697568, "q": [0.468242, -0.361337, -1.061428], "force": [0.380393, -0.022725], "event": "fold",
         "method": "moore_spence", "q_other": None, "force_other": None, "null_vector": [-0.46885, 1.0, -0.910853]},
        {"kind": "branch_end", "dx": 0.735642, "dy": 0.3, "edge": [[0, 0], [1, 0]], "fraction": 0.892736,
         "energy": 2.693019, "q": [-0.336504, 0.35355, 1.167391], "force": [0.324016, 0.060401], "event": "fold",
         "method": "moore_spence", "q_other": None, "force_other": None, "null_vector": [-0.479404, 1.0, -0.881537]}],
    "curves": {"switch": [], "branch_end": []}, "unresolved": []}

# ---------------------------------------------------------------------------- control (/v1/control/*)
#: The plan of PLAN_REQUEST_EXAMPLE (service.schemas.control), rounded.
PLAN = {'success': True,
 'status': 'complete',
 'message': '4 step(s), 4 feasible, 4 verified',
 'seconds': 0.05,
 'commands': [[[0.685134, 1.20777], [1.00651, 0.992736], [1.15883, 0.73099], [1.10476, 0.863456]],
              [[0.6478, 1.23069], [1.00698, 0.992219], [1.17654, 0.699084], [1.11677, 0.847328]],
              [[0.613379, 1.25045], [1.00592, 0.993389], [1.19053, 0.67253], [1.12667, 0.833699]],
              [[0.58143, 1.26765], [1.00362, 0.99594], [1.20158, 0.650598], [1.13485, 0.822196]]],
 'proposals': [[[0.685134, 1.20777], [1.00651, 0.992736], [1.15883, 0.73099], [1.10476, 0.863456]],
               [[0.6478, 1.23069], [1.00698, 0.992219], [1.17654, 0.699084], [1.11677, 0.847328]],
               [[0.613379, 1.25045], [1.00592, 0.993389], [1.19053, 0.67253], [1.12667, 0.833699]],
               [[0.58143, 1.26765], [1.00362, 0.99594], [1.20158, 0.650598], [1.13485, 0.822196]]],
 'q': [[0.404242, -0.109074, -0.504077, -0.261957],
       [0.469467, -0.109161, -0.557335, -0.29049],
       [0.528654, -0.106064, -0.601315, -0.31447],
       [0.582866, -0.100336, -0.637461, -0.334649]],
 'tip': [[7.6, 0.5], [7.5, 0.75], [7.4, 1.0], [7.3, 1.25]],
 'tip_error': [0.0, 0.0, 0.0, 0.0],
 'end_angle': [-0.470866, -0.487518, -0.493195, -0.48958],
 'margin': [0.957768, 0.954612, 0.951496, 0.948326],
 'feasible': [True, True, True, True],
 'verified': [True, True, True, True],
 'transition_margin': [0.957768, 0.954612, 0.951496, 0.948326],
 'method': ['ipopt', 'newton', 'newton', 'newton'],
 'targets': [[7.6, 0.5], [7.5, 0.75], [7.4, 1.0], [7.3, 1.25]],
 'times': [None, None, None, None],
 'on_infeasible': 'hold',
 'on_snap': 'continue',
 'start': [-0.136046, -0.096348, -0.057394, -0.019054]}

#: The simulation of SIMULATION_REQUEST_EXAMPLE (a load cycle on three bistable segments), rounded.
SIMULATION = {'success': True,
 'status': 'complete',
 'message': 'all 13 samples simulated, 2 snap(s)',
 'mode': 'free',
 'steps': 13,
 'done': 13,
 'q': [[1.68214, 1.68214, 1.68214], [1.41081, 1.34503, 1.64431], [1.83231, -1.2845, 1.54959],
       [1.82953, -1.11737, 1.44453], [1.83231, -1.2845, 1.54959], [1.79968, -1.47044, 1.63465],
       [1.68214, -1.68214, 1.68214], [-1.47674, -1.44435, 1.64627], [-1.40103, -1.23942, 1.55904],
       [-1.39399, -1.05329, 1.45003], [-1.40103, -1.23942, 1.55904], [-1.47674, -1.44435, 1.64627],
       [-1.68214, -1.68214, 1.68214]],
 'force': [{'fx': 0.0, 'fy': 0.0}, {'fx': 0.0, 'fy': 0.1}, {'fx': 0.0, 'fy': 0.2}, {'fx': 0.0, 'fy': 0.3},
           {'fx': 0.0, 'fy': 0.2}, {'fx': 0.0, 'fy': 0.1}, {'fx': 0.0, 'fy': 0.0}, {'fx': 0.0, 'fy': -0.1},
           {'fx': 0.0, 'fy': -0.2}, {'fx': 0.0, 'fy': -0.3}, {'fx': 0.0, 'fy': -0.2}, {'fx': 0.0, 'fy': -0.1},
           {'fx': 0.0, 'fy': 0.0}],
 'tip': [[-0.844993, 0.601192], [-0.841606, 1.77532], [1.68765, 3.83815], [1.44923, 4.07359], [1.68765, 3.83815],
         [2.05574, 3.51822], [2.66667, 2.98142], [-0.472052, -3.38513], [0.0539298, -3.81473], [0.357395, -4.08852],
         [0.0539298, -3.81473], [-0.472052, -3.38513], [-1.28395, -2.53973]],
 'deflection': [[6.84499, 0.601192], [6.84161, 1.77532], [4.31235, 3.83815], [4.55077, 4.07359], [4.31235, 3.83815],
                [3.94426, 3.51822], [3.33333, 2.98142], [6.47205, -3.38513], [5.94607, -3.81473], [5.64261, -4.08852],
                [5.94607, -3.81473], [6.47205, -3.38513], [7.28395, -2.53973]],
 'energy': [2.0, 2.06756, 2.07084, 2.12922, 2.07084, 2.02386, 2.0, 2.03749, 2.09985, 2.16756, 2.09985, 2.03749, 2.0],
 'potential': [2.0, 1.89003, 1.30321, 0.907148, 1.30321, 1.67204, 2.0, 1.69898, 1.3369, 0.941006, 1.3369, 1.69898,
               2.0],
 'stable': [True, True, True, True, True, True, True, True, True, True, True, True, True],
 'morse_index': [0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0],
 'events': [{'success': True,
             'status': 'landed',
             'message': 'snap at fraction 0.531107 of step 1: landed on a stable equilibrium (potential released '
                        '0.284993)',
             'kind': 'snap',
             'step': 1,
             'fraction': 0.531107,
             'time': 1.53111,
             'preloads': [[1.0, 1.0], [1.0, 1.0], [1.0, 1.0]],
             'load': [0.0, 0.153111],
             'target': None,
             'q_before': [1.3334, 0.770457, 1.49264],
             'q_after': [1.82323, -1.36896, 1.59252],
             'force_before': [0.0, 0.153111],
             'force_after': [0.0, 0.153111],
             'tip_before': [-0.444304, 3.22704],
             'tip_after': [1.83943, 3.70306],
             'energy_before': 2.25918,
             'energy_after': 2.04707,
             'potential_before': 1.76508,
             'potential_after': 1.48009,
             'energy_released': 0.284993,
             'null_vector': [-0.204827, 1.0, 0.0972962],
             'direction': -1,
             'method': 'moore_spence'},
            {'success': True,
             'status': 'landed',
             'message': 'snap at fraction 0.977542 of step 6: landed on a stable equilibrium (potential released '
                        '0.525489)',
             'kind': 'snap',
             'step': 6,
             'fraction': 0.977542,
             'time': 6.97754,
             'preloads': [[1.0, 1.0], [1.0, 1.0], [1.0, 1.0]],
             'load': [0.0, -0.0977542],
             'target': None,
             'q_before': [1.02658, -1.89304, 1.58809],
             'q_after': [-1.47972, -1.44931, 1.64785],
             'force_before': [0.0, -0.0977542],
             'force_after': [0.0, -0.0977542],
             'tip_before': [4.08128, 0.847599],
             'tip_after': [-0.487518, -3.37199],
             'energy_before': 2.1492,
             'energy_after': 2.03619,
             'potential_before': 2.23205,
             'potential_after': 1.70657,
             'energy_released': 0.525489,
             'null_vector': [1.0, -0.0686594, 0.0908063],
             'direction': -1,
             'method': 'moore_spence'}],
 'preloads': [[[1.0, 1.0], [1.0, 1.0], [1.0, 1.0]], [[1.0, 1.0], [1.0, 1.0], [1.0, 1.0]],
              [[1.0, 1.0], [1.0, 1.0], [1.0, 1.0]], [[1.0, 1.0], [1.0, 1.0], [1.0, 1.0]],
              [[1.0, 1.0], [1.0, 1.0], [1.0, 1.0]], [[1.0, 1.0], [1.0, 1.0], [1.0, 1.0]],
              [[1.0, 1.0], [1.0, 1.0], [1.0, 1.0]], [[1.0, 1.0], [1.0, 1.0], [1.0, 1.0]],
              [[1.0, 1.0], [1.0, 1.0], [1.0, 1.0]], [[1.0, 1.0], [1.0, 1.0], [1.0, 1.0]],
              [[1.0, 1.0], [1.0, 1.0], [1.0, 1.0]], [[1.0, 1.0], [1.0, 1.0], [1.0, 1.0]],
              [[1.0, 1.0], [1.0, 1.0], [1.0, 1.0]]],
 'loads': [[0.0, 0.0], [0.0, 0.1], [0.0, 0.2], [0.0, 0.3], [0.0, 0.2], [0.0, 0.1], [0.0, 0.0], [0.0, -0.1],
           [0.0, -0.2], [0.0, -0.3], [0.0, -0.2], [0.0, -0.1], [0.0, 0.0]]}

#: The equilibrium of the paper's chain under (-0.1, 0.05) (rounded angles) and its force estimate.
FORCE_ESTIMATE_Q = [0.742754, 0.522806, 0.297158, 0.0953]
FORCE_ESTIMATE = {'success': True,
 'status': 'generalized_least_squares',
 'message': 'generalised least-squares estimate, residual torque 6.18e-07, chi2 3.8e-07 on 2 degrees of freedom',
 'force': {'fx': -0.0999999, 'fy': 0.0500004},
 'covariance': [[7.47495e-08, 1.89726e-07], [1.89726e-07, 7.33302e-07]],
 'residual_torque': [8.28877e-08, -2.88129e-07, 4.62923e-07, -2.78041e-07],
 'residual_norm': 6.17652e-07,
 'chi2': 3.80324e-07,
 'dof': 2,
 'p_value': 1.0,
 'joint_chi2': [1.63718e-07, 2.0906e-07, 3.61366e-07, 8.50668e-08],
 'q': [0.742754, 0.522806, 0.297158, 0.0953],
 'measured': [0, 1, 2, 3],
 'hidden_covariance': [],
 'iterations': 1}

#: ``/v1/control/stiffness`` of the paper's chain, tip at (7, 1), both stiffness eigenvalues in [0.04, 0.6], rounded.
STIFFNESS_DESIGN = {
    "success": True, "status": "within_bounds",
    "message": "the stiffness bounds hold: eigenvalues 0.04, 0.6 (force / length)",
    "manipulator": {"segments": [{"a": 1.0, "b": 1.0, "k": 1.0, "L0": [2.622024, 2.694867]},
                                 {"a": 1.0, "b": 1.0, "k": 1.0, "L0": [2.358032, 1.93644]},
                                 {"a": 1.0, "b": 1.0, "k": 1.0, "L0": [1.342645, 1.838989]},
                                 {"a": 1.0, "b": 1.0, "k": 1.0, "L0": [0.1, 1.048735]}]},
    "rest_lengths": [[2.622024, 2.694867], [2.358032, 1.93644], [1.342645, 1.838989], [0.1, 1.048735]],
    "q": [0.027399, -0.195715, 0.309511, 1.380665], "tip": [7.0, 1.0],
    "K": [[0.564462, 0.136522], [0.136522, 0.075538]], "eigenvalues": [0.04, 0.6], "margin": 0.744931,
    "residual": 0.0, "exact": True, "load": [0.0, 0.0], "K_desired": None, "bounds_K": {}, "eig_bounds": [0.04, 0.6],
    "solver": {"status": "Solve_Succeeded", "iterations": 7}}

#: ``/v1/control/load-capacity`` of the straight paper chain, 8 directions up to 2 more (rounded): it buckles under
#: compression at its free critical load.
LOAD_CAPACITY = {
    "success": True, "status": "complete",
    "message": "8 directions: 0 fold(s), 1 bifurcation(s), 7 without a limit",
    "angles": [0.0, 0.785398, 1.570796, 2.356194, 3.141593, -2.356194, -1.570796, -0.785398],
    "directions": [[1.0, 0.0], [0.707107, 0.707107], [0.0, 1.0], [-0.707107, 0.707107], [-1.0, 0.0],
                   [-0.707107, -0.707107], [0.0, -1.0], [0.707107, -0.707107]],
    "loads": [None, None, None, None, 0.07612, None, None, None],
    "forces": [[None, None], [None, None], [None, None], [None, None], [-0.07612, 0.0], [None, None], [None, None],
               [None, None]],
    "kinds": ["none", "none", "none", "none", "bifurcation", "none", "none", "none"],
    "reasons": ["max_load", "max_load", "max_load", "joint_limit", None, "joint_limit", "max_load", "max_load"],
    "end_loads": [2.0, 2.0, 2.0, 0.639553, 0.07612, 0.639553, 2.0, 2.0], "base": [0.0, 0.0], "boundary": "free",
    "max_load": 2.0, "weakest": {"angle": 3.141593, "load": 0.07612},
    "start": {"success": True, "status": "converged", "message": "converged (exact, 0 iterations)",
              "q": [0.0, 0.0, 0.0, 0.0], "energy": 4.0, "force": {"fx": 0.0, "fy": 0.0}, "morse_index": 0,
              "stable": True, "kind": "minimum", "shape": "I", "signs": "0000", "tip": [8.0, 0.0],
              "solver": {"status": "exact", "iterations": 0}},
    "manipulator": {"segments": [{"a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0}] * 4}}


ERRORS: dict[int, dict[str, dict[str, Any]]] = {
    401: {"unauthorized": {"summary": "missing or wrong API key",
                           "value": {"code": "unauthorized", "message": "missing API key: send the X-API-Key header",
                                     "field": "X-API-Key"}}},
    413: {"body_too_large": {"summary": "request body over the limit",
                             "value": {"code": "body_too_large",
                                       "message": "request body of 2000000 bytes exceeds the limit of 1048576 bytes",
                                       "details": {"max_body_bytes": 1048576}}}},
    422: {
        "validation_error": {"summary": "schema violation (field path)", "value": {
            "code": "validation_error", "message": "manipulator.a: Input should be greater than 0",
            "field": "manipulator.a",
            "errors": [{"field": "manipulator.a", "message": "Input should be greater than 0",
                        "type": "greater_than"}]}},
        "unreachable_target": {"summary": "target beyond the chain's reach", "value": {
            "code": "unreachable_target",
            "message": "target (-12, 0) for dx=20, dy=0 is beyond the chain's reach: distance 13 from joint 1 "
                       "exceeds the total link length 7", "field": "dx", "details": {"distance": 13.0, "reach": 7.0}}},
        "straight_not_equilibrium": {"summary": "asymmetric segment: straight is not an equilibrium", "value": {
            "code": "straight_not_equilibrium",
            "message": "the straight configuration is not an equilibrium: segment 0 is asymmetric (k1=1, k2=2, "
                       "L1_0=1, L2_0=1) and exerts a torque -1 at q = 0", "field": "manipulator.segments[0]"}},
        "straight_unstable": {"summary": "straight configuration unstable (K <= 0)", "value": {
            "code": "straight_unstable",
            "message": "the straight configuration is not stable unloaded: segment 0 has joint stiffness "
                       "K = k (b L0 - 2 (b^2 - a^2)) = -1 <= 0 (condition (4) fails); raise L0 above 1.5",
            "field": "manipulator.L0"}},
        "too_many_segments": {"summary": "chain longer than this server accepts (its setting under the schema's "
                                         "200)", "value": {
            "code": "too_many_segments", "message": "the chain has 150 segments; this server accepts at most 100",
            "field": "manipulator.n", "details": {"n": 150, "max_segments": 100}}},
        "too_many_points": {"summary": "max_points over this server's TENSEGRITY_MAX_PATH_POINTS", "value": {
            "code": "too_many_points",
            "message": "max_points = 5000; this server follows at most 2000 points per branch",
            "field": "max_points", "details": {"max_points": 5000, "max_path_points": 2000}}},
        "too_many_steps": {"summary": "a trajectory longer than this server's TENSEGRITY_MAX_TRAJECTORY_STEPS",
                           "value": {"code": "too_many_steps",
                                     "message": "targets holds 2000 steps; this server computes at most 500 steps "
                                                "of a trajectory in one request",
                                     "field": "targets", "details": {"steps": 2000, "max_trajectory_steps": 500}}},
        "continuation_too_long": {"summary": "chain longer than the continuation handles (64 segments)", "value": {
            "code": "invalid_parameter",
            "message": "arclength continuation handles chains of up to 64 segments, got n = 100",
            "field": "manipulator.n"}},
        "bad_start": {"summary": "start outside the physical range", "value": {
            "code": "invalid_parameter",
            "message": "q0 lies outside the physical joint range |q_i| < pi - 2 beta_i", "field": "start.q"}},
        "response_too_large": {"summary": "answer over the server's response size limit", "value": {
            "code": "response_too_large",
            "message": "the answer exceeds this server's response size limit of 8388608 bytes "
                       "(TENSEGRITY_MAX_RESPONSE_BYTES): ask for less (dx)",
            "field": "dx", "details": {"max_response_bytes": 8388608}}},
        "solver_failed": {"summary": "no solve converged (IPOPT status)", "value": {
            "code": "solver_failed", "message": "no local solve converged inside the physical range for dx=7.9, dy=0",
            "status": "Infeasible_Problem_Detected x8, Maximum_Iterations_Exceeded x6"}},
        "design_infeasible": {"summary": "infeasible design problem: IPOPT status and best point", "value": {
            "code": "design_infeasible",
            "message": "no rest lengths within the bounds give a critical load of 10: the best achievable is 1.14559",
            "status": "Solve_Succeeded",
            "best": {"critical_force": -1.145586, "feasible": False, "multiplicity": 1,
                     "active": ["L0[0] <= 2", "L0[1] <= 2", "L0[2] <= 2", "L0[3] <= 2"]}}},
        "atlas_too_large": {"summary": "more targets than the server computes in one request (a job then)", "value": {
            "code": "atlas_too_large",
            "message": "the atlas has 441 targets (21 dx x 21 dy); this server computes at most 400 in one request: "
                       'submit it as a job, POST /v1/jobs with {"analysis": "atlas", "grid": {"dx": [...], '
                       '"dy": [...]}}, then GET /v1/jobs/{id}/atlas',
            "field": "dx", "details": {"targets": 441, "nx": 21, "ny": 21, "max_atlas_targets": 400}}},
        "bad_grid": {"summary": "grid values not strictly increasing", "value": {
            "code": "invalid_parameter", "message": "dx must be strictly increasing", "field": "dx"}},
        "no_equilibrium": {"summary": "no equilibrium inside the physical range", "value": {
            "code": "no_equilibrium",
            "message": "no equilibrium inside the physical range for the tip force (-0.6, 0): the minimiser "
                       "presses a joint against its limit", "status": "Solve_Succeeded"}},
    },
    503: {"overloaded": {"summary": "solver pool saturated (see Retry-After)", "value": {
        "code": "overloaded", "message": "all 2 solver workers are busy and 64 requests are queued"}}},
    504: {"timeout": {"summary": "solve time limit exceeded",
                      "value": {"code": "timeout", "message": "the solve did not finish within 10 s"}}},
}
