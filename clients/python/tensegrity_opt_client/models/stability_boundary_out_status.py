from enum import StrEnum


class StabilityBoundaryOutStatus(StrEnum):
    ENDED = "ended"
    JOINT_LIMIT = "joint_limit"
    MAX_POINTS = "max_points"
    P_RANGE = "p_range"
    STEP_TOO_SMALL = "step_too_small"
    TIME_LIMIT = "time_limit"

    def __str__(self) -> str:
        return str(self.value)
