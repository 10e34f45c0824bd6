from enum import StrEnum


class JumpOutKind(StrEnum):
    BUCKLING = "buckling"
    LEAVE_STRAIGHT = "leave_straight"
    SNAP = "snap"
    SWITCH = "switch"

    def __str__(self) -> str:
        return str(self.value)
