from enum import StrEnum


class ForceDeflectionOutReference(StrEnum):
    REST = "rest"
    STRAIGHT = "straight"

    def __str__(self) -> str:
        return str(self.value)
