from enum import StrEnum


class BranchRequestStopAtType0(StrEnum):
    EVENT = "event"
    STABILITY_LOSS = "stability_loss"

    def __str__(self) -> str:
        return str(self.value)
