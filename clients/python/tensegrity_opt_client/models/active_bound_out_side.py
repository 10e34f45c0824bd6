from enum import StrEnum


class ActiveBoundOutSide(StrEnum):
    LOWER = "lower"
    UPPER = "upper"

    def __str__(self) -> str:
        return str(self.value)
