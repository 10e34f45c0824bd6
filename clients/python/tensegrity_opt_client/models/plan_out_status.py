from enum import StrEnum


class PlanOutStatus(StrEnum):
    COMPLETE = "complete"
    INFEASIBLE_STEPS = "infeasible_steps"
    TIME_LIMIT = "time_limit"

    def __str__(self) -> str:
        return str(self.value)
