from enum import StrEnum


class EquilibriumOutKind(StrEnum):
    DEGENERATE = "degenerate"
    MAXIMUM = "maximum"
    MINIMUM = "minimum"
    SADDLE = "saddle"

    def __str__(self) -> str:
        return str(self.value)
