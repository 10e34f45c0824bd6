from enum import StrEnum


class LimitLoadOutBranchStatus(StrEnum):
    CLOSED_LOOP = "closed_loop"
    CORRECTOR_FAILED = "corrector_failed"
    EVENT = "event"
    FORCE_BOUND = "force_bound"
    JOINT_LIMIT = "joint_limit"
    MAX_POINTS = "max_points"
    STABILITY_LOSS = "stability_loss"
    STEP_TOO_SMALL = "step_too_small"
    TIME_LIMIT = "time_limit"
    T_MAX = "t_max"
    T_MIN = "t_min"
    WORKSPACE_BOUNDARY = "workspace_boundary"

    def __str__(self) -> str:
        return str(self.value)
