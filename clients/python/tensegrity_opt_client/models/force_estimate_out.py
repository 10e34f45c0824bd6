from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.force_estimate_out_spring_states_type_0_item_item import ForceEstimateOutSpringStatesType0ItemItem
from ..models.force_estimate_out_status import ForceEstimateOutStatus

if TYPE_CHECKING:
    from ..models.force import Force


T = TypeVar("T", bound="ForceEstimateOut")


@_attrs_define
class ForceEstimateOut:
    """`ForceEstimate.to_dict()`.

    Attributes:
        chi2 (float | None): r^T W r (null without sigma_q)
        covariance (list[list[float]] | None): 2 x 2 covariance of the force (null without sigma_q)
        dof (int): degrees of freedom: n - 2 - unmeasured joints
        force (Force):
        hidden_covariance (list[list[float]] | None): covariance of the estimated unmeasured angles (rad^2)
        iterations (int): Gauss-Newton and re-weighting iterations made
        joint_chi2 (list[float] | None): per joint: the decrease of chi2 an extra torque there would give (where the
            load not at the tip is)
        measured (list[int]): the measured joints (0-based)
        message (str): what happened, in a sentence
        p_value (float | None): P(chi2_dof >= chi2): small when the angles are not those of an equilibrium under a tip
            force only (null without sigma_q or dof 0)
        q (list[float]): the configuration used: measured angles as given, unmeasured estimated
        residual_norm (float):
        residual_torque (list[float]): grad E - J^T F at the estimate: the joint torques no tip force explains (torque
            units)
        spring_forces (list[list[float]] | None): each spring's force, tension positive: k (L - L0) (linear law), k
            max(0, L - L0) (tension-only)
        spring_lengths (list[list[float]] | None): each spring's length L (length units), [spring 1, spring 2] per
            segment
        spring_states (list[list[ForceEstimateOutSpringStatesType0ItemItem]] | None): `taut` (L >= L0), `slack`
            (tension-only, L < L0: no force) or `pushing` (linear law, L < L0: a compressive force a real tension spring
            cannot carry)
        spring_stretches (list[list[float]] | None): L - L0 per spring (negative: shorter than its rest length)
        status (ForceEstimateOutStatus): `least_squares`: every joint measured, no noise model: the least-squares force
            (eq. 8); `gauss_newton`: unmeasured joints, no noise model: the force and the unmeasured angles by Gauss-Newton;
            `generalized_least_squares`: every joint measured, with sigma_q: generalised least squares with the residual's
            covariance at the estimate; `weighted_gauss_newton`: unmeasured joints, with sigma_q: the re-weighted Gauss-
            Newton estimate; `reweighting_not_converged`: the re-weighting did not settle (angles far from any equilibrium
            under a tip force): the one-step estimate
        success (bool): whether it worked: `status` is one of gauss_newton, generalized_least_squares, least_squares,
            weighted_gauss_newton
    """

    chi2: float | None
    covariance: list[list[float]] | None
    dof: int
    force: Force
    hidden_covariance: list[list[float]] | None
    iterations: int
    joint_chi2: list[float] | None
    measured: list[int]
    message: str
    p_value: float | None
    q: list[float]
    residual_norm: float
    residual_torque: list[float]
    spring_forces: list[list[float]] | None
    spring_lengths: list[list[float]] | None
    spring_states: list[list[ForceEstimateOutSpringStatesType0ItemItem]] | None
    spring_stretches: list[list[float]] | None
    status: ForceEstimateOutStatus
    success: bool
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        chi2: float | None
        chi2 = self.chi2

        covariance: list[list[float]] | None
        if isinstance(self.covariance, list):
            covariance = []
            for covariance_type_0_item_data in self.covariance:
                covariance_type_0_item = covariance_type_0_item_data

                covariance.append(covariance_type_0_item)

        else:
            covariance = self.covariance

        dof = self.dof

        force = self.force.to_dict()

        hidden_covariance: list[list[float]] | None
        if isinstance(self.hidden_covariance, list):
            hidden_covariance = []
            for hidden_covariance_type_0_item_data in self.hidden_covariance:
                hidden_covariance_type_0_item = hidden_covariance_type_0_item_data

                hidden_covariance.append(hidden_covariance_type_0_item)

        else:
            hidden_covariance = self.hidden_covariance

        iterations = self.iterations

        joint_chi2: list[float] | None
        if isinstance(self.joint_chi2, list):
            joint_chi2 = self.joint_chi2

        else:
            joint_chi2 = self.joint_chi2

        measured = self.measured

        message = self.message

        p_value: float | None
        p_value = self.p_value

        q = self.q

        residual_norm = self.residual_norm

        residual_torque = self.residual_torque

        spring_forces: list[list[float]] | None
        if isinstance(self.spring_forces, list):
            spring_forces = []
            for spring_forces_type_0_item_data in self.spring_forces:
                spring_forces_type_0_item = spring_forces_type_0_item_data

                spring_forces.append(spring_forces_type_0_item)

        else:
            spring_forces = self.spring_forces

        spring_lengths: list[list[float]] | None
        if isinstance(self.spring_lengths, list):
            spring_lengths = []
            for spring_lengths_type_0_item_data in self.spring_lengths:
                spring_lengths_type_0_item = spring_lengths_type_0_item_data

                spring_lengths.append(spring_lengths_type_0_item)

        else:
            spring_lengths = self.spring_lengths

        spring_states: list[list[str]] | None
        if isinstance(self.spring_states, list):
            spring_states = []
            for spring_states_type_0_item_data in self.spring_states:
                spring_states_type_0_item = []
                for spring_states_type_0_item_item_data in spring_states_type_0_item_data:
                    spring_states_type_0_item_item = spring_states_type_0_item_item_data.value
                    spring_states_type_0_item.append(spring_states_type_0_item_item)

                spring_states.append(spring_states_type_0_item)

        else:
            spring_states = self.spring_states

        spring_stretches: list[list[float]] | None
        if isinstance(self.spring_stretches, list):
            spring_stretches = []
            for spring_stretches_type_0_item_data in self.spring_stretches:
                spring_stretches_type_0_item = spring_stretches_type_0_item_data

                spring_stretches.append(spring_stretches_type_0_item)

        else:
            spring_stretches = self.spring_stretches

        status = self.status.value

        success = self.success

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "chi2": chi2,
                "covariance": covariance,
                "dof": dof,
                "force": force,
                "hidden_covariance": hidden_covariance,
                "iterations": iterations,
                "joint_chi2": joint_chi2,
                "measured": measured,
                "message": message,
                "p_value": p_value,
                "q": q,
                "residual_norm": residual_norm,
                "residual_torque": residual_torque,
                "spring_forces": spring_forces,
                "spring_lengths": spring_lengths,
                "spring_states": spring_states,
                "spring_stretches": spring_stretches,
                "status": status,
                "success": success,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.force import Force  # noqa: PLC0415

        d = dict(src_dict)

        def _parse_chi2(data: object) -> float | None:
            if data is None:
                return data
            return cast(float | None, data)

        chi2 = _parse_chi2(d.pop("chi2"))

        def _parse_covariance(data: object) -> list[list[float]] | None:
            if data is None:
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                covariance_type_0 = []
                _covariance_type_0 = data
                for covariance_type_0_item_data in _covariance_type_0:
                    covariance_type_0_item = cast(list[float], covariance_type_0_item_data)

                    covariance_type_0.append(covariance_type_0_item)

                return covariance_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[list[float]] | None, data)

        covariance = _parse_covariance(d.pop("covariance"))

        dof = d.pop("dof")

        force = Force.from_dict(d.pop("force"))

        def _parse_hidden_covariance(data: object) -> list[list[float]] | None:
            if data is None:
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                hidden_covariance_type_0 = []
                _hidden_covariance_type_0 = data
                for hidden_covariance_type_0_item_data in _hidden_covariance_type_0:
                    hidden_covariance_type_0_item = cast(list[float], hidden_covariance_type_0_item_data)

                    hidden_covariance_type_0.append(hidden_covariance_type_0_item)

                return hidden_covariance_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[list[float]] | None, data)

        hidden_covariance = _parse_hidden_covariance(d.pop("hidden_covariance"))

        iterations = d.pop("iterations")

        def _parse_joint_chi2(data: object) -> list[float] | None:
            if data is None:
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                joint_chi2_type_0 = cast(list[float], data)

                return joint_chi2_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float] | None, data)

        joint_chi2 = _parse_joint_chi2(d.pop("joint_chi2"))

        measured = cast(list[int], d.pop("measured"))

        message = d.pop("message")

        def _parse_p_value(data: object) -> float | None:
            if data is None:
                return data
            return cast(float | None, data)

        p_value = _parse_p_value(d.pop("p_value"))

        q = cast(list[float], d.pop("q"))

        residual_norm = d.pop("residual_norm")

        residual_torque = cast(list[float], d.pop("residual_torque"))

        def _parse_spring_forces(data: object) -> list[list[float]] | None:
            if data is None:
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                spring_forces_type_0 = []
                _spring_forces_type_0 = data
                for spring_forces_type_0_item_data in _spring_forces_type_0:
                    spring_forces_type_0_item = cast(list[float], spring_forces_type_0_item_data)

                    spring_forces_type_0.append(spring_forces_type_0_item)

                return spring_forces_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[list[float]] | None, data)

        spring_forces = _parse_spring_forces(d.pop("spring_forces"))

        def _parse_spring_lengths(data: object) -> list[list[float]] | None:
            if data is None:
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                spring_lengths_type_0 = []
                _spring_lengths_type_0 = data
                for spring_lengths_type_0_item_data in _spring_lengths_type_0:
                    spring_lengths_type_0_item = cast(list[float], spring_lengths_type_0_item_data)

                    spring_lengths_type_0.append(spring_lengths_type_0_item)

                return spring_lengths_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[list[float]] | None, data)

        spring_lengths = _parse_spring_lengths(d.pop("spring_lengths"))

        def _parse_spring_states(data: object) -> list[list[ForceEstimateOutSpringStatesType0ItemItem]] | None:
            if data is None:
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                spring_states_type_0 = []
                _spring_states_type_0 = data
                for spring_states_type_0_item_data in _spring_states_type_0:
                    spring_states_type_0_item = []
                    _spring_states_type_0_item = spring_states_type_0_item_data
                    for spring_states_type_0_item_item_data in _spring_states_type_0_item:
                        spring_states_type_0_item_item = ForceEstimateOutSpringStatesType0ItemItem(
                            spring_states_type_0_item_item_data
                        )

                        spring_states_type_0_item.append(spring_states_type_0_item_item)

                    spring_states_type_0.append(spring_states_type_0_item)

                return spring_states_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[list[ForceEstimateOutSpringStatesType0ItemItem]] | None, data)

        spring_states = _parse_spring_states(d.pop("spring_states"))

        def _parse_spring_stretches(data: object) -> list[list[float]] | None:
            if data is None:
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                spring_stretches_type_0 = []
                _spring_stretches_type_0 = data
                for spring_stretches_type_0_item_data in _spring_stretches_type_0:
                    spring_stretches_type_0_item = cast(list[float], spring_stretches_type_0_item_data)

                    spring_stretches_type_0.append(spring_stretches_type_0_item)

                return spring_stretches_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[list[float]] | None, data)

        spring_stretches = _parse_spring_stretches(d.pop("spring_stretches"))

        status = ForceEstimateOutStatus(d.pop("status"))

        success = d.pop("success")

        force_estimate_out = cls(
            chi2=chi2,
            covariance=covariance,
            dof=dof,
            force=force,
            hidden_covariance=hidden_covariance,
            iterations=iterations,
            joint_chi2=joint_chi2,
            measured=measured,
            message=message,
            p_value=p_value,
            q=q,
            residual_norm=residual_norm,
            residual_torque=residual_torque,
            spring_forces=spring_forces,
            spring_lengths=spring_lengths,
            spring_states=spring_states,
            spring_stretches=spring_stretches,
            status=status,
            success=success,
        )

        force_estimate_out.additional_properties = d
        return force_estimate_out

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
