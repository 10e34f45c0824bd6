from enum import StrEnum


class PlanStepOutStatus(StrEnum):
    FEASIBLE = "feasible"
    INFEASIBLE = "infeasible"
    NO_EQUILIBRIUM = "no_equilibrium"
    SNAP = "snap"

    def __str__(self) -> str:
        return str(self.value)
