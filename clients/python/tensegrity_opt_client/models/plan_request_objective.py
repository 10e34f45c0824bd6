from enum import StrEnum


class PlanRequestObjective(StrEnum):
    CHANGE = "change"
    ENERGY = "energy"
    MARGIN = "margin"

    def __str__(self) -> str:
        return str(self.value)
