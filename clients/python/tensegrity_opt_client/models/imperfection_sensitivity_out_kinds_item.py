from enum import StrEnum


class ImperfectionSensitivityOutKindsItem(StrEnum):
    BIFURCATION = "bifurcation"
    FOLD = "fold"
    JOINT_LIMIT = "joint_limit"
    NONE = "none"
    UNKNOWN = "unknown"

    def __str__(self) -> str:
        return str(self.value)
