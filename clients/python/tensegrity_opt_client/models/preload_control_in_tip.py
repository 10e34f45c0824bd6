from enum import StrEnum


class PreloadControlInTip(StrEnum):
    FREE = "free"
    HELD = "held"

    def __str__(self) -> str:
        return str(self.value)
