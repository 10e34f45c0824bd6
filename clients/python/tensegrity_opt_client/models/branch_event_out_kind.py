from enum import StrEnum


class BranchEventOutKind(StrEnum):
    BRANCH_POINT = "branch_point"
    FOLD = "fold"
    JOINT_LIMIT = "joint_limit"
    SPRING_SLACK = "spring_slack"
    SPRING_TAUT = "spring_taut"

    def __str__(self) -> str:
        return str(self.value)
