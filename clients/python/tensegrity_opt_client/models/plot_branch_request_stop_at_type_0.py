from enum import StrEnum


class PlotBranchRequestStopAtType0(StrEnum):
    EVENT = "event"
    STABILITY_LOSS = "stability_loss"

    def __str__(self) -> str:
        return str(self.value)
