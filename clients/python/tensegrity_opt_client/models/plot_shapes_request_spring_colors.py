from enum import StrEnum


class PlotShapesRequestSpringColors(StrEnum):
    STATE = "state"
    TENSION = "tension"

    def __str__(self) -> str:
        return str(self.value)
