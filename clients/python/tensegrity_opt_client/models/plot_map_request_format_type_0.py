from enum import StrEnum


class PlotMapRequestFormatType0(StrEnum):
    PNG = "png"
    SVG = "svg"

    def __str__(self) -> str:
        return str(self.value)
