from enum import StrEnum


class ControlOutTipType0(StrEnum):
    FREE = "free"
    HELD = "held"

    def __str__(self) -> str:
        return str(self.value)
