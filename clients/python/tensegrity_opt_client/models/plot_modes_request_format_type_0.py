from enum import StrEnum


class PlotModesRequestFormatType0(StrEnum):
    PNG = "png"
    SVG = "svg"

    def __str__(self) -> str:
        return str(self.value)
