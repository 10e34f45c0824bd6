from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.atlas_crossing_out_kind import AtlasCrossingOutKind

T = TypeVar("T", bound="AtlasCrossingOut")


@_attrs_define
class AtlasCrossingOut:
    """A point on a grid edge where the least-energy branch switches or a stable branch ends.

    Attributes:
        dx (float):
        dy (float):
        edge (list[list[int]]): grid indices [[i, j], [i, j]] (dx index, dy index) of the edge's ends (the same twice: a
            tie at a target)
        energy (float):
        event (str): branch_end: fold, branch_point or joint_limit; switch: maxwell
        force (list[float]): the tip force there [fx, fy]
        force_other (list[float] | None):
        fraction (float): position along the edge from its first end (0) to its second (1)
        kind (AtlasCrossingOutKind): switch (the least-energy branch changes: the Maxwell point of the held tip) or
            branch_end (a stable branch loses stability: the arm snaps)
        method (str): moore_spence / test_function / limit (the event's), equal_energy, branch_end or tie
        null_vector (list[float] | None): the mode of a fold or branch point
        q (list[float]): the configuration there (rad)
        q_other (list[float] | None): switch: the equilibrium on the other side (same energy)
    """

    dx: float
    dy: float
    edge: list[list[int]]
    energy: float
    event: str
    force: list[float]
    force_other: list[float] | None
    fraction: float
    kind: AtlasCrossingOutKind
    method: str
    null_vector: list[float] | None
    q: list[float]
    q_other: list[float] | None
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        dx = self.dx

        dy = self.dy

        edge = []
        for edge_item_data in self.edge:
            edge_item = edge_item_data

            edge.append(edge_item)

        energy = self.energy

        event = self.event

        force = self.force

        force_other: list[float] | None
        if isinstance(self.force_other, list):
            force_other = self.force_other

        else:
            force_other = self.force_other

        fraction = self.fraction

        kind = self.kind.value

        method = self.method

        null_vector: list[float] | None
        if isinstance(self.null_vector, list):
            null_vector = self.null_vector

        else:
            null_vector = self.null_vector

        q = self.q

        q_other: list[float] | None
        if isinstance(self.q_other, list):
            q_other = self.q_other

        else:
            q_other = self.q_other

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "dx": dx,
                "dy": dy,
                "edge": edge,
                "energy": energy,
                "event": event,
                "force": force,
                "force_other": force_other,
                "fraction": fraction,
                "kind": kind,
                "method": method,
                "null_vector": null_vector,
                "q": q,
                "q_other": q_other,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        dx = d.pop("dx")

        dy = d.pop("dy")

        edge = []
        _edge = d.pop("edge")
        for edge_item_data in _edge:
            edge_item = cast(list[int], edge_item_data)

            edge.append(edge_item)

        energy = d.pop("energy")

        event = d.pop("event")

        force = cast(list[float], d.pop("force"))

        def _parse_force_other(data: object) -> list[float] | None:
            if data is None:
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                force_other_type_0 = cast(list[float], data)

                return force_other_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float] | None, data)

        force_other = _parse_force_other(d.pop("force_other"))

        fraction = d.pop("fraction")

        kind = AtlasCrossingOutKind(d.pop("kind"))

        method = d.pop("method")

        def _parse_null_vector(data: object) -> list[float] | None:
            if data is None:
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                null_vector_type_0 = cast(list[float], data)

                return null_vector_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float] | None, data)

        null_vector = _parse_null_vector(d.pop("null_vector"))

        q = cast(list[float], d.pop("q"))

        def _parse_q_other(data: object) -> list[float] | None:
            if data is None:
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                q_other_type_0 = cast(list[float], data)

                return q_other_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float] | None, data)

        q_other = _parse_q_other(d.pop("q_other"))

        atlas_crossing_out = cls(
            dx=dx,
            dy=dy,
            edge=edge,
            energy=energy,
            event=event,
            force=force,
            force_other=force_other,
            fraction=fraction,
            kind=kind,
            method=method,
            null_vector=null_vector,
            q=q,
            q_other=q_other,
        )

        atlas_crossing_out.additional_properties = d
        return atlas_crossing_out

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
