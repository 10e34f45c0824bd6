from enum import StrEnum


class ModesOutStatus(StrEnum):
    DEGENERATE = "degenerate"
    SOLVED = "solved"
    UNSTABLE = "unstable"

    def __str__(self) -> str:
        return str(self.value)
