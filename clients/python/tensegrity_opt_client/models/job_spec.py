from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar

from attrs import define as _attrs_define

from ..models.job_spec_analysis import JobSpecAnalysis
from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.sweep_grid import SweepGrid
    from ..models.sweep_options import SweepOptions
    from ..models.sweep_point import SweepPoint
    from ..models.sweep_segmented_manipulator import SweepSegmentedManipulator
    from ..models.sweep_uniform_manipulator import SweepUniformManipulator


T = TypeVar("T", bound="JobSpec")


@_attrs_define
class JobSpec:
    """A sweep spec: one analysis over a grid or a list of points (exactly one of them).

    Attributes:
        analysis (JobSpecAnalysis): what to compute at each point
        grid (SweepGrid | Unset): ``{parameter: [values]}``: the cartesian product, in the order the keys are given
            (first slowest).
        manipulator (SweepSegmentedManipulator | SweepUniformManipulator | Unset): The base chain: `{n, a, b, k, L0}`
            (uniform; the points may vary these) or `{"segments": [...]}` (given
            segment by segment; the points vary only dx, dy, load), not both.
        options (SweepOptions | Unset): ``boundary`` for buckling and design; ``method`` for atlas; the rest are
            ``maximize_critical_force``'s
            (design only).
        points (list[SweepPoint] | Unset): explicit list of points
    """

    analysis: JobSpecAnalysis
    grid: SweepGrid | Unset = UNSET
    manipulator: SweepSegmentedManipulator | SweepUniformManipulator | Unset = UNSET
    options: SweepOptions | Unset = UNSET
    points: list[SweepPoint] | Unset = UNSET

    def to_dict(self) -> dict[str, Any]:
        from ..models.sweep_uniform_manipulator import SweepUniformManipulator  # noqa: PLC0415

        analysis = self.analysis.value

        grid: dict[str, Any] | Unset = UNSET
        if not isinstance(self.grid, Unset):
            grid = self.grid.to_dict()

        manipulator: dict[str, Any] | Unset
        if isinstance(self.manipulator, Unset):
            manipulator = UNSET
        elif isinstance(self.manipulator, SweepUniformManipulator):
            manipulator = self.manipulator.to_dict()
        else:
            manipulator = self.manipulator.to_dict()

        options: dict[str, Any] | Unset = UNSET
        if not isinstance(self.options, Unset):
            options = self.options.to_dict()

        points: list[dict[str, Any]] | Unset = UNSET
        if not isinstance(self.points, Unset):
            points = []
            for points_item_data in self.points:
                points_item = points_item_data.to_dict()
                points.append(points_item)

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "analysis": analysis,
            }
        )
        if grid is not UNSET:
            field_dict["grid"] = grid
        if manipulator is not UNSET:
            field_dict["manipulator"] = manipulator
        if options is not UNSET:
            field_dict["options"] = options
        if points is not UNSET:
            field_dict["points"] = points

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.sweep_grid import SweepGrid  # noqa: PLC0415
        from ..models.sweep_options import SweepOptions  # noqa: PLC0415
        from ..models.sweep_point import SweepPoint  # noqa: PLC0415
        from ..models.sweep_segmented_manipulator import SweepSegmentedManipulator  # noqa: PLC0415
        from ..models.sweep_uniform_manipulator import SweepUniformManipulator  # noqa: PLC0415

        d = dict(src_dict)
        analysis = JobSpecAnalysis(d.pop("analysis"))

        _grid = d.pop("grid", UNSET)
        grid: SweepGrid | Unset
        if isinstance(_grid, Unset):
            grid = UNSET
        else:
            grid = SweepGrid.from_dict(_grid)

        def _parse_manipulator(data: object) -> SweepSegmentedManipulator | SweepUniformManipulator | Unset:
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                componentsschemas_sweep_manipulator_type_0 = SweepUniformManipulator.from_dict(data)

                return componentsschemas_sweep_manipulator_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            if not isinstance(data, dict):
                raise TypeError()
            componentsschemas_sweep_manipulator_type_1 = SweepSegmentedManipulator.from_dict(data)

            return componentsschemas_sweep_manipulator_type_1

        manipulator = _parse_manipulator(d.pop("manipulator", UNSET))

        _options = d.pop("options", UNSET)
        options: SweepOptions | Unset
        if isinstance(_options, Unset):
            options = UNSET
        else:
            options = SweepOptions.from_dict(_options)

        _points = d.pop("points", UNSET)
        points: list[SweepPoint] | Unset = UNSET
        if _points is not UNSET:
            points = []
            for points_item_data in _points:
                points_item = SweepPoint.from_dict(points_item_data)

                points.append(points_item)

        job_spec = cls(
            analysis=analysis,
            grid=grid,
            manipulator=manipulator,
            options=options,
            points=points,
        )

        return job_spec
