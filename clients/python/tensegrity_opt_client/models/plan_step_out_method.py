from enum import StrEnum


class PlanStepOutMethod(StrEnum):
    HORIZON = "horizon"
    IPOPT = "ipopt"
    NEAREST = "nearest"
    NEWTON = "newton"
    NONE = "none"

    def __str__(self) -> str:
        return str(self.value)
