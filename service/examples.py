"""Request and response examples for the OpenAPI document (values from the paper's chain, rounded)."""

from __future__ import annotations

from typing import Any

PAPER_CHAIN = {"n": 4, "a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0}

EQUILIBRIUM = {
    "q": [0.178155, -0.076587, -0.245053, -0.131183], "energy": 4.057381,
    "force": {"fx": -0.574823, "fy": 0.025785}, "morse_index": 0, "stable": True, "kind": "minimum",
    "shape": "U", "signs": "+---", "tip": [7.9, 0.0],
    "solver": {"status": "Newton_Converged", "iterations": 3},
}
FORCE_EQUILIBRIUM = {
    "q": [-1.532346, -0.809098, -0.358652, -0.100399], "energy": 5.509784,
    "force": {"fx": -0.3, "fy": 0.0}, "morse_index": 0, "stable": True, "kind": "minimum",
    "shape": "C", "signs": "----", "tip": [-3.066931, -4.62255],
    "solver": {"status": "Solve_Succeeded", "iterations": 10},
}


def _eq(q, energy, fx, fy, mi, kind, shape, signs) -> dict[str, Any]:
    return {"q": q, "energy": energy, "force": {"fx": fx, "fy": fy}, "morse_index": mi, "stable": mi == 0,
            "kind": kind, "shape": shape, "signs": signs, "tip": [7.9, 0.0],
            "solver": {"status": "converged", "iterations": 5}}


EQUILIBRIA = {"equilibria": [
    _eq([0.178155, -0.076587, -0.245053, -0.131183], 4.057381, -0.574823, 0.025785, 0, "minimum", "U", "+---"),
    _eq([-0.178155, 0.076587, 0.245053, 0.131183], 4.057381, -0.574823, -0.025785, 0, "minimum", "U", "-+++"),
    _eq([0.183914, -0.370084, 0.085087, 0.308833], 4.1364, -1.365098, 0.026617, 1, "saddle", "ZU", "+-++"),
    _eq([-0.183914, 0.370084, -0.085087, -0.308833], 4.1364, -1.365098, -0.026617, 1, "saddle", "ZU", "-+--"),
    _eq([0.076358, -0.239509, 0.365593, -0.434349], 4.192165, -1.921865, 0.011064, 2, "maximum", "Z", "+-+-"),
    _eq([-0.076358, 0.239509, -0.365593, 0.434349], 4.192165, -1.921865, -0.011064, 2, "maximum", "Z", "-+-+"),
], "method": "homotopy", "certified": True, "paths": 456, "failed_paths": 0}

BUCKLING = {
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
    "points": [
        {"dx": 0.0, "dy": 0.0, "fx": 0.0, "fy": 0.0, "energy": 4.0, "q": [0.0, 0.0, 0.0, 0.0], "stable": True,
         "morse_index": 0, "shape": "I", "branch": -1},
        {"dx": 0.05, "dy": 0.0, "fx": -0.57381, "fy": 0.018121, "energy": 4.028665,
         "q": [0.126027, -0.054267, -0.172908, -0.092902], "stable": True, "morse_index": 0, "shape": "U",
         "branch": 0},
        {"dx": 0.1, "dy": 0.0, "fx": -0.574823, "fy": 0.025785, "energy": 4.057381,
         "q": [0.178155, -0.076587, -0.245053, -0.131183], "stable": True, "morse_index": 0, "shape": "U",
         "branch": 0},
    ],
    "jumps": [{"kind": "buckling", "dx_before": 0.0, "dx_after": 0.05, "force_before": {"fx": 0.0, "fy": 0.0},
               "force_after": {"fx": -0.572793, "fy": 0.0}, "branch_before": -1, "branch_after": 0}],
    "branches": [],
}

STIFFNESS = {"matrix": [[0.020242, -0.132106], [-0.132106, -0.06731]], "equilibrium": EQUILIBRIUM}

SEGMENT_TORQUE = {"q": [-0.5, 0.0, 0.5], "torque": [0.494808, 0.0, -0.494808],
                  "dtorque": [-0.968912, -1.0, -0.968912], "energy": [1.12435, 1.0, 1.12435],
                  "stiffness": 1.0, "monotonic": True, "joint_limit": 1.570796}

ENERGY_LANDSCAPE = {"pair": [0, 3], "qi": [-1.569226, 0.0, 1.569226], "qj": [-1.569226, 0.0, 1.569226],
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
    "manipulator": {"segments": [{"a": 1.0, "b": 1.0, "k": 1.768, "L0": 1.0}, {"a": 1.0, "b": 1.0, "k": 0.2, "L0": 1.0},
                                 {"a": 1.0, "b": 1.0, "k": 1.178286, "L0": 1.0},
                                 {"a": 1.0, "b": 1.0, "k": 0.853714, "L0": 1.0}]},
    "critical_force": -0.691429, "loads": [0.691429, 0.846986, 1.751871], "multiplicity": 1,
    "active": ["k[1] >= 0.2", "sum(k) <= 4"], "initial_critical_force": -0.572793, "feasible": True,
    "solver": {"status": "Solve_Succeeded", "iterations": 17}}

PRELOADS = {
    "manipulator": {"segments": [{"a": 1.0, "b": 1.0, "k": 1.0, "L0": [1.041489, 0.944056]},
                                 {"a": 1.0, "b": 1.0, "k": 1.0, "L0": [0.736705, 1.198028]},
                                 {"a": 1.0, "b": 1.0, "k": 1.0, "L0": [0.468097, 1.248362]},
                                 {"a": 1.0, "b": 1.0, "k": 1.0, "L0": [0.785856, 1.154345]}]},
    "preloads": [[1.041489, 0.944056], [0.736705, 1.198028], [0.468097, 1.248362], [0.785856, 1.154345]],
    "q": [-0.294564, 0.281086, 0.697109, 0.321762], "margin": 0.977663, "tip": [7.0, 1.5], "energy": 4.215705,
    "solver": {"status": "Solve_Succeeded", "iterations": 5}}

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
