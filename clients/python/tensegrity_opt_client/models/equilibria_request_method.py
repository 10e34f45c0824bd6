from enum import StrEnum


class EquilibriaRequestMethod(StrEnum):
    HOMOTOPY = "homotopy"
    SEARCH = "search"

    def __str__(self) -> str:
        return str(self.value)
