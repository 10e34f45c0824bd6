from enum import StrEnum


class PlanOutObjective(StrEnum):
    CHANGE = "change"
    ENERGY = "energy"
    MARGIN = "margin"

    def __str__(self) -> str:
        return str(self.value)
