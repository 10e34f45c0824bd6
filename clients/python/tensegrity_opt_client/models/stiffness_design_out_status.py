from enum import StrEnum


class StiffnessDesignOutStatus(StrEnum):
    CLOSEST = "closest"
    EXACT = "exact"
    WITHIN_BOUNDS = "within_bounds"

    def __str__(self) -> str:
        return str(self.value)
