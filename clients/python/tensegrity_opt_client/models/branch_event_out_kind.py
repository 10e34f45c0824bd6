from enum import StrEnum


class BranchEventOutKind(StrEnum):
    BRANCH_POINT = "branch_point"
    FOLD = "fold"
    JOINT_LIMIT = "joint_limit"

    def __str__(self) -> str:
        return str(self.value)
