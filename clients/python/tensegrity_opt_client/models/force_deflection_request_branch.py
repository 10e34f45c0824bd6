from enum import StrEnum


class ForceDeflectionRequestBranch(StrEnum):
    ALL = "all"
    STABLE = "stable"

    def __str__(self) -> str:
        return str(self.value)
