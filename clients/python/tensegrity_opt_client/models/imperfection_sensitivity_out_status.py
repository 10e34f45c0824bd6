from enum import StrEnum


class ImperfectionSensitivityOutStatus(StrEnum):
    COMPLETE = "complete"
    PARTIAL = "partial"
    TIME_LIMIT = "time_limit"

    def __str__(self) -> str:
        return str(self.value)
