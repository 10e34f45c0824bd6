from enum import StrEnum


class PlotModesRequestTipType0(StrEnum):
    HELD = "held"
    LOADED = "loaded"

    def __str__(self) -> str:
        return str(self.value)
