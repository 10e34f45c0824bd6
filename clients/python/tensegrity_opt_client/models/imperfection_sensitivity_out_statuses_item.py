from enum import StrEnum


class ImperfectionSensitivityOutStatusesItem(StrEnum):
    CLOSED_LOOP = "closed_loop"
    CORRECTOR_FAILED = "corrector_failed"
    FAILED = "failed"
    FORCE_BOUND = "force_bound"
    JOINT_LIMIT = "joint_limit"
    MAX_LOAD = "max_load"
    MAX_POINTS = "max_points"
    NOT_COMPUTED = "not_computed"
    STABILITY_LOST = "stability_lost"
    STEP_TOO_SMALL = "step_too_small"
    TIME_LIMIT = "time_limit"

    def __str__(self) -> str:
        return str(self.value)
