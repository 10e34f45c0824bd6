from enum import StrEnum


class HoldingRequestVaryItem(StrEnum):
    K = "k"
    L0 = "L0"

    def __str__(self) -> str:
        return str(self.value)
