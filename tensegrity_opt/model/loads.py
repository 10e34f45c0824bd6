"""The chain's dead loads: weights under gravity and point forces at joints (``docs/model.md``, "Weights and loads").

Every dead load is a constant force at a point carried by the chain: a triangle's centroid or the payload (weight
``mass * g``) or a joint (a joint force, ``Manipulator(..., joint_forces=((j, (fx, fy)), ...))``, joints counted
from 1). A point's position is ``p_1 + sum_j C[j] u_j`` (``p_1 = (b_1, 0)`` joint 1, ``u_j = (cos psi_j,
sin psi_j)`` link ``j``'s direction in the absolute angles ``psi_j = q_1 + ... + q_j``, ``C[j]`` a constant lever
length: :func:`~.inertia.mass_points`). So the potential of every dead load together is

    V(q) = -sum_points w . position = V_0 - sum_j G_j . u_j,    G_j = sum_points w C[j]

with one constant vector ``G_j`` per link (:func:`link_loads`): a tip force ``F`` is ``G_j = l_j F``, which is how
the solvers take every load at once. The chain's potential is ``E(q) + V(q)`` (its springs, its weights and joint
forces; a tip force's work ``-F . tip`` comes on top where the tip is loaded).

Derivatives (``u x G = cos psi G_y - sin psi G_x``): ``dV / dq_i = -sum_{j >= i} u_j x G_j`` and
``d^2 V / dq_i dq_k = sum_{j >= max(i, k)} G_j . u_j``.

:func:`unloaded_only` is the one refusal of an analysis that does not (yet) honour the loads.

The functions take a :class:`~.manipulator.Manipulator` (typed ``Any``: ``manipulator`` imports this module, and no
import goes back).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from ..errors import InvalidParameterError, UnsupportedError

__all__ = ["loads_key", "loads_json", "describe", "check_gravity", "check_joint_forces", "link_loads", "load_offset",
           "load_potential", "load_gradient",
           "load_hessian", "unloaded_only", "LOAD_ANALYSES"]

#: The analyses that honour the loads (named by the refusal of the others).
LOAD_ANALYSES = ("solve_equilibrium", "find_equilibria (method='search')", "solve_equilibrium_under_force",
                 "rest_configuration", "find_equilibria_under_force (stable_only=True)",
                 "force_deflection (branch='stable')", "cartesian_stiffness", "modes", "energy_landscape",
                 "load_capacity (boundary='free')", "preloads_for_holding", "holding_map",
                 "weight_capacity")


def _vector(value: Any, field: str) -> tuple[float, float]:
    try:
        x, y = (float(v) for v in value)
    except (TypeError, ValueError):
        raise InvalidParameterError(f"{field} must be a pair of numbers (x, y), got {value!r}", field=field) from None
    if not (math.isfinite(x) and math.isfinite(y)):
        raise InvalidParameterError(f"{field} must be finite, got {value!r}", field=field)
    return x, y


def check_gravity(value: Any) -> tuple[float, float] | None:
    """``gravity`` as a pair of floats, or None (no gravity)."""
    return None if value is None else _vector(value, "gravity")


def check_joint_forces(value: Any, n: int) -> tuple[tuple[int, tuple[float, float]], ...]:
    """``joint_forces`` as ``((joint, (fx, fy)), ...)``, joints ``1..n``; each item a pair ``(joint, (fx, fy))`` or
    a mapping ``{"joint": j, "force": [fx, fy]}`` (the JSON form)."""
    if value is None:
        return ()
    if isinstance(value, dict) and "joint" not in value:
        value = list(value.items())             # {joint: (fx, fy)}
    try:
        items = list(value)
    except TypeError:
        raise InvalidParameterError(f"joint_forces must be a list of (joint, (fx, fy)), got {value!r}",
                                    field="joint_forces") from None
    out = []
    for i, item in enumerate(items):
        field = f"joint_forces[{i}]"
        if isinstance(item, dict):
            unknown = [k for k in item if k not in ("joint", "force")]
            if unknown or "joint" not in item or "force" not in item:
                raise InvalidParameterError(f"{field} must be {{'joint': j, 'force': [fx, fy]}}, got {item!r}",
                                            field=field)
            j, f = item["joint"], item["force"]
        else:
            try:
                j, f = item
            except (TypeError, ValueError):
                raise InvalidParameterError(f"{field} must be a pair (joint, (fx, fy)), got {item!r}",
                                            field=field) from None
        if isinstance(j, bool) or not isinstance(j, (int, np.integer)) or not 1 <= int(j) <= n:
            raise InvalidParameterError(f"{field}.joint must be an integer from 1 to {n} (joints are counted from "
                                        f"the base, 1-based), got {j!r}", field=f"{field}.joint")
        out.append((int(j), _vector(f, f"{field}.force")))
    return tuple(out)


def _lever_rows(m: Any) -> tuple[np.ndarray, np.ndarray]:
    """``(w, C)``: the dead loads' forces ``w`` (P, 2) and their points' lever rows ``C`` (P, n)."""
    from .inertia import mass_points

    n, l = m.n, m.link_lengths
    w_rows, c_rows = [], []
    if m.gravity is not None:
        mass, joint, link, offset = mass_points(m)
        C = np.where(np.arange(n)[None, :] < joint[:, None], l[None, :], 0.0)
        C[np.arange(C.shape[0]), link] += offset
        w_rows.append(mass[:, None] * np.asarray(m.gravity, float)[None, :])
        c_rows.append(C)
    for j, f in m.joint_forces:                 # joint j (1-based) sits after links 1..j-1
        w_rows.append(np.array([f], float))
        c_rows.append(np.where(np.arange(n) < j - 1, l, 0.0)[None, :])
    if not w_rows:
        return np.zeros((0, 2)), np.zeros((0, n))
    return np.vstack(w_rows), np.vstack(c_rows)


def link_loads(m: Any) -> np.ndarray:
    """``G`` (n, 2): the dead loads on each link, ``V = V_0 - sum_j G_j . u_j`` (module docstring); zeros when the
    chain carries none."""
    w, C = _lever_rows(m)
    return C.T @ w


def load_offset(m: Any) -> float:
    """``V_0 = -sum w . p_1``: the loads' potential that no joint angle changes (joint 1 is fixed at ``(b_1, 0)``)."""
    w, _ = _lever_rows(m)
    return float(-w[:, 0].sum() * m.base_length) if w.size else 0.0


def _directions(q: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    phi = np.cumsum(q, axis=-1)
    return np.cos(phi), np.sin(phi)


def load_potential(m: Any, Q: Any) -> np.ndarray | float:
    """``V(q)`` of one configuration (n,) or of the rows of ``Q`` (M, n)."""
    G = m.link_loads
    c, s = _directions(np.asarray(Q, float))
    v = m.load_offset - (c @ G[:, 0] + s @ G[:, 1])
    return float(v) if np.ndim(v) == 0 else v


def load_gradient(m: Any, Q: Any) -> np.ndarray:
    """``dV / dq`` of one configuration (n,) or of the rows of ``Q`` (M, n)."""
    G = m.link_loads
    c, s = _directions(np.asarray(Q, float))
    cross = c * G[:, 1] - s * G[:, 0]
    return -np.flip(np.cumsum(np.flip(cross, -1), axis=-1), -1)


def load_hessian(m: Any, q: Any) -> np.ndarray:
    """``d^2 V / dq^2`` (n, n) at ``q`` (n,)."""
    G = m.link_loads
    c, s = _directions(np.asarray(q, float))
    d = np.flip(np.cumsum(np.flip(c * G[:, 0] + s * G[:, 1])))     # sum_{j >= i} G_j . u_j
    idx = np.maximum.outer(np.arange(m.n), np.arange(m.n))
    return d[idx]


def loads_key(m: Any) -> tuple | None:
    """The chain's dead loads as a plain tuple ``(payload, gravity, joint_forces)`` for a result to carry (picklable,
    immutable), or None when it carries none (:attr:`Manipulator.loaded`)."""
    return (m.payload, m.gravity, m.joint_forces) if m.loaded else None


def loads_json(key: tuple | None) -> dict[str, Any] | None:
    """The JSON form of :func:`loads_key`: ``gravity`` ``[gx, gy]`` (or null), ``payload``, ``joint_forces``
    ``[{"joint", "force": [fx, fy]}]``, ``total_mass`` omitted (the chain's description has the masses)."""
    if key is None:
        return None
    payload, gravity, forces = key
    return {"gravity": None if gravity is None else list(gravity), "payload": float(payload),
            "joint_forces": [{"joint": int(j), "force": [float(f[0]), float(f[1])]} for j, f in forces]}


def describe(key: tuple | None) -> str:
    """The loads in words (``"gravity (0, -9.81), payload 0.05, a force (0, 1) at joint 3"``); empty without."""
    if key is None:
        return ""
    payload, gravity, forces = key
    parts = []
    if gravity is not None:
        parts.append(f"gravity ({gravity[0]:g}, {gravity[1]:g})" + (f", payload {payload:g}" if payload else ""))
    parts += [f"a force ({f[0]:g}, {f[1]:g}) at joint {j}" for j, f in forces]
    return ", ".join(parts)


def unloaded_only(m: Any, what: str) -> None:
    """Refuse an analysis ``what`` that does not honour the dead loads when ``m`` carries some (gravity on a mass, or
    a joint force): :class:`UnsupportedError` naming ``gravity`` or ``joint_forces``."""
    if not getattr(m, "loaded", False):
        return
    field = "joint_forces" if m.joint_forces and m.gravity is None else "gravity"
    raise UnsupportedError(
        f"{what} does not honour the chain's dead loads (its weights under gravity and its joint forces; {field} is "
        f"set); the loads are honoured by {', '.join(LOAD_ANALYSES)}. Ask this analysis without them (gravity=None, "
        f"no joint_forces) or one of those", field=field, analysis=what)
