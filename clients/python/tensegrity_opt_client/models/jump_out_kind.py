from enum import StrEnum


class JumpOutKind(StrEnum):
    BRANCH_SWITCH = "branch_switch"
    BUCKLING = "buckling"

    def __str__(self) -> str:
        return str(self.value)
