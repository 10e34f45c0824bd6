from enum import StrEnum


class EnergyBoundOutStatus(StrEnum):
    CERTIFIED = "certified"
    OPEN = "open"

    def __str__(self) -> str:
        return str(self.value)
