from enum import StrEnum


class AtlasCrossingOutKind(StrEnum):
    BRANCH_END = "branch_end"
    SWITCH = "switch"

    def __str__(self) -> str:
        return str(self.value)
