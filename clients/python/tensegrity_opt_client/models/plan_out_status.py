from enum import StrEnum


class PlanOutStatus(StrEnum):
    COMPLETE = "complete"
    INFEASIBLE_STEPS = "infeasible_steps"
    NO_EQUILIBRIUM = "no_equilibrium"
    SNAPPED = "snapped"
    TIME_LIMIT = "time_limit"

    def __str__(self) -> str:
        return str(self.value)
