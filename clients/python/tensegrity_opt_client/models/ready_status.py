from enum import StrEnum


class ReadyStatus(StrEnum):
    DEGRADED = "degraded"
    READY = "ready"
    STARTING = "starting"

    def __str__(self) -> str:
        return str(self.value)
