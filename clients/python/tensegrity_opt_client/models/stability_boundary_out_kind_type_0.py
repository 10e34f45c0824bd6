from enum import StrEnum


class StabilityBoundaryOutKindType0(StrEnum):
    BRANCH_POINT = "branch_point"
    FOLD = "fold"

    def __str__(self) -> str:
        return str(self.value)
