from enum import StrEnum


class PreloadsRequestObjective(StrEnum):
    ENERGY = "energy"
    MARGIN = "margin"
    NOMINAL = "nominal"

    def __str__(self) -> str:
        return str(self.value)
