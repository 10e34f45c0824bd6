from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define

from ..models.simulation_request_tip import SimulationRequestTip
from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.segmented_manipulator_in import SegmentedManipulatorIn
    from ..models.start_q import StartQ
    from ..models.uniform_manipulator_in import UniformManipulatorIn


T = TypeVar("T", bound="SimulationRequest")


@_attrs_define
class SimulationRequest:
    """Quasi-static simulation under sampled preloads and a tip load or deflection (`tensegrity_opt.simulate`).

    Attributes:
        manipulator (SegmentedManipulatorIn | UniformManipulatorIn): the chain: {"n", "a", "b", "k", "L0", "spring"}
            (uniform) or {"segments": [...]}
        loads (list[list[float]] | None | Unset): the dead tip load [fx, fy] at each sample (tip free; force units;
            default zero); fx < 0 compresses
        perturbation (float | Unset): where a snap's descent starts: this far (rad, the largest joint) from the fold
            along its null vector Default: 0.0001.
        preloads (list[list[list[float]]] | None | Unset): the rest lengths [L1_0, L2_0] of every segment at each
            sample, (K, n, 2) (length units); default the chain's own, constant
        start (None | StartQ | Unset): {"q": [...]}: the state at sample 0 (must be a stable equilibrium under the first
            inputs); null: free, the least-energy rest configuration (under a non-zero first load the least-potential stable
            equilibrium); held, the least-energy stable equilibrium at the first target
        targets (list[list[float]] | None | Unset): the tip deflection [dx, dy] at each sample (tip held; length units;
            the tip at (2 sum b - dx, dy))
        tip (SimulationRequestTip | Unset): free: the tip is loaded by `loads`; held: the tip is held at `targets`
            Default: SimulationRequestTip.FREE.
    """

    manipulator: SegmentedManipulatorIn | UniformManipulatorIn
    loads: list[list[float]] | None | Unset = UNSET
    perturbation: float | Unset = 0.0001
    preloads: list[list[list[float]]] | None | Unset = UNSET
    start: None | StartQ | Unset = UNSET
    targets: list[list[float]] | None | Unset = UNSET
    tip: SimulationRequestTip | Unset = SimulationRequestTip.FREE

    def to_dict(self) -> dict[str, Any]:
        from ..models.start_q import StartQ  # noqa: PLC0415
        from ..models.uniform_manipulator_in import UniformManipulatorIn  # noqa: PLC0415

        manipulator: dict[str, Any]
        if isinstance(self.manipulator, UniformManipulatorIn):
            manipulator = self.manipulator.to_dict()
        else:
            manipulator = self.manipulator.to_dict()

        loads: list[list[float]] | None | Unset
        if isinstance(self.loads, Unset):
            loads = UNSET
        elif isinstance(self.loads, list):
            loads = []
            for loads_type_0_item_data in self.loads:
                loads_type_0_item = loads_type_0_item_data

                loads.append(loads_type_0_item)

        else:
            loads = self.loads

        perturbation = self.perturbation

        preloads: list[list[list[float]]] | None | Unset
        if isinstance(self.preloads, Unset):
            preloads = UNSET
        elif isinstance(self.preloads, list):
            preloads = []
            for preloads_type_0_item_data in self.preloads:
                preloads_type_0_item = []
                for preloads_type_0_item_item_data in preloads_type_0_item_data:
                    preloads_type_0_item_item = preloads_type_0_item_item_data

                    preloads_type_0_item.append(preloads_type_0_item_item)

                preloads.append(preloads_type_0_item)

        else:
            preloads = self.preloads

        start: dict[str, Any] | None | Unset
        if isinstance(self.start, Unset):
            start = UNSET
        elif isinstance(self.start, StartQ):
            start = self.start.to_dict()
        else:
            start = self.start

        targets: list[list[float]] | None | Unset
        if isinstance(self.targets, Unset):
            targets = UNSET
        elif isinstance(self.targets, list):
            targets = []
            for targets_type_0_item_data in self.targets:
                targets_type_0_item = targets_type_0_item_data

                targets.append(targets_type_0_item)

        else:
            targets = self.targets

        tip: str | Unset = UNSET
        if not isinstance(self.tip, Unset):
            tip = self.tip.value

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "manipulator": manipulator,
            }
        )
        if loads is not UNSET:
            field_dict["loads"] = loads
        if perturbation is not UNSET:
            field_dict["perturbation"] = perturbation
        if preloads is not UNSET:
            field_dict["preloads"] = preloads
        if start is not UNSET:
            field_dict["start"] = start
        if targets is not UNSET:
            field_dict["targets"] = targets
        if tip is not UNSET:
            field_dict["tip"] = tip

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.segmented_manipulator_in import SegmentedManipulatorIn  # noqa: PLC0415
        from ..models.start_q import StartQ  # noqa: PLC0415
        from ..models.uniform_manipulator_in import UniformManipulatorIn  # noqa: PLC0415

        d = dict(src_dict)

        def _parse_manipulator(data: object) -> SegmentedManipulatorIn | UniformManipulatorIn:
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                manipulator_type_0 = UniformManipulatorIn.from_dict(data)

                return manipulator_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            if not isinstance(data, dict):
                raise TypeError()
            manipulator_type_1 = SegmentedManipulatorIn.from_dict(data)

            return manipulator_type_1

        manipulator = _parse_manipulator(d.pop("manipulator"))

        def _parse_loads(data: object) -> list[list[float]] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                loads_type_0 = []
                _loads_type_0 = data
                for loads_type_0_item_data in _loads_type_0:
                    loads_type_0_item = cast(list[float], loads_type_0_item_data)

                    loads_type_0.append(loads_type_0_item)

                return loads_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[list[float]] | None | Unset, data)

        loads = _parse_loads(d.pop("loads", UNSET))

        perturbation = d.pop("perturbation", UNSET)

        def _parse_preloads(data: object) -> list[list[list[float]]] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                preloads_type_0 = []
                _preloads_type_0 = data
                for preloads_type_0_item_data in _preloads_type_0:
                    preloads_type_0_item = []
                    _preloads_type_0_item = preloads_type_0_item_data
                    for preloads_type_0_item_item_data in _preloads_type_0_item:
                        preloads_type_0_item_item = cast(list[float], preloads_type_0_item_item_data)

                        preloads_type_0_item.append(preloads_type_0_item_item)

                    preloads_type_0.append(preloads_type_0_item)

                return preloads_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[list[list[float]]] | None | Unset, data)

        preloads = _parse_preloads(d.pop("preloads", UNSET))

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

        def _parse_targets(data: object) -> list[list[float]] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                targets_type_0 = []
                _targets_type_0 = data
                for targets_type_0_item_data in _targets_type_0:
                    targets_type_0_item = cast(list[float], targets_type_0_item_data)

                    targets_type_0.append(targets_type_0_item)

                return targets_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[list[float]] | None | Unset, data)

        targets = _parse_targets(d.pop("targets", UNSET))

        _tip = d.pop("tip", UNSET)
        tip: SimulationRequestTip | Unset
        if isinstance(_tip, Unset):
            tip = UNSET
        else:
            tip = SimulationRequestTip(_tip)

        simulation_request = cls(
            manipulator=manipulator,
            loads=loads,
            perturbation=perturbation,
            preloads=preloads,
            start=start,
            targets=targets,
            tip=tip,
        )

        return simulation_request
