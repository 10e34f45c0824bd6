from enum import StrEnum


class CertificateOutStatus(StrEnum):
    CERTIFIED = "certified"
    OPEN = "open"

    def __str__(self) -> str:
        return str(self.value)
