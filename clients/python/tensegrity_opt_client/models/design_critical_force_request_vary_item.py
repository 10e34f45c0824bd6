from enum import StrEnum


class DesignCriticalForceRequestVaryItem(StrEnum):
    A = "a"
    B = "b"
    K = "k"
    L0 = "L0"

    def __str__(self) -> str:
        return str(self.value)
