from enum import StrEnum


class ImperfectionSensitivityOutBoundary(StrEnum):
    FREE = "free"
    GUIDED = "guided"

    def __str__(self) -> str:
        return str(self.value)
