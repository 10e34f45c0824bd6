from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar

from attrs import define as _attrs_define

T = TypeVar("T", bound="AtlasRange")


@_attrs_define
class AtlasRange:
    """`num` evenly spaced deflections from `start` to `stop` inclusive (`start < stop` unless `num` is 1).

    Attributes:
        num (int): number of values (1..400; the grid's targets, num_dx x num_dy, at most the server's
            TENSEGRITY_MAX_ATLAS_TARGETS)
        start (float):
        stop (float):
    """

    num: int
    start: float
    stop: float

    def to_dict(self) -> dict[str, Any]:
        num = self.num

        start = self.start

        stop = self.stop

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "num": num,
                "start": start,
                "stop": stop,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        num = d.pop("num")

        start = d.pop("start")

        stop = d.pop("stop")

        atlas_range = cls(
            num=num,
            start=start,
            stop=stop,
        )

        return atlas_range
