from enum import StrEnum


class CurvePointStatus(StrEnum):
    ABSENT = "absent"
    CONVERGED = "converged"
    STRAIGHT = "straight"
    STRAIGHT_NOT_EQUILIBRIUM = "straight_not_equilibrium"

    def __str__(self) -> str:
        return str(self.value)
