from enum import StrEnum


class IntervalCertificateOutControl(StrEnum):
    DISPLACEMENT = "displacement"
    FORCE = "force"

    def __str__(self) -> str:
        return str(self.value)
