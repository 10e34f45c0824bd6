from enum import StrEnum


class BranchEventOutStability(StrEnum):
    GAINED = "gained"
    LOST = "lost"
    UNCHANGED = "unchanged"

    def __str__(self) -> str:
        return str(self.value)
