"""Hand-written serialisers, one per result type: the independent reference the results' ``to_dict()`` are
checked against (``tests/service/test_serialisation.py``: the same keys, order and types), so that no API body
changes unnoticed. Each builds its dict key by key from the result's attributes.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np


class NonFiniteResult(ArithmeticError):
    pass


def _num(x: Any) -> float:
    v = float(x)
    if not math.isfinite(v):
        raise NonFiniteResult("not finite")
    return v


def _nums(a: Any) -> list[Any]:
    arr = np.asarray(a, dtype=float)
    if not bool(np.all(np.isfinite(arr))):
        raise NonFiniteResult("not finite")
    return arr.tolist()


def _f(x: Any) -> float | None:
    v = float(x)
    return v if math.isfinite(v) else None


def outcome(r) -> dict[str, Any]:
    """The result contract's three fields (every body carries them first)."""
    return {"success": bool(r.success), "status": str(r.status), "message": str(r.message)}


def springs_out(q, sp) -> dict[str, Any]:
    """The spring state at ``q`` written out spring by spring (plain floats): ``L = 2 c cos(beta -+ q/2)`` from the
    segments' ``c``, ``beta``, ``k``, ``L0`` and law (``sp``), the force ``k (L - L0)`` or ``k max(0, L - L0)``, the
    state ``taut`` / ``slack`` / ``pushing`` (shorter than ``L0`` by more than 1e-9 of it)."""
    names = ("spring_lengths", "spring_stretches", "spring_forces", "spring_states")
    if q is None or not all(math.isfinite(float(v)) for v in q):
        return dict.fromkeys(names)
    out: dict[str, list] = {k: [] for k in names}
    for i, qi in enumerate(q):
        c, beta, tension_only = float(sp.c[i]), float(sp.beta[i]), bool(sp.tension_only[i])
        row = {k: [] for k in names}
        for j, L in enumerate((2.0 * c * math.cos(beta + float(qi) / 2.0), 2.0 * c * math.cos(beta - float(qi) / 2.0))):
            L0, k = float(sp.L0[i][j]), float(sp.k[i][j])
            stretch = L - L0
            short = stretch < -1e-9 * L0
            row["spring_lengths"].append(L)
            row["spring_stretches"].append(stretch)
            row["spring_forces"].append(k * max(0.0, stretch) if tension_only else k * stretch)
            row["spring_states"].append(("slack" if tension_only else "pushing") if short else "taut")
        for k in names:
            out[k].append(row[k])
    return out


def springs_series_out(Q, sp) -> dict[str, Any]:
    """:func:`springs_out` of each row of ``Q``, as lists per field."""
    rows = [springs_out(q, sp) for q in Q]
    return {k: [r[k] for r in rows] for k in ("spring_lengths", "spring_stretches", "spring_forces", "spring_states")}


def equilibrium_out(eq) -> dict[str, Any]:
    return {**outcome(eq), **springs_out(eq.q, eq.springs), "q": _nums(eq.q), "energy": _num(eq.energy),
            "force": {"fx": _num(eq.fx), "fy": _num(eq.fy)},
            "morse_index": int(eq.morse_index), "stable": bool(eq.stable), "kind": eq.kind, "shape": eq.shape,
            "signs": eq.signs, "tip": _nums(eq.tip),
            "solver": {"status": str(eq.solver.status),
                       "iterations": None if eq.solver.iterations is None else int(eq.solver.iterations)},
            "certificate": energy_bound_out(eq.certificate), "at_stop": [bool(v) for v in eq.at_stop],
            "contact_torques": [_num(v) for v in eq.contact_torques], "loads": loads_out(eq.loads)}


def loads_out(key) -> dict[str, Any] | None:
    """The dead loads ``(payload, gravity, joint_forces)`` an equilibrium was computed under, or None."""
    if key is None:
        return None
    payload, gravity, forces = key
    return {"gravity": None if gravity is None else [float(g) for g in gravity], "payload": float(payload),
            "joint_forces": [{"joint": int(j), "force": [float(f[0]), float(f[1])]} for j, f in forces]}


def energy_bound_out(c) -> dict[str, Any] | None:
    if c is None:
        return None
    return {**outcome(c), "bound": _num(c.bound), "energy": _num(c.energy), "gap": _num(max(0.0, c.energy - c.bound)),
            "tolerance": _num(c.tolerance), "certified": c.status == "certified", "improved": bool(c.improved),
            "patterns": int(c.patterns), "boxes": int(c.boxes), "newton": int(c.newton), "seconds": _num(c.seconds)}


def certificate_out(c) -> dict[str, Any] | None:
    if c is None:
        return None
    return {**outcome(c), "method": c.method, "control": c.control, "paths": int(c.paths),
            "roots_proven": all(b.proven for b in c.boxes), "morse_proven": all(b.morse_proven for b in c.boxes),
            "nonreal_checked": int(c.nonreal_checked), "nonreal_proven": int(c.nonreal_proven),
            "outside_checked": int(c.outside_checked), "outside_proven": int(c.outside_proven),
            "seconds": float(c.seconds),
            "boxes": [{"lower": [float(v) for v in b.lower], "upper": [float(v) for v in b.upper],
                       "proven": bool(b.proven), "morse_index": None if b.morse_index is None else int(b.morse_index),
                       "morse_proven": bool(b.morse_proven), "reason": b.reason} for b in c.boxes]}


def equilibria_out(eqs) -> dict[str, Any]:
    return {**outcome(eqs), "equilibria": [equilibrium_out(e) for e in eqs], "method": eqs.method,
            "certified": eqs.certified,
            "paths": eqs.paths, "failed_paths": eqs.failed_paths, "certificate": certificate_out(eqs.certificate)}


def buckling_out(bk) -> dict[str, Any]:
    return {**outcome(bk), "boundary": bk.boundary, "critical_force": _num(bk.force), "loads": _nums(bk.loads),
            "modes": [{"load": _num(md.load), "q": _nums(md.q), "fy": _num(md.fy),
                       "energy_factor": _num(md.energy_factor), "mu_x": _num(md.mu_x),
                       "fy_coefficient": _num(md.fy_coefficient), "shape": md.shape, "signs": md.signs,
                       "stable": bool(md.stable)} for md in bk.modes]}


def _force(v: Any) -> dict[str, float]:
    return {"fx": _num(v[0]), "fy": _num(v[1])}


def curve_out(c) -> dict[str, Any]:
    points = [{**springs_out(c.q[i], c.springs), "dx": _num(c.dx[i]), "dy": _num(c.dy[i]), "fx": _num(c.fx[i]),
               "fy": _num(c.fy[i]),
               "energy": _num(c.energy[i]), "q": _nums(c.q[i]), "stable": bool(c.stable[i]),
               "morse_index": int(c.morse_index[i]), "shape": c.shape[i], "branch": int(c.branch[i]),
               "status": c.point_status[i],
               "solver": {"status": str(c.solver[i].status),
                          "iterations": None if c.solver[i].iterations is None else int(c.solver[i].iterations)}}
              for i in range(c.dx.size)]
    jumps = [{"kind": j.kind, "dx_before": _num(j.dx_before), "dx_after": _num(j.dx_after),
              "force_before": _force(j.force_before), "force_after": _force(j.force_after),
              "branch_before": int(j.branch_before), "branch_after": int(j.branch_after),
              "delta": _force(np.asarray(j.force_after) - np.asarray(j.force_before)), "label": j.label}
             for j in c.jumps]
    branches = []
    for bi, br in enumerate(c.branches):
        bid = int(br.branch[0]) if br.branch.size else bi
        pts = []
        for i in range(br.dx.size):
            exists = bool(np.isfinite(br.energy[i]))
            pts.append({**springs_out(br.q[i], br.springs), "dx": _num(br.dx[i]), "dy": _num(br.dy[i]),
                        "exists": exists, "fx": _f(br.fx[i]),
                        "fy": _f(br.fy[i]), "energy": _f(br.energy[i]),
                        "q": [_f(v) for v in br.q[i]], "stable": bool(br.stable[i]),
                        "morse_index": int(br.morse_index[i]), "shape": br.shape[i]})
        branches.append({"id": bid, "points": pts})
    end = c.ended_at
    return {**outcome(c), "points": points, "jumps": jumps, "branches": branches,
            "reference": c.reference, "origin": [float(v) for v in c.origin],
            "ended_at": None if end is None else {**outcome(end), "dx": _num(end.dx), "dy": _num(end.dy)},
            "requested": int(c.requested), "loads": loads_out(c.loads)}


def landscape_out(land) -> dict[str, Any]:
    E = land.energy
    energy = [[[None if not math.isfinite(v) else v for v in row] for row in plane] for plane in E.tolist()]
    return {**outcome(land), "pair": [int(p) for p in land.pair], "qi": _nums(land.qi), "qj": _nums(land.qj),
            "energy": energy, "loads": loads_out(land.loads)}


def manipulator_out(m) -> dict[str, Any]:
    return {"segments": [{"a": _num(sg.a), "b": _num(sg.b),
                          "k": _num(sg.k1) if sg.k1 == sg.k2 else [_num(sg.k1), _num(sg.k2)],
                          "L0": _num(sg.L1_0) if sg.L1_0 == sg.L2_0 else [_num(sg.L1_0), _num(sg.L2_0)],
                          **({} if sg.spring == "linear" else {"spring": sg.spring})}
                         for sg in m.segments]}


def design_out(d) -> dict[str, Any]:
    return {**outcome(d), "manipulator": manipulator_out(d.manipulator), "critical_force": _num(d.critical_force),
            "loads": _nums(d.loads), "multiplicity": int(d.multiplicity), "active": list(d.active),
            "initial_critical_force": _f(d.initial_critical_force), "feasible": bool(d.feasible),
            "solver": {"status": d.solver.status, "iterations": int(d.solver.iterations)}}


def preload_design_out(r) -> dict[str, Any]:
    return {**outcome(r), **springs_out(r.q, r.manipulator.springs), "manipulator": manipulator_out(r.manipulator),
            "preloads": _nums(r.preloads), "q": _nums(r.q),
            "margin": _num(r.margin), "tip": _nums(r.tip), "energy": _num(r.energy),
            "active_bounds": [{"segment": int(b.segment), "variable": b.variable, "side": b.side,
                               "value": _num(b.value), "bound": _num(b.bound)} for b in r.active_bounds],
            "solver": {"status": r.solver.status, "iterations": int(r.solver.iterations)}}
