"""The springs of a chain: their law, and their state (length, stretch, force, taut / slack / pushing) at any
configuration.

Two spring laws (``docs/model.md``, "The spring law"):

* ``"linear"`` (the paper's model, the default): force ``k (L - L0)`` and energy ``k/2 (L - L0)^2`` at every
  length, so a spring shorter than its rest length *pushes* (a negative force);
* ``"tension_only"`` (a real extension spring or a cable in series): force ``k max(0, L - L0)``, energy
  ``k/2 max(0, L - L0)^2`` (C^1: the stiffness jumps where the spring goes slack).

:class:`Springs` holds one chain's spring data as arrays and evaluates the state of every spring for one
configuration ``q`` (n,) or many (..., n) at once: ``(..., n, 2)`` arrays, spring 1 then spring 2 of each segment.
Every result that carries a configuration reports it through :class:`Springs` (``spring_lengths``,
``spring_forces``, ...), so the numbers are the same on every interface.

:func:`linear_only` is the one refusal of an analysis that does not (yet) honour the tension-only law: an
:class:`~tensegrity_opt.errors.UnsupportedError` whose ``field`` names the first tension-only segment's
``spring`` (never a silent linear answer for a tension-only chain).
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from ..errors import InvalidParameterError, UnsupportedError, unknown_name

__all__ = ["SHORT_TOL", "SPRING_LAWS", "spring_law", "Springs", "SpringFields", "linear_only", "SPRING_STATES"]

#: The spring laws and what each means.
SPRING_LAWS: dict[str, str] = {
    "linear": "force k (L - L0) at every length: a spring shorter than its rest length pushes (the paper's model)",
    "tension_only": "force k max(0, L - L0): a spring shorter than its rest length is slack and carries nothing",
}

#: A spring is shorter than its rest length (slack or pushing) when ``L - L0 < -SHORT_TOL * L0``: a spring a design put
#: at its rest length (``L = L0`` to rounding) is taut at zero force, not pushing.
SHORT_TOL = 1e-9

#: The state of one spring: ``taut`` (L >= L0, in tension or at zero force), ``slack`` (tension-only, L < L0:
#: no force), ``pushing`` (linear law, L < L0: a compressive force a real tension spring cannot carry).
SPRING_STATES = ("taut", "slack", "pushing")


def spring_law(value: Any, field: str = "spring") -> str:
    """``value`` as a spring law name (:data:`SPRING_LAWS`), or :class:`InvalidParameterError` naming ``field``."""
    if isinstance(value, str) and value in SPRING_LAWS:
        return value
    if not isinstance(value, str):
        raise InvalidParameterError(f"{field} must be one of {sorted(SPRING_LAWS)}, got {value!r}", field=field)
    raise InvalidParameterError(f"{field}: {unknown_name(value, tuple(SPRING_LAWS), 'spring law')}", field=field)


@dataclass(frozen=True, eq=False)
class Springs:
    """One chain's springs as arrays (segment ``i``: row ``i``; spring 1 then spring 2).

    Attributes
    ----------
    c, beta : ndarray (n,)
        Each segment's half-diagonal and triangle half-angle.
    k, L0 : ndarray (n, 2)
        Stiffnesses and rest lengths (``L0`` may be (N, n, 2): one row per configuration of a series,
        :meth:`with_rest_lengths`).
    tension_only : ndarray (n,) of bool
        The segments whose springs follow the tension-only law.
    """

    c: np.ndarray
    beta: np.ndarray
    k: np.ndarray
    L0: np.ndarray
    tension_only: np.ndarray

    def __post_init__(self) -> None:
        for name in ("c", "beta", "k", "L0", "tension_only"):
            a = np.array(getattr(self, name))
            a.setflags(write=False)
            object.__setattr__(self, name, a)
        # read on the hot paths (every energy, torque and residual of a chain asks it): a plain bool, once
        object.__setattr__(self, "_linear", not bool(self.tension_only.any()))

    def with_rest_lengths(self, L0: Any) -> "Springs":
        """The same springs with the rest lengths ``L0``: (n, 2), or (N, n, 2) for a series of configurations whose
        rest lengths change (a plan, a simulation, a branch under a preload control)."""
        return replace(self, L0=np.asarray(L0, dtype=float))

    @property
    def linear(self) -> bool:
        """Every spring follows the linear law."""
        return self._linear

    def lengths(self, q: Any) -> np.ndarray:
        """Spring lengths ``L1 = 2c cos(beta + q/2)``, ``L2 = 2c cos(beta - q/2)`` at ``q`` (..., n): (..., n, 2)."""
        q = np.asarray(q, dtype=float)
        return np.stack([2.0 * self.c * np.cos(self.beta + q / 2.0), 2.0 * self.c * np.cos(self.beta - q / 2.0)],
                        axis=-1)

    def stretches(self, q: Any) -> np.ndarray:
        """``L - L0`` (..., n, 2): negative where a spring is shorter than its rest length."""
        return self.lengths(q) - self.L0

    def forces(self, q: Any) -> np.ndarray:
        """Spring forces, tension positive (..., n, 2): ``k (L - L0)`` (linear), ``k max(0, L - L0)`` (tension-only)."""
        s = self.stretches(q)
        if not self.linear:
            s = np.where(self.tension_only[:, None], np.maximum(s, 0.0), s)
        return self.k * s

    def states(self, q: Any) -> np.ndarray:
        """Each spring's state (:data:`SPRING_STATES`), (..., n, 2) strings."""
        short = self.stretches(q) < -SHORT_TOL * self.L0
        slack = np.broadcast_to(self.tension_only[:, None], short.shape)
        return np.where(short, np.where(slack, "slack", "pushing"), "taut")

    def energy(self, q: Any) -> np.ndarray:
        """Elastic energy of the chain at ``q`` (..., n): ``1/2 sum k s^2`` with ``s`` the stretch (clipped at 0 for a
        tension-only spring)."""
        f = self.forces(q)
        return 0.5 * np.sum(f * f / self.k, axis=(-2, -1))

    def to_dict(self, q: Any) -> dict[str, Any]:
        """The spring state at ``q`` (one configuration (n,) or a series (N, n)) as JSON:
        ``spring_lengths``, ``spring_stretches``, ``spring_forces`` (nested lists (n, 2) or (N, n, 2); a
        configuration that is not known, NaN, gives ``null``) and ``spring_states``."""
        q = np.asarray(q, dtype=float)
        known = np.isfinite(q).all(axis=-1)
        L, s, f, st = self.lengths(q), self.stretches(q), self.forces(q), self.states(q)

        def rows(a, i=None):
            a = a if i is None else a[i]
            return np.where(np.isfinite(a), a, np.nan).tolist()

        if q.ndim == 1:
            if not known:
                return {"spring_lengths": None, "spring_stretches": None, "spring_forces": None, "spring_states": None}
            return {"spring_lengths": L.tolist(), "spring_stretches": s.tolist(), "spring_forces": f.tolist(),
                    "spring_states": st.tolist()}
        out: dict[str, list] = {"spring_lengths": [], "spring_stretches": [], "spring_forces": [],
                                "spring_states": []}
        for i in range(q.shape[0]):
            ok = bool(known[i])
            out["spring_lengths"].append(L[i].tolist() if ok else None)
            out["spring_stretches"].append(s[i].tolist() if ok else None)
            out["spring_forces"].append(f[i].tolist() if ok else None)
            out["spring_states"].append(st[i].tolist() if ok else None)
        return out

    def summary(self, q: Any) -> list[str]:
        """Sentences for the springs that are not taut at ``q`` (n,): ``"spring 3.2 pushes 0.47"`` (its compressive
        force) or ``"spring 3.2 slack"``; segments and springs counted from 1."""
        st, f = self.states(q), self.forces(q)
        out = []
        for i, j in zip(*np.nonzero(st != "taut")):
            name = f"spring {i + 1}.{j + 1}"
            out.append(f"{name} slack" if st[i, j] == "slack" else f"{name} pushes {-f[i, j]:.3g}")
        return out


def linear_only(m: Any, what: str) -> None:
    """Refuse an analysis ``what`` that honours only the linear spring law when ``m`` has a tension-only segment:
    :class:`UnsupportedError` with ``field="segments[i].spring"`` (the first such segment)."""
    sp = getattr(m, "springs", None)
    if sp is None or sp.linear:                 # not a chain: the analysis's own checks refuse it
        return
    i = int(np.flatnonzero(sp.tension_only)[0])
    raise UnsupportedError(
        f"{what} honours only the linear spring law; segments[{i}].spring is 'tension_only'. The tension-only law "
        f"is honoured by solve_equilibrium (the least-energy equilibrium, joint stops included), find_equilibria, "
        f"force_deflection (branch='stable'), trace_branch, solve_equilibrium_under_force, rest_configuration, "
        f"limit_load, simulate, transition, PreloadFollower, plan_preloads and PreloadController (taut=True), "
        f"stability_atlas, "
        f"cartesian_stiffness, critical_force (springs taut at the straight chain), preloads_for_critical_force, "
        f"preloads_for_pose (taut=True), "
        f"energy_landscape and the spring state of every answer; use spring='linear' for this analysis (its answer "
        f"is then valid where every spring_states entry is 'taut')",
        field=f"segments[{i}].spring", spring="tension_only", analysis=what)


class SpringFields:
    """The spring state of a result that carries a configuration ``q`` (n,) or a series of them (N, n): mixed into
    the result types, which hold the chain's :class:`Springs` in ``springs`` (``None``: not known, every field
    ``None``). Arrays are (n, 2) or (N, n, 2): spring 1 then spring 2 of each segment."""

    springs: Springs | None
    q: Any

    def _spring_rest_lengths(self) -> Any:
        """The rest lengths of the configurations, where the result's own commands set them (a plan, a simulation):
        (n, 2) or (N, n, 2); ``None``: the chain's."""
        return None

    def _spring_model(self) -> Springs | None:
        s = self.springs
        if s is None:
            return None
        L0 = self._spring_rest_lengths()
        return s if L0 is None else s.with_rest_lengths(L0)

    @property
    def spring_lengths(self) -> np.ndarray | None:
        """Spring lengths ``L`` at ``q``."""
        s = self._spring_model()
        return None if s is None else s.lengths(self.q)

    @property
    def spring_stretches(self) -> np.ndarray | None:
        """``L - L0`` at ``q`` (negative: shorter than the rest length)."""
        s = self._spring_model()
        return None if s is None else s.stretches(self.q)

    @property
    def spring_forces(self) -> np.ndarray | None:
        """Spring forces at ``q``, tension positive (the law of each segment)."""
        s = self._spring_model()
        return None if s is None else s.forces(self.q)

    @property
    def spring_states(self) -> np.ndarray | None:
        """``"taut"``, ``"slack"`` (tension-only, L < L0) or ``"pushing"`` (linear law, L < L0) per spring."""
        s = self._spring_model()
        return None if s is None else s.states(self.q)

    def spring_dict(self) -> dict[str, Any]:
        """The four spring fields as JSON (:meth:`Springs.to_dict`)."""
        s = self._spring_model()
        if s is None or self.q is None:
            return {"spring_lengths": None, "spring_stretches": None, "spring_forces": None, "spring_states": None}
        return s.to_dict(self.q)
