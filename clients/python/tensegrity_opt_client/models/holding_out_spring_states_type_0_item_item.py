from enum import StrEnum


class HoldingOutSpringStatesType0ItemItem(StrEnum):
    PUSHING = "pushing"
    SLACK = "slack"
    TAUT = "taut"

    def __str__(self) -> str:
        return str(self.value)
