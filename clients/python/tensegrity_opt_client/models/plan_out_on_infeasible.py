from enum import StrEnum


class PlanOutOnInfeasible(StrEnum):
    APPROACH = "approach"
    HOLD = "hold"

    def __str__(self) -> str:
        return str(self.value)
