from enum import StrEnum


class ReadyDegradedItem(StrEnum):
    DESIGN_PROCESSES = "design_processes"
    FAST_PATH = "fast_path"
    JOB_STORE = "job_store"

    def __str__(self) -> str:
        return str(self.value)
