from enum import StrEnum


class ImperfectionSensitivityOutImperfection(StrEnum):
    A = "a"
    ASYMMETRY = "asymmetry"
    B = "b"
    K = "k"
    L0 = "L0"

    def __str__(self) -> str:
        return str(self.value)
