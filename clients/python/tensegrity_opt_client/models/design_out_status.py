from enum import StrEnum


class DesignOutStatus(StrEnum):
    BELOW_REQUIRED = "below_required"
    INFEASIBLE = "infeasible"
    OPTIMAL = "optimal"

    def __str__(self) -> str:
        return str(self.value)
