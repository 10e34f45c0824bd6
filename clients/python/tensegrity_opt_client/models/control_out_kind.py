from enum import StrEnum


class ControlOutKind(StrEnum):
    DISPLACEMENT = "displacement"
    GUIDED = "guided"
    LOAD = "load"
    PRELOAD = "preload"
    WALL = "wall"

    def __str__(self) -> str:
        return str(self.value)
