from enum import StrEnum


class IntervalCertificateOutStatus(StrEnum):
    NOT_PROVEN = "not_proven"
    PROVEN = "proven"
    ROOTS_PROVEN = "roots_proven"

    def __str__(self) -> str:
        return str(self.value)
