from enum import StrEnum


class LoadCapacityOutStatus(StrEnum):
    COMPLETE = "complete"
    PATH_FAILED = "path_failed"
    TIME_LIMIT = "time_limit"

    def __str__(self) -> str:
        return str(self.value)
