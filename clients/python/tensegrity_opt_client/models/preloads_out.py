from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, Literal, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

if TYPE_CHECKING:
    from ..models.active_bound_out import ActiveBoundOut
    from ..models.manipulator_out import ManipulatorOut
    from ..models.solver_info import SolverInfo


T = TypeVar("T", bound="PreloadsOut")


@_attrs_define
class PreloadsOut:
    """`PreloadDesign.to_dict()`: rest lengths for a pose, verified by the forward equilibrium.

    Attributes:
        active_bounds (list[ActiveBoundOut]): the rest lengths at (or near) their bounds
        energy (float):
        manipulator (ManipulatorOut):
        margin (float): achieved stability margin (recomputed)
        message (str): what happened, in a sentence
        preloads (list[list[float]]): rest lengths [L1_0, L2_0] per segment
        q (list[float]): verified equilibrium configuration (rad)
        solver (SolverInfo):
        status (Literal['optimal']): `optimal`: IPOPT converged to rest lengths meeting every requirement, and the
            forward equilibrium with them, from the optimiser's configuration, lands on the target, stable
        success (bool): whether it worked: `status` is one of optimal
        tip (list[float]):
    """

    active_bounds: list[ActiveBoundOut]
    energy: float
    manipulator: ManipulatorOut
    margin: float
    message: str
    preloads: list[list[float]]
    q: list[float]
    solver: SolverInfo
    status: Literal["optimal"]
    success: bool
    tip: list[float]
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        active_bounds = []
        for active_bounds_item_data in self.active_bounds:
            active_bounds_item = active_bounds_item_data.to_dict()
            active_bounds.append(active_bounds_item)

        energy = self.energy

        manipulator = self.manipulator.to_dict()

        margin = self.margin

        message = self.message

        preloads = []
        for preloads_item_data in self.preloads:
            preloads_item = preloads_item_data

            preloads.append(preloads_item)

        q = self.q

        solver = self.solver.to_dict()

        status = self.status

        success = self.success

        tip = self.tip

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "active_bounds": active_bounds,
                "energy": energy,
                "manipulator": manipulator,
                "margin": margin,
                "message": message,
                "preloads": preloads,
                "q": q,
                "solver": solver,
                "status": status,
                "success": success,
                "tip": tip,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.active_bound_out import ActiveBoundOut  # noqa: PLC0415
        from ..models.manipulator_out import ManipulatorOut  # noqa: PLC0415
        from ..models.solver_info import SolverInfo  # noqa: PLC0415

        d = dict(src_dict)
        active_bounds = []
        _active_bounds = d.pop("active_bounds")
        for active_bounds_item_data in _active_bounds:
            active_bounds_item = ActiveBoundOut.from_dict(active_bounds_item_data)

            active_bounds.append(active_bounds_item)

        energy = d.pop("energy")

        manipulator = ManipulatorOut.from_dict(d.pop("manipulator"))

        margin = d.pop("margin")

        message = d.pop("message")

        preloads = []
        _preloads = d.pop("preloads")
        for preloads_item_data in _preloads:
            preloads_item = cast(list[float], preloads_item_data)

            preloads.append(preloads_item)

        q = cast(list[float], d.pop("q"))

        solver = SolverInfo.from_dict(d.pop("solver"))

        status = cast(Literal["optimal"], d.pop("status"))
        if status != "optimal":
            raise ValueError(f"status must match const 'optimal', got '{status}'")

        success = d.pop("success")

        tip = cast(list[float], d.pop("tip"))

        preloads_out = cls(
            active_bounds=active_bounds,
            energy=energy,
            manipulator=manipulator,
            margin=margin,
            message=message,
            preloads=preloads,
            q=q,
            solver=solver,
            status=status,
            success=success,
            tip=tip,
        )

        preloads_out.additional_properties = d
        return preloads_out

    @property
    def additional_keys(self) -> list[str]:
        return list(self.additional_properties.keys())

    def __getitem__(self, key: str) -> Any:
        return self.additional_properties[key]

    def __setitem__(self, key: str, value: Any) -> None:
        self.additional_properties[key] = value

    def __delitem__(self, key: str) -> None:
        del self.additional_properties[key]

    def __contains__(self, key: str) -> bool:
        return key in self.additional_properties
