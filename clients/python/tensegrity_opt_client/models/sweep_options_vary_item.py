from enum import StrEnum


class SweepOptionsVaryItem(StrEnum):
    A = "a"
    B = "b"
    K = "k"
    L0 = "L0"

    def __str__(self) -> str:
        return str(self.value)
