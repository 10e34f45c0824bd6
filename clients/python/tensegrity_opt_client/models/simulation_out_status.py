from enum import StrEnum


class SimulationOutStatus(StrEnum):
    COMPLETE = "complete"
    FAILED = "failed"
    FORCE_BOUND = "force_bound"
    JOINT_LIMIT = "joint_limit"
    TIME_LIMIT = "time_limit"
    WORKSPACE_BOUNDARY = "workspace_boundary"

    def __str__(self) -> str:
        return str(self.value)
