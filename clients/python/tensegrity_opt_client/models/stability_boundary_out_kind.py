from enum import StrEnum


class StabilityBoundaryOutKind(StrEnum):
    BRANCH_POINT = "branch_point"
    FOLD = "fold"

    def __str__(self) -> str:
        return str(self.value)
