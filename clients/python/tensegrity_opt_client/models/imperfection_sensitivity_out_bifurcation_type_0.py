from enum import StrEnum


class ImperfectionSensitivityOutBifurcationType0(StrEnum):
    ASYMMETRIC = "asymmetric"
    STABLE_SYMMETRIC = "stable_symmetric"
    UNSTABLE_SYMMETRIC = "unstable_symmetric"

    def __str__(self) -> str:
        return str(self.value)
