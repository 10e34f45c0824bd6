from enum import StrEnum


class UniformManipulatorInSpring(StrEnum):
    LINEAR = "linear"
    TENSION_ONLY = "tension_only"

    def __str__(self) -> str:
        return str(self.value)
