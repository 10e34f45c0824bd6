from enum import StrEnum


class HoldingOutStatus(StrEnum):
    METASTABLE = "metastable"
    OPTIMAL = "optimal"

    def __str__(self) -> str:
        return str(self.value)
