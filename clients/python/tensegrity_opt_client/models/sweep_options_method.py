from enum import StrEnum


class SweepOptionsMethod(StrEnum):
    HOMOTOPY = "homotopy"
    SEARCH = "search"

    def __str__(self) -> str:
        return str(self.value)
