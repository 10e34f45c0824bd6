from enum import StrEnum


class ProcessesStateState(StrEnum):
    DOWN = "down"
    RESTARTING = "restarting"
    STARTING = "starting"
    UP = "up"

    def __str__(self) -> str:
        return str(self.value)
