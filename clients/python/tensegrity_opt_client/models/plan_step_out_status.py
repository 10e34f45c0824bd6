from enum import StrEnum


class PlanStepOutStatus(StrEnum):
    FEASIBLE = "feasible"
    INFEASIBLE = "infeasible"

    def __str__(self) -> str:
        return str(self.value)
