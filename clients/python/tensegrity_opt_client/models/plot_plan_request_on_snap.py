from enum import StrEnum


class PlotPlanRequestOnSnap(StrEnum):
    CONTINUE = "continue"
    STOP = "stop"

    def __str__(self) -> str:
        return str(self.value)
