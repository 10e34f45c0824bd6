from enum import StrEnum


class JobSpecAnalysis(StrEnum):
    ATLAS = "atlas"
    BUCKLING = "buckling"
    DESIGN = "design"
    EQUILIBRIA_COUNT = "equilibria_count"
    EQUILIBRIUM = "equilibrium"
    STIFFNESS = "stiffness"

    def __str__(self) -> str:
        return str(self.value)
