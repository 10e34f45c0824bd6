from enum import StrEnum


class JobOutAnalysis(StrEnum):
    ATLAS = "atlas"
    BUCKLING = "buckling"
    DESIGN = "design"
    EQUILIBRIA_COUNT = "equilibria_count"
    EQUILIBRIUM = "equilibrium"
    FIGURE = "figure"
    STIFFNESS = "stiffness"

    def __str__(self) -> str:
        return str(self.value)
