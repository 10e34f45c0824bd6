from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.interval_certificate_out_control import IntervalCertificateOutControl
from ..models.interval_certificate_out_status import IntervalCertificateOutStatus

if TYPE_CHECKING:
    from ..models.root_box_out import RootBoxOut


T = TypeVar("T", bound="IntervalCertificateOut")


@_attrs_define
class IntervalCertificateOut:
    """The interval (ball-arithmetic) proofs of a homotopy's equilibria
    (`tensegrity_opt.results.IntervalCertificate`).

        Attributes:
            boxes (list[RootBoxOut]): one per equilibrium, in the order of `equilibria`
            control (IntervalCertificateOutControl): the unknowns proven: (q, Fx, Fy) or q
            message (str): what happened, in a sentence
            method (str): `krawczyk (arb)`: Krawczyk's test in Arb's ball arithmetic (python-flint)
            morse_proven (bool): every Morse index proven
            nonreal_checked (int): homotopy roots classed non-real but near the real set (within 0.1)
            nonreal_proven (int): of those, proven non-real (complex Krawczyk, a box off the real set)
            outside_checked (int): homotopy real roots just beyond the joint range (by less than 0.1 rad)
            outside_proven (int): of those, proven beyond it (Krawczyk, a box beyond a joint limit)
            paths (int): homotopy paths behind the equilibria
            roots_proven (bool): every equilibrium proven (unique in its box, real, in range, disjoint)
            seconds (float): wall time of the proofs (s)
            status (IntervalCertificateOutStatus): `proven`: every equilibrium proven by Krawczyk's test in ball arithmetic
                (exactly one real equilibrium in its box, the box inside the joint range, the boxes pairwise disjoint) and every
                Morse index proven over its box; `roots_proven`: every equilibrium proven as for 'proven'; the Morse index of
                some (near-degenerate) is floating-point; `not_proven`: some equilibrium was not proven (singular, ill-
                conditioned, against the range limit, or its box meets another): the boxes say which
            success (bool): whether it worked: `status` is one of proven, roots_proven
    """

    boxes: list[RootBoxOut]
    control: IntervalCertificateOutControl
    message: str
    method: str
    morse_proven: bool
    nonreal_checked: int
    nonreal_proven: int
    outside_checked: int
    outside_proven: int
    paths: int
    roots_proven: bool
    seconds: float
    status: IntervalCertificateOutStatus
    success: bool
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        boxes = []
        for boxes_item_data in self.boxes:
            boxes_item = boxes_item_data.to_dict()
            boxes.append(boxes_item)

        control = self.control.value

        message = self.message

        method = self.method

        morse_proven = self.morse_proven

        nonreal_checked = self.nonreal_checked

        nonreal_proven = self.nonreal_proven

        outside_checked = self.outside_checked

        outside_proven = self.outside_proven

        paths = self.paths

        roots_proven = self.roots_proven

        seconds = self.seconds

        status = self.status.value

        success = self.success

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "boxes": boxes,
                "control": control,
                "message": message,
                "method": method,
                "morse_proven": morse_proven,
                "nonreal_checked": nonreal_checked,
                "nonreal_proven": nonreal_proven,
                "outside_checked": outside_checked,
                "outside_proven": outside_proven,
                "paths": paths,
                "roots_proven": roots_proven,
                "seconds": seconds,
                "status": status,
                "success": success,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.root_box_out import RootBoxOut  # noqa: PLC0415

        d = dict(src_dict)
        boxes = []
        _boxes = d.pop("boxes")
        for boxes_item_data in _boxes:
            boxes_item = RootBoxOut.from_dict(boxes_item_data)

            boxes.append(boxes_item)

        control = IntervalCertificateOutControl(d.pop("control"))

        message = d.pop("message")

        method = d.pop("method")

        morse_proven = d.pop("morse_proven")

        nonreal_checked = d.pop("nonreal_checked")

        nonreal_proven = d.pop("nonreal_proven")

        outside_checked = d.pop("outside_checked")

        outside_proven = d.pop("outside_proven")

        paths = d.pop("paths")

        roots_proven = d.pop("roots_proven")

        seconds = d.pop("seconds")

        status = IntervalCertificateOutStatus(d.pop("status"))

        success = d.pop("success")

        interval_certificate_out = cls(
            boxes=boxes,
            control=control,
            message=message,
            method=method,
            morse_proven=morse_proven,
            nonreal_checked=nonreal_checked,
            nonreal_proven=nonreal_proven,
            outside_checked=outside_checked,
            outside_proven=outside_proven,
            paths=paths,
            roots_proven=roots_proven,
            seconds=seconds,
            status=status,
            success=success,
        )

        interval_certificate_out.additional_properties = d
        return interval_certificate_out

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
