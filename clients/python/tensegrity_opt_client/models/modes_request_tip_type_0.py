from enum import StrEnum


class ModesRequestTipType0(StrEnum):
    HELD = "held"
    LOADED = "loaded"

    def __str__(self) -> str:
        return str(self.value)
