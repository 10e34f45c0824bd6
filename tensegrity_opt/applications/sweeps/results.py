"""The rows of a sweep as a :class:`SweepResult` (the result contract: ``success``, ``status``, ``message``) and
its files: CSV, JSON, Parquet (write and read back)."""

from __future__ import annotations

import csv
import io
import json
import os
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, ClassVar

from ...errors import InvalidParameterError
from ...outcome import Outcome, freeze
from .spec import _BASE_TYPES, RESULT_COLUMNS

__all__ = ["SweepResult", "write_csv", "read_results"]


def _cell_csv(v: Any, kind: str) -> str:
    if v is None:
        return ""
    if kind in ("floats", "strs", "floats2", "strs2"):
        return json.dumps(v, allow_nan=False)
    if kind == "bool":
        return "true" if v else "false"
    if kind == "float":
        return repr(float(v))
    return str(v)


def _cell_parse(text: str, kind: str) -> Any:
    if text == "":
        return None
    if kind == "int":
        return int(text)
    if kind == "float":
        return float(text)
    if kind == "bool":
        return text.lower() in ("true", "1", "yes")
    if kind in ("floats", "strs", "floats2", "strs2"):
        return json.loads(text)
    return text


def _type_of(col: str) -> str:
    if col in _BASE_TYPES:
        return _BASE_TYPES[col]
    for cols in RESULT_COLUMNS.values():
        if col in cols:
            return cols[col]
    if col.endswith("_opt"):
        return "floats"
    return "str"


@dataclass(frozen=True)
class SweepResult(Outcome):
    """Rows of a sweep (sorted by ``index``; skipped points are absent) and how it ran.

    Attributes
    ----------
    spec : dict or None
        The validated spec (``None`` for rows read back from a CSV file).
    columns : tuple of str
        ``index``, the swept parameters, the analysis's result columns, ``error``.
    rows : tuple of dict
        One ``{column: value}`` per point solved, by ``index``; a failed point's row has its ``error``
        (``"code: message"``) and empty results.
    total, skipped : int
        Points of the sweep, and those skipped (``skip``: done before, not in :attr:`rows`).
    cancelled : bool
        The sweep stopped early (``should_stop``): some points have no row.
    elapsed : float
        Wall time (s).
    scheduler : str
        What ran it (``"serial"``, ``"serial+local"``, ``"threads"``, a Dask address ...).
    types : dict
        Column -> type (``int``, ``float``, ``bool``, ``str``, ``floats``, ``strs``).
    status : str
        :attr:`STATUSES`, derived from :attr:`cancelled` and the rows' errors.
    message : str
        The same in a sentence, with the counts.
    """

    STATUSES: ClassVar[dict[str, str]] = {
        "complete": "every point to solve has its row and none failed",
        "point_errors": "every point to solve has its row; some points failed (their rows carry the error)",
        "cancelled": "the sweep stopped early: some points have no row",
    }
    SUCCESS: ClassVar[frozenset[str]] = frozenset({"complete", "point_errors"})

    spec: dict[str, Any] | None
    columns: tuple[str, ...]
    rows: tuple[dict[str, Any], ...]
    total: int = 0
    skipped: int = 0
    cancelled: bool = False
    elapsed: float = 0.0
    scheduler: str = "serial"
    types: dict[str, str] = field(default_factory=dict, repr=False)

    def __post_init__(self) -> None:
        if not self.types:
            object.__setattr__(self, "types", {c: _type_of(c) for c in self.columns})
        freeze(self)

    def __len__(self) -> int:
        return len(self.rows)

    @property
    def status(self) -> str:
        """``"complete"``, ``"point_errors"`` or ``"cancelled"`` (:attr:`STATUSES`)."""
        if self.cancelled:
            return "cancelled"
        return "point_errors" if self.errors else "complete"

    @property
    def message(self) -> str:
        """A sentence: the points solved, failed and skipped."""
        failed = len(self.errors)
        skipped = f", {self.skipped} skipped (done before)" if self.skipped else ""
        head = "stopped early: " if self.cancelled else ""
        return f"{head}{len(self.rows)} of {self.total} points solved, {failed} failed{skipped}"

    @property
    def errors(self) -> list[dict[str, Any]]:
        """The rows whose point failed."""
        return [r for r in self.rows if r.get("error")]

    def column(self, name: str) -> list[Any]:
        return [r.get(name) for r in self.rows]

    # -------------------------------------------------------------- writers
    def csv_text(self) -> str:
        buf = io.StringIO()
        write_csv(buf, self.columns, self.rows, self.types)
        return buf.getvalue()

    def to_csv(self, path: str | os.PathLike[str]) -> Path:
        """CSV with a header; lists as JSON text, booleans ``true``/``false``, missing values empty."""
        path = Path(path)
        with open(path, "w", encoding="utf-8", newline="") as fh:
            write_csv(fh, self.columns, self.rows, self.types)
        return path

    def to_dict(self) -> dict[str, Any]:
        """JSON form, the document :meth:`to_json` writes: ``{"success", "status", "message", "format", "spec",
        "columns", "rows": [{column: value}, ...]}`` (no NaN: a missing value is ``None``)."""
        return {**self.outcome(), "format": "tensegrity-sweep/1", "spec": self.spec, "columns": list(self.columns),
                "rows": [{c: r.get(c) for c in self.columns} for r in self.rows]}

    def to_json(self, path: str | os.PathLike[str]) -> Path:
        """:meth:`to_dict` as a JSON file (``allow_nan=False``)."""
        path = Path(path)
        with open(path, "w", encoding="utf-8") as fh:
            json.dump(self.to_dict(), fh, allow_nan=False, indent=1)
            fh.write("\n")
        return path

    def to_parquet(self, path: str | os.PathLike[str]) -> Path:
        """Parquet (pyarrow) with typed columns; lists as list columns; the spec in the schema metadata."""
        import pyarrow as pa
        import pyarrow.parquet as pq

        arrow = {"int": pa.int64(), "float": pa.float64(), "bool": pa.bool_(), "str": pa.string(),
                 "floats": pa.list_(pa.float64()), "strs": pa.list_(pa.string()),
                 "floats2": pa.list_(pa.list_(pa.float64())), "strs2": pa.list_(pa.list_(pa.string()))}
        schema = pa.schema([pa.field(c, arrow[self.types.get(c, "str")]) for c in self.columns],
                           metadata={"tensegrity_sweep_spec": json.dumps(self.spec)})
        table = pa.Table.from_pylist([{c: r.get(c) for c in self.columns} for r in self.rows], schema=schema)
        path = Path(path)
        pq.write_table(table, path)
        return path

    def save(self, path: str | os.PathLike[str]) -> Path:
        """Write by suffix: ``.csv``, ``.json``, ``.parquet`` / ``.pq``."""
        suffix = Path(path).suffix.lower()
        if suffix == ".csv":
            return self.to_csv(path)
        if suffix == ".json":
            return self.to_json(path)
        if suffix in (".parquet", ".pq"):
            return self.to_parquet(path)
        raise InvalidParameterError(f"output: unknown file type {suffix or '(none)'!r}; use .csv, .json or .parquet",
                                    field="output")

    # -------------------------------------------------------------- reader
    @classmethod
    def read(cls, path: str | os.PathLike[str]) -> SweepResult:
        """Read a file written by :meth:`save` back (same rows, same types)."""
        path = Path(path)
        suffix = path.suffix.lower()
        if suffix == ".json":
            with open(path, encoding="utf-8") as fh:
                doc = json.load(fh)
            return cls(doc.get("spec"), list(doc["columns"]), list(doc["rows"]), total=len(doc["rows"]),
                       cancelled=doc.get("status") == "cancelled")
        if suffix in (".parquet", ".pq"):
            import pyarrow.parquet as pq

            table = pq.read_table(path)
            meta = table.schema.metadata or {}
            raw = meta.get(b"tensegrity_sweep_spec")
            spec = json.loads(raw) if raw else None
            rows = table.to_pylist()
            return cls(spec, list(table.column_names), rows, total=len(rows))
        if suffix == ".csv":
            with open(path, encoding="utf-8", newline="") as fh:
                reader = csv.reader(fh)
                header = next(reader)
                types = [_type_of(c) for c in header]
                rows = [{c: _cell_parse(v, t) for c, v, t in zip(header, line, types)} for line in reader]
            return cls(None, header, rows, total=len(rows))
        raise InvalidParameterError(f"unknown file type {suffix or '(none)'!r}; use .csv, .json or .parquet",
                                    field="path")


def write_csv(fh: Any, cols: Sequence[str], rows: Iterable[Mapping[str, Any]],
              types: Mapping[str, str] | None = None, header: bool = True) -> None:
    """Write ``rows`` as CSV to the text file ``fh`` (the format of :meth:`SweepResult.to_csv`);
    ``header=False``: without the header line (a later batch of a streamed file)."""
    types = dict(types or {})
    kinds = [types.get(c) or _type_of(c) for c in cols]
    w = csv.writer(fh, lineterminator="\n")
    if header:
        w.writerow(cols)
    for r in rows:
        w.writerow([_cell_csv(r.get(c), k) for c, k in zip(cols, kinds)])


def read_results(path: str | os.PathLike[str]) -> SweepResult:
    """Shorthand for :meth:`SweepResult.read`."""
    return SweepResult.read(path)

