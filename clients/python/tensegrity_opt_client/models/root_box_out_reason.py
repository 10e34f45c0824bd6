from enum import StrEnum


class RootBoxOutReason(StrEnum):
    KRAWCZYK = "krawczyk"
    MOVED = "moved"
    OUTSIDE = "outside"
    OVERLAP = "overlap"
    RANGE = "range"
    SINGULAR = "singular"
    VALUE_0 = ""

    def __str__(self) -> str:
        return str(self.value)
