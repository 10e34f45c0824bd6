from enum import StrEnum


class WeightCapacityOutKind(StrEnum):
    BIFURCATION = "bifurcation"
    FOLD = "fold"
    NONE = "none"

    def __str__(self) -> str:
        return str(self.value)
