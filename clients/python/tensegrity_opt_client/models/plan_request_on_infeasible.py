from enum import StrEnum


class PlanRequestOnInfeasible(StrEnum):
    APPROACH = "approach"
    HOLD = "hold"

    def __str__(self) -> str:
        return str(self.value)
