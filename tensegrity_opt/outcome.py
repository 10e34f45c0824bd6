"""The result contract: every public result says whether it worked the same way.

Like :class:`scipy.optimize.OptimizeResult`, one shape a user learns once. Every result class that a
public function returns (and every sub-record that carries an outcome of its own) derives from
:class:`Outcome` and has

``success`` : bool
    Whether the computation delivered what was asked (``status in SUCCESS``).
``status`` : str
    One word from the class's closed vocabulary :attr:`Outcome.STATUSES` (documented per class, checked
    on construction): never prose and never a solver's own string. The solver's status (IPOPT's
    ``return_status``, the Newton status) is a detail, ``solver``, where a result has one.
``message`` : str
    One sentence for a person: what happened, in the caller's terms.

``to_dict()`` carries all three first (:meth:`Outcome.outcome`), and results are immutable once
returned: frozen dataclasses whose arrays are read-only (:func:`freeze`).
"""

from __future__ import annotations

import dataclasses
from collections.abc import Mapping
from typing import Any, ClassVar

import numpy as np

__all__ = ["Outcome", "SolverInfo", "freeze", "outcome_classes"]

_REGISTRY: list[type[Outcome]] = []


class Outcome:
    """Mixin of every public result: ``success``, ``status`` (closed vocabulary), ``message``.

    A subclass declares

    * ``STATUSES``: a mapping from every status it may take to what that status means;
    * ``SUCCESS``: the statuses that count as success (a subset of ``STATUSES``);

    and provides ``status`` and ``message`` as dataclass fields or properties. ``success`` is derived, so
    it never disagrees with ``status``. Construction checks that ``status`` belongs to the vocabulary
    (:meth:`_check_outcome`, called by :func:`freeze`).
    """

    STATUSES: ClassVar[Mapping[str, str]] = {}
    SUCCESS: ClassVar[frozenset[str]] = frozenset()

    def __init_subclass__(cls, **kw: Any) -> None:
        super().__init_subclass__(**kw)
        if not cls.STATUSES:
            raise TypeError(f"{cls.__name__} must declare its STATUSES (the closed status vocabulary)")
        extra = set(cls.SUCCESS) - set(cls.STATUSES)
        if extra:
            raise TypeError(f"{cls.__name__}.SUCCESS names statuses outside STATUSES: {sorted(extra)}")
        _REGISTRY.append(cls)

    @property
    def success(self) -> bool:
        """``True`` when :attr:`status` is one of the class's :attr:`SUCCESS` statuses."""
        return self.status in self.SUCCESS  # type: ignore[attr-defined]

    def outcome(self) -> dict[str, Any]:
        """``{"success", "status", "message"}``: the first three keys of every ``to_dict()``."""
        return {"success": bool(self.success), "status": str(self.status),  # type: ignore[attr-defined]
                "message": str(self.message)}  # type: ignore[attr-defined]

    def _check_outcome(self) -> None:
        status = self.status  # type: ignore[attr-defined]
        if status not in self.STATUSES:
            raise ValueError(f"{type(self).__name__}.status {status!r} is not one of {sorted(self.STATUSES)}")


@dataclasses.dataclass(frozen=True, slots=True)
class SolverInfo:
    """The solver detail of a result: the solver's own status string (IPOPT's ``return_status``, the Newton
    status, ``"straight"`` ...) and its iteration count (``None``: not counted)."""

    status: str
    iterations: int | None = None

    def to_dict(self) -> dict[str, Any]:
        """``{"status", "iterations"}``."""
        return {"status": str(self.status), "iterations": None if self.iterations is None else int(self.iterations)}


def freeze(obj: Any, *, copy: bool = True) -> None:
    """Make a (frozen) dataclass result immutable all the way: its numpy arrays become read-only (a private
    copy of each writeable one, unless ``copy=False``: the builder passed arrays it owns), its lists tuples;
    then check its status against its vocabulary. Call it from ``__post_init__``."""
    if dataclasses.is_dataclass(obj):
        for f in dataclasses.fields(obj):
            v = getattr(obj, f.name)
            if isinstance(v, np.ndarray):
                if v.flags.writeable:
                    if copy:                       # a private copy: the caller's array stays theirs
                        v = v.copy()
                        object.__setattr__(obj, f.name, v)
                    v.setflags(write=False)
            elif isinstance(v, list):
                object.__setattr__(obj, f.name, tuple(v))
    if isinstance(obj, Outcome):
        obj._check_outcome()


def outcome_classes() -> list[type[Outcome]]:
    """Every class that follows the contract (for the documentation and the contract's tests)."""
    return list(_REGISTRY)
