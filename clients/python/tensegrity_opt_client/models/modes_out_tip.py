from enum import StrEnum


class ModesOutTip(StrEnum):
    HELD = "held"
    LOADED = "loaded"

    def __str__(self) -> str:
        return str(self.value)
