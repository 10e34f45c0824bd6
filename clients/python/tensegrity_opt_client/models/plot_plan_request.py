from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, Literal, TypeVar, cast

from attrs import define as _attrs_define

from ..models.plot_plan_request_format_type_0 import PlotPlanRequestFormatType0
from ..models.plot_plan_request_objective import PlotPlanRequestObjective
from ..models.plot_plan_request_on_infeasible import PlotPlanRequestOnInfeasible
from ..models.plot_plan_request_on_snap import PlotPlanRequestOnSnap
from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.design_segmented_manipulator_in import DesignSegmentedManipulatorIn
    from ..models.design_uniform_manipulator_in import DesignUniformManipulatorIn
    from ..models.rest_length_bounds_in import RestLengthBoundsIn
    from ..models.start_q import StartQ


T = TypeVar("T", bound="PlotPlanRequest")


@_attrs_define
class PlotPlanRequest:
    """The plan of `/v1/control/plan` computed for the figure (the same body): rest lengths, tip path, margin.

    Attributes:
        manipulator (DesignSegmentedManipulatorIn | DesignUniformManipulatorIn): the chain (at most 60 segments): {"n",
            "a", "b", "k", "L0", "spring"} (uniform) or {"segments": [...]}
        targets (list[list[float]]): tip positions [x, y] per step (length units; 1..2000, server limit
            TENSEGRITY_MAX_TRAJECTORY_STEPS)
        bounds (list[float | list[float]] | None | RestLengthBoundsIn | Unset): actuator bounds on the rest lengths;
            default (0.1 b_min, 4 b_max)
        dpi (int | Unset): PNG resolution in dots per inch (30..200; default 120, the command line's too) Default: 120.
        dt (float | None | Unset): a fixed time between steps (seconds, > 0) instead of `times`: t_k = (k + 1) dt
        end_angles (list[float | None] | None | Unset): the last link's absolute angle per step (rad; null: free), as
            many as targets; default free
        format_ (None | PlotPlanRequestFormatType0 | Unset): "png" or "svg"; when absent the Accept header decides
            (image/svg+xml or image/png), PNG by default
        horizon (int | Literal['all'] | None | Unset): null: step by step; N: a receding horizon, each step planned with
            the N steps from it as one IPOPT problem (equilibrium, range, bounds, margin of every step and the rate box
            between steps as constraints; tip error and actuator motion as objective), the first applied; all: the whole
            trajectory as one problem. Needs `objective: change`; its steps' method is horizon (none: held)
        loads (list[float] | list[list[float]] | None | Unset): dead tip load: one [fx, fy] or one per step; default
            none
        margin (float | Unset): required stability margin: the smallest eigenvalue of the Hessian of E - F . tip in the
            joint angles, absolute, in torque per radian (force x length / rad) like every margin of the API; for a margin
            relative to the chain's torque scale max k c^2, multiply by that scale Default: 0.001.
        objective (PlotPlanRequestObjective | Unset): change: least change from the previous step (compiled Newton,
            IPOPT where a bound is active); margin: largest margin; energy: least spring energy (IPOPT) Default:
            PlotPlanRequestObjective.CHANGE.
        on_infeasible (PlotPlanRequestOnInfeasible | Unset): what an infeasible step commands: hold (the previous
            command; the arm stays, under the step's load) or approach (the rest lengths of the admissible pose nearest to
            the target, within the bounds, the rate limit and the margin: the arm moves toward the target and catches up
            when it is in reach) Default: PlotPlanRequestOnInfeasible.HOLD.
        on_snap (PlotPlanRequestOnSnap | Unset): when the arm snaps during a step (nothing admissible avoids it) or has
            no equilibrium (a joint reaches its stop): continue (the next steps start from where it went) or stop (the plan
            ends after that step) Default: PlotPlanRequestOnSnap.CONTINUE.
        rate_limit (float | list[float] | None | Unset): largest speed of each rest length (length units per second): a
            number or 2n numbers; step k changes each rest length by at most rate_limit * (t_k - t_{k-1}). Needs `times` or
            `dt`; default none
        rest_lengths0 (list[list[float]] | None | Unset): the arm's current rest lengths [L1_0, L2_0] per segment (n
            pairs, length units, inside `bounds`): the start is an equilibrium with them and the first step's change is
            measured from them; default the manipulator's own
        start (None | StartQ | Unset): {"q": [...]}: the configuration with the start's rest lengths (`rest_lengths0`)
            under the first load; null: the equilibrium under it reached from the least-energy rest configuration
        taut (bool | Unset): keep every spring in tension (L > L0, strictly) at every designed pose; required for a
            chain with tension-only springs (there the laws agree; the moves between a plan's poses are verified under the
            laws) Default: False.
        times (list[float] | None | Unset): the steps' instants (seconds), as many as targets, strictly increasing from
            a first one > 0: the start (`rest_lengths0`, `start`) is the state at time 0; default none (or `dt`)
        verify (bool | Unset): verify every step along its transition (`verified`): the previous command and load moving
            linearly to the step's over its interval, a command is sent only where the arm follows its branch to the step's
            pose, stable with the margin all along (no fold, branch point or joint stop on the way); false: the end pose
            only, nothing verified Default: True.
        weights (list[list[float]] | None | Unset): weights [w1, w2] of each segment's rest-length changes in the least-
            change objective (n pairs, > 0); default 1
    """

    manipulator: DesignSegmentedManipulatorIn | DesignUniformManipulatorIn
    targets: list[list[float]]
    bounds: list[float | list[float]] | None | RestLengthBoundsIn | Unset = UNSET
    dpi: int | Unset = 120
    dt: float | None | Unset = UNSET
    end_angles: list[float | None] | None | Unset = UNSET
    format_: None | PlotPlanRequestFormatType0 | Unset = UNSET
    horizon: int | Literal["all"] | None | Unset = UNSET
    loads: list[float] | list[list[float]] | None | Unset = UNSET
    margin: float | Unset = 0.001
    objective: PlotPlanRequestObjective | Unset = PlotPlanRequestObjective.CHANGE
    on_infeasible: PlotPlanRequestOnInfeasible | Unset = PlotPlanRequestOnInfeasible.HOLD
    on_snap: PlotPlanRequestOnSnap | Unset = PlotPlanRequestOnSnap.CONTINUE
    rate_limit: float | list[float] | None | Unset = UNSET
    rest_lengths0: list[list[float]] | None | Unset = UNSET
    start: None | StartQ | Unset = UNSET
    taut: bool | Unset = False
    times: list[float] | None | Unset = UNSET
    verify: bool | Unset = True
    weights: list[list[float]] | None | Unset = UNSET

    def to_dict(self) -> dict[str, Any]:
        from ..models.design_uniform_manipulator_in import DesignUniformManipulatorIn  # noqa: PLC0415
        from ..models.rest_length_bounds_in import RestLengthBoundsIn  # noqa: PLC0415
        from ..models.start_q import StartQ  # noqa: PLC0415

        manipulator: dict[str, Any]
        if isinstance(self.manipulator, DesignUniformManipulatorIn):
            manipulator = self.manipulator.to_dict()
        else:
            manipulator = self.manipulator.to_dict()

        targets = []
        for targets_item_data in self.targets:
            targets_item = targets_item_data

            targets.append(targets_item)

        bounds: dict[str, Any] | list[float | list[float]] | None | Unset
        if isinstance(self.bounds, Unset):
            bounds = UNSET
        elif isinstance(self.bounds, list):
            bounds = []
            for bounds_type_0_type_0_item_data in self.bounds:
                bounds_type_0_type_0_item: float | list[float]
                if isinstance(bounds_type_0_type_0_item_data, list):
                    bounds_type_0_type_0_item = bounds_type_0_type_0_item_data

                else:
                    bounds_type_0_type_0_item = bounds_type_0_type_0_item_data
                bounds.append(bounds_type_0_type_0_item)

        elif isinstance(self.bounds, RestLengthBoundsIn):
            bounds = self.bounds.to_dict()
        else:
            bounds = self.bounds

        dpi = self.dpi

        dt: float | None | Unset
        if isinstance(self.dt, Unset):
            dt = UNSET
        else:
            dt = self.dt

        end_angles: list[float | None] | None | Unset
        if isinstance(self.end_angles, Unset):
            end_angles = UNSET
        elif isinstance(self.end_angles, list):
            end_angles = []
            for end_angles_type_0_item_data in self.end_angles:
                end_angles_type_0_item: float | None
                end_angles_type_0_item = end_angles_type_0_item_data
                end_angles.append(end_angles_type_0_item)

        else:
            end_angles = self.end_angles

        format_: None | str | Unset
        if isinstance(self.format_, Unset):
            format_ = UNSET
        elif isinstance(self.format_, PlotPlanRequestFormatType0):
            format_ = self.format_.value
        else:
            format_ = self.format_

        horizon: int | Literal["all"] | None | Unset
        if isinstance(self.horizon, Unset):
            horizon = UNSET
        else:
            horizon = self.horizon

        loads: list[float] | list[list[float]] | None | Unset
        if isinstance(self.loads, Unset):
            loads = UNSET
        elif isinstance(self.loads, list):
            loads = self.loads

        elif isinstance(self.loads, list):
            loads = []
            for loads_type_0_type_1_item_data in self.loads:
                loads_type_0_type_1_item = loads_type_0_type_1_item_data

                loads.append(loads_type_0_type_1_item)

        else:
            loads = self.loads

        margin = self.margin

        objective: str | Unset = UNSET
        if not isinstance(self.objective, Unset):
            objective = self.objective.value

        on_infeasible: str | Unset = UNSET
        if not isinstance(self.on_infeasible, Unset):
            on_infeasible = self.on_infeasible.value

        on_snap: str | Unset = UNSET
        if not isinstance(self.on_snap, Unset):
            on_snap = self.on_snap.value

        rate_limit: float | list[float] | None | Unset
        if isinstance(self.rate_limit, Unset):
            rate_limit = UNSET
        elif isinstance(self.rate_limit, list):
            rate_limit = self.rate_limit

        else:
            rate_limit = self.rate_limit

        rest_lengths0: list[list[float]] | None | Unset
        if isinstance(self.rest_lengths0, Unset):
            rest_lengths0 = UNSET
        elif isinstance(self.rest_lengths0, list):
            rest_lengths0 = []
            for rest_lengths0_type_0_item_data in self.rest_lengths0:
                rest_lengths0_type_0_item = rest_lengths0_type_0_item_data

                rest_lengths0.append(rest_lengths0_type_0_item)

        else:
            rest_lengths0 = self.rest_lengths0

        start: dict[str, Any] | None | Unset
        if isinstance(self.start, Unset):
            start = UNSET
        elif isinstance(self.start, StartQ):
            start = self.start.to_dict()
        else:
            start = self.start

        taut = self.taut

        times: list[float] | None | Unset
        if isinstance(self.times, Unset):
            times = UNSET
        elif isinstance(self.times, list):
            times = self.times

        else:
            times = self.times

        verify = self.verify

        weights: list[list[float]] | None | Unset
        if isinstance(self.weights, Unset):
            weights = UNSET
        elif isinstance(self.weights, list):
            weights = []
            for weights_type_0_item_data in self.weights:
                weights_type_0_item = weights_type_0_item_data

                weights.append(weights_type_0_item)

        else:
            weights = self.weights

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "manipulator": manipulator,
                "targets": targets,
            }
        )
        if bounds is not UNSET:
            field_dict["bounds"] = bounds
        if dpi is not UNSET:
            field_dict["dpi"] = dpi
        if dt is not UNSET:
            field_dict["dt"] = dt
        if end_angles is not UNSET:
            field_dict["end_angles"] = end_angles
        if format_ is not UNSET:
            field_dict["format"] = format_
        if horizon is not UNSET:
            field_dict["horizon"] = horizon
        if loads is not UNSET:
            field_dict["loads"] = loads
        if margin is not UNSET:
            field_dict["margin"] = margin
        if objective is not UNSET:
            field_dict["objective"] = objective
        if on_infeasible is not UNSET:
            field_dict["on_infeasible"] = on_infeasible
        if on_snap is not UNSET:
            field_dict["on_snap"] = on_snap
        if rate_limit is not UNSET:
            field_dict["rate_limit"] = rate_limit
        if rest_lengths0 is not UNSET:
            field_dict["rest_lengths0"] = rest_lengths0
        if start is not UNSET:
            field_dict["start"] = start
        if taut is not UNSET:
            field_dict["taut"] = taut
        if times is not UNSET:
            field_dict["times"] = times
        if verify is not UNSET:
            field_dict["verify"] = verify
        if weights is not UNSET:
            field_dict["weights"] = weights

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.design_segmented_manipulator_in import DesignSegmentedManipulatorIn  # noqa: PLC0415
        from ..models.design_uniform_manipulator_in import DesignUniformManipulatorIn  # noqa: PLC0415
        from ..models.rest_length_bounds_in import RestLengthBoundsIn  # noqa: PLC0415
        from ..models.start_q import StartQ  # noqa: PLC0415

        d = dict(src_dict)

        def _parse_manipulator(data: object) -> DesignSegmentedManipulatorIn | DesignUniformManipulatorIn:
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                manipulator_type_0 = DesignUniformManipulatorIn.from_dict(data)

                return manipulator_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            if not isinstance(data, dict):
                raise TypeError()
            manipulator_type_1 = DesignSegmentedManipulatorIn.from_dict(data)

            return manipulator_type_1

        manipulator = _parse_manipulator(d.pop("manipulator"))

        targets = []
        _targets = d.pop("targets")
        for targets_item_data in _targets:
            targets_item = cast(list[float], targets_item_data)

            targets.append(targets_item)

        def _parse_bounds(data: object) -> list[float | list[float]] | None | RestLengthBoundsIn | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                bounds_type_0_type_0 = []
                _bounds_type_0_type_0 = data
                for bounds_type_0_type_0_item_data in _bounds_type_0_type_0:

                    def _parse_bounds_type_0_type_0_item(data: object) -> float | list[float]:
                        try:
                            if not isinstance(data, list):
                                raise TypeError()
                            bounds_type_0_type_0_item_type_1 = cast(list[float], data)

                            return bounds_type_0_type_0_item_type_1
                        except (TypeError, ValueError, AttributeError, KeyError):
                            pass
                        return cast(float | list[float], data)

                    bounds_type_0_type_0_item = _parse_bounds_type_0_type_0_item(bounds_type_0_type_0_item_data)

                    bounds_type_0_type_0.append(bounds_type_0_type_0_item)

                return bounds_type_0_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                bounds_type_0_type_1 = RestLengthBoundsIn.from_dict(data)

                return bounds_type_0_type_1
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float | list[float]] | None | RestLengthBoundsIn | Unset, data)

        bounds = _parse_bounds(d.pop("bounds", UNSET))

        dpi = d.pop("dpi", UNSET)

        def _parse_dt(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        dt = _parse_dt(d.pop("dt", UNSET))

        def _parse_end_angles(data: object) -> list[float | None] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                end_angles_type_0 = []
                _end_angles_type_0 = data
                for end_angles_type_0_item_data in _end_angles_type_0:

                    def _parse_end_angles_type_0_item(data: object) -> float | None:
                        if data is None:
                            return data
                        return cast(float | None, data)

                    end_angles_type_0_item = _parse_end_angles_type_0_item(end_angles_type_0_item_data)

                    end_angles_type_0.append(end_angles_type_0_item)

                return end_angles_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float | None] | None | Unset, data)

        end_angles = _parse_end_angles(d.pop("end_angles", UNSET))

        def _parse_format_(data: object) -> None | PlotPlanRequestFormatType0 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                format_type_0 = PlotPlanRequestFormatType0(data)

                return format_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | PlotPlanRequestFormatType0 | Unset, data)

        format_ = _parse_format_(d.pop("format", UNSET))

        def _parse_horizon(data: object) -> int | Literal["all"] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            horizon_type_0_type_1 = cast(Literal["all"], data)
            if horizon_type_0_type_1 != "all":
                raise ValueError(f"horizon_type_0_type_1 must match const 'all', got '{horizon_type_0_type_1}'")
            return horizon_type_0_type_1
            return cast(int | Literal["all"] | None | Unset, data)

        horizon = _parse_horizon(d.pop("horizon", UNSET))

        def _parse_loads(data: object) -> list[float] | list[list[float]] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                loads_type_0_type_0 = cast(list[float], data)

                return loads_type_0_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            try:
                if not isinstance(data, list):
                    raise TypeError()
                loads_type_0_type_1 = []
                _loads_type_0_type_1 = data
                for loads_type_0_type_1_item_data in _loads_type_0_type_1:
                    loads_type_0_type_1_item = cast(list[float], loads_type_0_type_1_item_data)

                    loads_type_0_type_1.append(loads_type_0_type_1_item)

                return loads_type_0_type_1
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float] | list[list[float]] | None | Unset, data)

        loads = _parse_loads(d.pop("loads", UNSET))

        margin = d.pop("margin", UNSET)

        _objective = d.pop("objective", UNSET)
        objective: PlotPlanRequestObjective | Unset
        if isinstance(_objective, Unset):
            objective = UNSET
        else:
            objective = PlotPlanRequestObjective(_objective)

        _on_infeasible = d.pop("on_infeasible", UNSET)
        on_infeasible: PlotPlanRequestOnInfeasible | Unset
        if isinstance(_on_infeasible, Unset):
            on_infeasible = UNSET
        else:
            on_infeasible = PlotPlanRequestOnInfeasible(_on_infeasible)

        _on_snap = d.pop("on_snap", UNSET)
        on_snap: PlotPlanRequestOnSnap | Unset
        if isinstance(_on_snap, Unset):
            on_snap = UNSET
        else:
            on_snap = PlotPlanRequestOnSnap(_on_snap)

        def _parse_rate_limit(data: object) -> float | list[float] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                rate_limit_type_0_type_1 = cast(list[float], data)

                return rate_limit_type_0_type_1
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(float | list[float] | None | Unset, data)

        rate_limit = _parse_rate_limit(d.pop("rate_limit", UNSET))

        def _parse_rest_lengths0(data: object) -> list[list[float]] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                rest_lengths0_type_0 = []
                _rest_lengths0_type_0 = data
                for rest_lengths0_type_0_item_data in _rest_lengths0_type_0:
                    rest_lengths0_type_0_item = cast(list[float], rest_lengths0_type_0_item_data)

                    rest_lengths0_type_0.append(rest_lengths0_type_0_item)

                return rest_lengths0_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[list[float]] | None | Unset, data)

        rest_lengths0 = _parse_rest_lengths0(d.pop("rest_lengths0", UNSET))

        def _parse_start(data: object) -> None | StartQ | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                start_type_0 = StartQ.from_dict(data)

                return start_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | StartQ | Unset, data)

        start = _parse_start(d.pop("start", UNSET))

        taut = d.pop("taut", UNSET)

        def _parse_times(data: object) -> list[float] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                times_type_0 = cast(list[float], data)

                return times_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float] | None | Unset, data)

        times = _parse_times(d.pop("times", UNSET))

        verify = d.pop("verify", UNSET)

        def _parse_weights(data: object) -> list[list[float]] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                weights_type_0 = []
                _weights_type_0 = data
                for weights_type_0_item_data in _weights_type_0:
                    weights_type_0_item = cast(list[float], weights_type_0_item_data)

                    weights_type_0.append(weights_type_0_item)

                return weights_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[list[float]] | None | Unset, data)

        weights = _parse_weights(d.pop("weights", UNSET))

        plot_plan_request = cls(
            manipulator=manipulator,
            targets=targets,
            bounds=bounds,
            dpi=dpi,
            dt=dt,
            end_angles=end_angles,
            format_=format_,
            horizon=horizon,
            loads=loads,
            margin=margin,
            objective=objective,
            on_infeasible=on_infeasible,
            on_snap=on_snap,
            rate_limit=rate_limit,
            rest_lengths0=rest_lengths0,
            start=start,
            taut=taut,
            times=times,
            verify=verify,
            weights=weights,
        )

        return plot_plan_request
