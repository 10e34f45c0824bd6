from enum import StrEnum


class PlanOutMethodItem(StrEnum):
    IPOPT = "ipopt"
    NEWTON = "newton"
    NONE = "none"

    def __str__(self) -> str:
        return str(self.value)
