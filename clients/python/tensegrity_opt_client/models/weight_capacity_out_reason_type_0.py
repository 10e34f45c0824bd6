from enum import StrEnum


class WeightCapacityOutReasonType0(StrEnum):
    JOINT_LIMIT = "joint_limit"
    MAX_FACTOR = "max_factor"

    def __str__(self) -> str:
        return str(self.value)
