from enum import StrEnum


class ForceEstimateOutStatus(StrEnum):
    GAUSS_NEWTON = "gauss_newton"
    GENERALIZED_LEAST_SQUARES = "generalized_least_squares"
    LEAST_SQUARES = "least_squares"
    REWEIGHTING_NOT_CONVERGED = "reweighting_not_converged"
    WEIGHTED_GAUSS_NEWTON = "weighted_gauss_newton"

    def __str__(self) -> str:
        return str(self.value)
