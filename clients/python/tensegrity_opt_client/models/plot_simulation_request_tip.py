from enum import StrEnum


class PlotSimulationRequestTip(StrEnum):
    FREE = "free"
    HELD = "held"

    def __str__(self) -> str:
        return str(self.value)
