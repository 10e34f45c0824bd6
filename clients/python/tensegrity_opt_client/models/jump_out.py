from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.jump_out_kind import JumpOutKind

if TYPE_CHECKING:
    from ..models.force import Force


T = TypeVar("T", bound="JumpOut")


@_attrs_define
class JumpOut:
    """A force discontinuity between two consecutive points (in the order followed).

    Attributes:
        branch_after (int): branch identifier after (-1: straight)
        branch_before (int): branch identifier before (-1: straight)
        delta (Force):
        dx_after (float):
        dx_before (float):
        force_after (Force):
        force_before (Force):
        kind (JumpOutKind): "buckling": leaving (or returning to) the stable straight chain at dx -> 0+, dy = 0, from 0
            to the guided critical force; "leave_straight": leaving (returning to) a straight chain that is not stable
            unloaded (K <= 0) or at dy != 0, from the straight force to the deflected point's; "snap": the selected stable
            branch ends or loses stability and the chain jumps to another stable branch; "switch": the least-energy stable
            branch changes while the previous one is still stable
        label (str): a sentence naming the jump with sign and size, e.g. "buckling of the straight chain: F_x 0 ->
            -0.573 (compressive)"
    """

    branch_after: int
    branch_before: int
    delta: Force
    dx_after: float
    dx_before: float
    force_after: Force
    force_before: Force
    kind: JumpOutKind
    label: str
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        branch_after = self.branch_after

        branch_before = self.branch_before

        delta = self.delta.to_dict()

        dx_after = self.dx_after

        dx_before = self.dx_before

        force_after = self.force_after.to_dict()

        force_before = self.force_before.to_dict()

        kind = self.kind.value

        label = self.label

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "branch_after": branch_after,
                "branch_before": branch_before,
                "delta": delta,
                "dx_after": dx_after,
                "dx_before": dx_before,
                "force_after": force_after,
                "force_before": force_before,
                "kind": kind,
                "label": label,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.force import Force  # noqa: PLC0415

        d = dict(src_dict)
        branch_after = d.pop("branch_after")

        branch_before = d.pop("branch_before")

        delta = Force.from_dict(d.pop("delta"))

        dx_after = d.pop("dx_after")

        dx_before = d.pop("dx_before")

        force_after = Force.from_dict(d.pop("force_after"))

        force_before = Force.from_dict(d.pop("force_before"))

        kind = JumpOutKind(d.pop("kind"))

        label = d.pop("label")

        jump_out = cls(
            branch_after=branch_after,
            branch_before=branch_before,
            delta=delta,
            dx_after=dx_after,
            dx_before=dx_before,
            force_after=force_after,
            force_before=force_before,
            kind=kind,
            label=label,
        )

        jump_out.additional_properties = d
        return jump_out

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
