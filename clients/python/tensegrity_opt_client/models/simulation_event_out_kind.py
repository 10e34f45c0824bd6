from enum import StrEnum


class SimulationEventOutKind(StrEnum):
    BIFURCATION = "bifurcation"
    JOINT_LIMIT = "joint_limit"
    SNAP = "snap"

    def __str__(self) -> str:
        return str(self.value)
