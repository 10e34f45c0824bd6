from enum import StrEnum


class ForceDeflectionRequestReference(StrEnum):
    REST = "rest"
    STRAIGHT = "straight"

    def __str__(self) -> str:
        return str(self.value)
