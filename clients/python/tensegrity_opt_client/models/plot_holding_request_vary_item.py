from enum import StrEnum


class PlotHoldingRequestVaryItem(StrEnum):
    K = "k"
    L0 = "L0"

    def __str__(self) -> str:
        return str(self.value)
