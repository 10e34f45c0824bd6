from enum import StrEnum


class EquilibriumOutStatus(StrEnum):
    CERTIFIED = "certified"
    CONVERGED = "converged"
    EXACT = "exact"

    def __str__(self) -> str:
        return str(self.value)
