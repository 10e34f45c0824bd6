from enum import StrEnum


class EquilibriaOutStatus(StrEnum):
    CERTIFIED = "certified"
    EXACT = "exact"
    SEARCHED = "searched"
    UNCERTIFIED = "uncertified"

    def __str__(self) -> str:
        return str(self.value)
