from enum import StrEnum


class DesignCriticalForceRequestBoundary(StrEnum):
    FREE = "free"
    GUIDED = "guided"

    def __str__(self) -> str:
        return str(self.value)
