"""The state of a control stream (``/v1/control/stream``) and the solver threads streams run in.

A stream is a connection for one chain in one mode; its session keeps what the next step continues
from (the library's own state objects) and answers each step with the library's ``to_dict()`` plus
the stream's events:

* ``track`` (:class:`TrackSession`): a :class:`tensegrity_opt.analyses.paths.continuation.Tracker`; each step
  ``(dx, dy)`` is ``Tracker.solve(dx, dy)``; a ``jump`` event when the tracker left its branch (the
  branch ended or turned unstable: a global re-solve from the last configuration, what the chain does).
* ``preloads`` (:class:`PreloadsSession`): a :class:`tensegrity_opt.PreloadFollower`; each step's rest lengths
  are commanded, ``PreloadFollower.step(rest_lengths, load)``: the equilibrium the arm reaches along the
  command's transition from the last state (the branch followed by continuation), a ``snap`` event where the branch
  folds on the way (the landing ``q_after``).
* ``inverse`` (:class:`InverseSession`): a :class:`tensegrity_opt.PreloadController`; each step is
  ``PreloadController.step(target, load, end_angle, dt=...)``, ``dt`` the step's own, the difference of its
  ``time`` and the last step's (the open is time 0), or the open's; the answer carries the step's ``time``.

Every function here runs in the stream's solver thread (:class:`service.execution.slots.StreamSlots`), never
on the event loop; :func:`step_task` returns the answer already rendered (``service.responses.render_json``).
Library exceptions propagate unchanged (the route maps them through :mod:`service.api.errors`); a session
keeps its state when a step raises.
"""

from __future__ import annotations

from typing import Any

import numpy as np

import tensegrity_opt as to
from tensegrity_opt.analyses.design.follower import PreloadFollower
from tensegrity_opt.analyses.design.preload_control import PreloadController
from tensegrity_opt.analyses.paths.continuation import Tracker
from tensegrity_opt.serialize import number, numbers

from . import schemas as s
from .adapters.inputs import build_manipulator
from .responses import render_json

__all__ = ["Session", "TrackSession", "PreloadsSession", "InverseSession", "open_session", "step_task", "SESSIONS"]


def _max_change(a: np.ndarray, b: np.ndarray) -> float:
    return float(np.max(np.abs(np.asarray(a) - np.asarray(b)))) if len(a) else 0.0


class Session:
    """One stream's state: ``opened()`` (the answer to the open), ``step(msg)`` (the answer to a step)."""

    mode = ""

    def __init__(self, m: to.Manipulator) -> None:
        self.m = m

    def opened(self) -> dict[str, Any]:
        return {"n": self.m.n}

    def step(self, msg: Any) -> dict[str, Any]:  # pragma: no cover - every mode has its own
        raise NotImplementedError


class TrackSession(Session):
    mode = "track"

    def __init__(self, m: to.Manipulator, req: s.TrackOpen) -> None:
        super().__init__(m)
        self.tracker = Tracker(m, jump=req.jump)

    def step(self, msg: s.TrackStep) -> dict[str, Any]:
        tr = self.tracker
        prev, jumps = tr.current, tr.jumps
        eq = tr.solve(msg.dx, msg.dy)
        events: list[dict[str, Any]] = []
        if tr.jumps != jumps and prev is not None:
            events.append({"kind": "jump", "distance": number(_max_change(eq.q, prev.q)),
                           "q_before": numbers(prev.q), "energy_before": number(prev.energy),
                           "stable_before": bool(prev.stable)})
        return {**eq.to_dict(), "events": events, "jumps": tr.jumps}


class PreloadsSession(Session):
    mode = "preloads"

    def __init__(self, m: to.Manipulator, req: s.PreloadsOpen) -> None:
        super().__init__(m)
        self.follower = PreloadFollower(m, req.start, load=req.load)

    def opened(self) -> dict[str, Any]:
        f = self.follower
        return {"n": self.m.n, "q": numbers(f.q), "load": numbers(f.load)}

    def step(self, msg: s.PreloadsStep) -> dict[str, Any]:
        return self.follower.step(msg.rest_lengths, load=msg.load).to_dict()


class InverseSession(Session):
    mode = "inverse"

    def __init__(self, m: to.Manipulator, req: s.InverseOpen) -> None:
        super().__init__(m)
        self.controller = PreloadController(
            m, req.start, rest_lengths0=req.rest_lengths0, load=tuple(req.load),
            bounds=None if req.bounds is None else tuple(req.bounds), rate_limit=req.rate_limit, dt=req.dt,
            margin=req.margin, objective=req.objective, weights=req.weights, on_infeasible=req.on_infeasible,
            verify=req.verify, taut=req.taut)
        #: the last step's instant (s; the open is 0), None once a step came without a time base
        self.time: float | None = 0.0

    def opened(self) -> dict[str, Any]:
        c = self.controller
        return {"n": self.m.n, "q": numbers(c.q), "command": [numbers(p) for p in c.ell.reshape(c.n, 2)],
                "load": numbers(c.load), "on_infeasible": c.on_infeasible, "time": 0.0}

    def step(self, msg: s.InverseStep) -> dict[str, Any]:
        dt = msg.dt
        if msg.time is not None:
            if dt is not None:
                raise to.InvalidParameterError("give the step's time or its dt, not both", field="dt")
            if self.time is None:
                raise to.InvalidParameterError("the stream's clock is unknown (an earlier step had no time): give "
                                               "dt, the seconds since the last step", field="time")
            if not msg.time > self.time:
                raise to.InvalidParameterError(f"time must be after the last step's, {self.time:g} s", field="time")
            dt = msg.time - self.time
        h = dt if dt is not None else self.controller.dt
        res = self.controller.step(msg.target, load=msg.load, end_angle=msg.end_angle, dt=dt)
        self.time = None if h is None or self.time is None else (msg.time if msg.time is not None else self.time + h)
        return {**res.to_dict(), "time": self.time}


#: The session class of each mode.
SESSIONS: dict[str, type[Session]] = {"track": TrackSession, "preloads": PreloadsSession,
                                      "inverse": InverseSession}


def open_session(req: Any) -> tuple[Session, dict[str, Any]]:
    """The session an ``open`` message asks for and its ``opened`` fields (runs in the stream's thread:
    the preloads and inverse modes solve their start configuration)."""
    session = SESSIONS[req.mode](build_manipulator(req.manipulator), req)
    return session, session.opened()


def step_task(session: Session, msg: Any, seq: int) -> bytes:
    """One step's ``result`` message, rendered (in the stream's thread)."""
    return render_json({"type": "result", "seq": seq, "mode": session.mode, **session.step(msg)})
