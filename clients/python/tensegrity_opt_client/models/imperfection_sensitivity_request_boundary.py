from enum import StrEnum


class ImperfectionSensitivityRequestBoundary(StrEnum):
    FREE = "free"
    GUIDED = "guided"

    def __str__(self) -> str:
        return str(self.value)
