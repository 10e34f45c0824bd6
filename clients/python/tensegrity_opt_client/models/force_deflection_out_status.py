from enum import StrEnum


class ForceDeflectionOutStatus(StrEnum):
    COMPLETE = "complete"
    NO_STABLE_EQUILIBRIUM = "no_stable_equilibrium"

    def __str__(self) -> str:
        return str(self.value)
