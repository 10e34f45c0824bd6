from enum import StrEnum


class PlotHoldingRequestFormatType0(StrEnum):
    PNG = "png"
    SVG = "svg"

    def __str__(self) -> str:
        return str(self.value)
