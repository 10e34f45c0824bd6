from enum import StrEnum


class AtlasTargetOutStatus(StrEnum):
    FAILED = "failed"
    SOLVED = "solved"
    TIME_LIMIT = "time_limit"
    UNREACHABLE = "unreachable"

    def __str__(self) -> str:
        return str(self.value)
