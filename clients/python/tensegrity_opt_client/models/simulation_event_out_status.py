from enum import StrEnum


class SimulationEventOutStatus(StrEnum):
    JOINT_LIMIT = "joint_limit"
    LANDED = "landed"

    def __str__(self) -> str:
        return str(self.value)
