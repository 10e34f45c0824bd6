"""One input vocabulary: every parameter has one name and one form on every interface.

The walk reads every request body of the committed OpenAPI document (every operation, ``$ref``s resolved), the
job spec's schema (``JobSpec``: the sweep spec as the service takes it, which the library's sweep spec mirrors),
and collects each field's *forms* (its JSON shapes: ``number``,
``[number]``, ``{hi,lo}``, ...; ``null`` is only "optional" and left out). It then finds

* a concept under two spellings (``l0`` and ``L0``, ``rest_length`` and ``rest_lengths``): names equal once
  case, underscores and a plural ``s`` are dropped must be one name, or be listed in :data:`DISTINCT` (a
  value and a list of them, ``target``/``targets``);
* one name with two sets of forms (bounds as an object in one operation, an array in another): every
  occurrence of a name takes the same forms, or the name is in :data:`HOMONYMS` (two concepts, one word) or
  :data:`NARROWER` (a documented subset, with its reason).

Conventions of the walk (the forms the vocabulary has on purpose, README "The HTTP service"):
``map[X]`` (one ``X`` per name: ``bounds: {"k": X}``) is compared as ``X``; the values of a parameter (a job
grid's lists, ``dx: [..] | {start, stop, num}``) are compared as the parameter; the parts of a value (``lo``,
``hi`` of bounds, ``start``, ``stop``, ``num`` of a range) are compared under their parent's name.
"""

from __future__ import annotations

import json
import re
from collections import defaultdict
from pathlib import Path

import pytest

pytest.importorskip("fastapi")

from service.schemas import jobs as job_schemas  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
SPEC = ROOT / "openapi" / "openapi.json"

#: One word, two concepts: the name, and why its forms may differ.
HOMONYMS = {
    "grid": "an energy landscape's points per axis (an integer) vs a job's cartesian product (an object)",
    "q": "a configuration (n angles) vs the angles of one joint at which a segment's torque is drawn",
    "x": "the quantity on a branch figure's horizontal axis (a name), not a coordinate",
    "y": "the quantity on a branch figure's vertical axis (a name), not a coordinate",
    "targets": "held-tip deflections {dx, dy} of a batch vs tip positions [x, y] of a rest-length plan",
}
#: Names some operations take in fewer forms than others, and why.
NARROWER = {
    "start": "a loading path also starts from a held tip {dx, dy} (its least-energy equilibrium); every other "
             "start is the configuration {q}",
    "loads": "a plan takes one [fx, fy] for every step or one per step; a simulation's loads are its sampled "
             "input, one per sample",
}
#: Parameters a sweep varies as one number (its typed columns): a job's grid and points take ``k`` and ``L0`` as
#: one number for both springs; its base chain, as every chain, also takes the pair.
SWEPT_AS_NUMBERS = {"k", "L0"}
#: Names equal up to case, underscores and a plural ``s`` that are two concepts (a value and a list of them).
DISTINCT = {frozenset(p) for p in (("target", "targets"), ("load", "loads"), ("end_angle", "end_angles"),
                                   ("segment", "segments"), ("value", "values"), ("preload", "preloads"),
                                   ("bound", "bounds"), ("step", "steps"), ("kind", "kinds"),
                                   ("weight", "weights"), ("point", "points"), ("start", "starts"),
                                   ("direction", "directions"),
                                   ("stop", "stops"))}          # a range's end; the joints' stops (`stops`)
#: The parts of a composite value, compared under their parent's name.
PARTS = {"lo", "hi", "start", "stop", "num"}
_RANGE = "{num,start,stop}"


class Walk:
    """The forms of every field met, by name, with where each was met."""

    def __init__(self) -> None:
        self.forms: dict[str, dict[frozenset[str], list[str]]] = defaultdict(lambda: defaultdict(list))

    # ---- shapes
    @staticmethod
    def resolve(schema: dict, defs: dict) -> dict:
        while "$ref" in schema:
            schema = defs[schema["$ref"].rsplit("/", 1)[-1]]
        return schema

    def alternatives(self, schema: dict, defs: dict) -> list[dict]:
        schema = self.resolve(schema, defs)
        for key in ("anyOf", "oneOf"):
            if key in schema:
                return [a for alt in schema[key] for a in self.alternatives(alt, defs)]
        if len(schema.get("allOf", ())) == 1:
            return self.alternatives(schema["allOf"][0], defs)
        return [] if schema.get("type") == "null" else [schema]

    def shape(self, schema: dict, defs: dict, depth: int = 0) -> str:
        schema = self.resolve(schema, defs)
        if depth > 6:
            return "..."
        if "const" in schema:
            return type(schema["const"]).__name__.replace("str", "string").replace("bool", "boolean")
        kind = schema.get("type")
        if kind == "array":
            items = schema.get("items") or {}
            inner = [items] if isinstance(items, dict) else list(items)
            inner += schema.get("prefixItems", [])
            return "[" + "|".join(sorted({self.shape(a, defs, depth + 1) for i in inner
                                            for a in self.alternatives(i, defs)})) + "]"
        if "properties" in schema:
            return "{" + ",".join(sorted(schema["properties"])) + "}"
        if isinstance(schema.get("additionalProperties"), dict):
            values = self.alternatives(schema["additionalProperties"], defs)
            return "map[" + "|".join(sorted({self.shape(a, defs, depth + 1) for a in values})) + "]"
        if kind == "integer":
            return "number"          # an integer is a number with no fraction (JSON Schema's integer)
        return kind or "any"

    def form_set(self, schema: dict, defs: dict) -> frozenset[str]:
        alts = self.alternatives(schema, defs)
        shapes = {self.shape(a, defs) for a in alts}
        # map[X]: one X per name, compared as X
        if len(alts) == 1 and shapes and next(iter(shapes)).startswith("map["):
            ap = self.resolve(alts[0], defs)["additionalProperties"]
            return self.form_set(ap, defs)
        # the values of a parameter: [T] | {start, stop, num} compared as T
        if _RANGE in shapes and len(shapes) == 2:
            item = next(self.resolve(a, defs) for a in alts if self.resolve(a, defs).get("type") == "array")
            return self.form_set(item.get("items", {}), defs)
        return frozenset(shapes)

    # ---- the walk
    def walk(self, schema: dict, defs: dict, where: str, parent: str | None = None,
             stack: tuple[str, ...] = ()) -> None:
        if "$ref" in schema:
            name = schema["$ref"].rsplit("/", 1)[-1]
            if name in stack:
                return
            stack = (*stack, name)
        schema = self.resolve(schema, defs)
        for key in ("anyOf", "oneOf", "allOf"):
            for alt in schema.get(key, ()):
                self.walk(alt, defs, where, parent, stack)
        values = schema.get("title") == "SweepGrid"        # a job grid: {parameter: [values]}
        for name, sub in schema.get("properties", {}).items():
            key = f"{parent}.{name}" if parent is not None and name in PARTS else name
            sub_forms = self.form_set(self.resolve(sub, defs).get("items", {}) if values else sub, defs)
            if name in SWEPT_AS_NUMBERS and (values or schema.get("title") == "SweepPoint"):
                key = f"{name} (swept)"
            self.forms[key][sub_forms].append(f"{where}.{name}")
            self.walk(sub, defs, f"{where}.{name}", key, stack)
        if schema.get("type") == "array":
            items = schema.get("items")
            for item in ([items] if isinstance(items, dict) else []) + list(schema.get("prefixItems", [])):
                self.walk(item, defs, f"{where}[]", parent, stack)
        if isinstance(schema.get("additionalProperties"), dict):
            self.walk(schema["additionalProperties"], defs, f"{where}.*", parent, stack)

    # ---- the findings
    def shaped_two_ways(self) -> list[str]:
        out = []
        for name, forms in sorted(self.forms.items()):
            if len(forms) > 1 and name not in HOMONYMS and name not in NARROWER:
                out.append(f"{name}: " + "; ".join(f"{' | '.join(sorted(f))} at {', '.join(sorted(w)[:3])}"
                                                 for f, w in forms.items()))
        return out

    def spelled_two_ways(self) -> list[str]:
        by_key = defaultdict(set)
        for name in self.forms:
            leaf = name.rsplit(".", 1)[-1]
            by_key[re.sub(r"s$", "", leaf.replace("_", "").lower())].add(leaf)
        return [" / ".join(sorted(names)) for names in by_key.values()
                if len(names) > 1 and not any(frozenset(p) <= frozenset(names) and len(names) == 2 for p in DISTINCT)]


def _document_walk(doc: dict) -> Walk:
    walk = Walk()
    defs = doc["components"]["schemas"]
    for path, item in doc["paths"].items():
        for method, op in item.items():
            for media in (op.get("requestBody") or {}).get("content", {}).values():
                walk.walk(media["schema"], defs, f"{method.upper()} {path}")
    return walk


def _model_walk(walk: Walk, model: type, where: str) -> None:
    schema = model.model_json_schema()
    walk.walk(schema, schema.get("$defs", {}), where)


@pytest.fixture(scope="module")
def walk() -> Walk:
    w = _document_walk(json.loads(SPEC.read_text(encoding="utf-8")))
    _model_walk(w, job_schemas.JobSpec, "job spec")
    return w


def test_no_parameter_is_shaped_two_ways(walk):
    found = walk.shaped_two_ways()
    assert not found, "fields with two sets of forms:\n  " + "\n  ".join(found)


def test_no_parameter_is_spelled_two_ways(walk):
    found = walk.spelled_two_ways()
    assert not found, "one concept under two names:\n  " + "\n  ".join(found)


def test_the_walk_sees_what_it_checks(walk):
    """The walk reads the bounds of the design and of the job spec, and the ranges' parts."""
    where = {w for forms in walk.forms["bounds"].values() for w in forms}
    assert any(w.startswith("POST /v1/design/critical-force") for w in where)
    assert any(w.startswith("job spec") for w in where)
    assert "dx.start" in walk.forms and "bounds.lo" in walk.forms


def test_the_walk_finds_a_field_shaped_two_ways():
    doc = {"components": {"schemas": {"B": {"type": "object", "properties": {"lo": {"type": "number"},
                                                                            "hi": {"type": "number"}}}}},
           "paths": {
               "/a": {"post": {"requestBody": {"content": {"application/json": {"schema": {
                   "type": "object", "properties": {"bounds": {"$ref": "#/components/schemas/B"},
                                                    "L0": {"type": "number"}}}}}}}},
               "/b": {"post": {"requestBody": {"content": {"application/json": {"schema": {
                   "type": "object", "properties": {"bounds": {"type": "array", "minItems": 2, "maxItems": 2,
                                                               "items": {"type": "number"}},
                                                    "l0": {"type": "number"}}}}}}}}}}
    w = _document_walk(doc)
    assert [f.split(":")[0] for f in w.shaped_two_ways()] == ["bounds"]
    assert w.spelled_two_ways() == ["L0 / l0"]


def test_the_client_spells_every_field_as_the_json_does():
    """The generated client's attribute of a field is its JSON name (``L0``, ``K_min``), not a case-folded
    copy (``l0``): one spelling in the JSON, the library and the client (``clients/regenerate.py``)."""
    models = ROOT / "clients" / "python" / "tensegrity_opt_client" / "models"
    pairs = {m for path in models.glob("*.py")
             for m in re.findall(r'field_dict\["(\w+)"\] = (\w+)$', path.read_text(encoding="utf-8"), re.MULTILINE)}
    assert ("L0", "L0") in pairs
    renamed = sorted({(name, attr) for name, attr in pairs if name != attr and attr != f"{name}_"})
    assert not renamed, f"client attributes spelled unlike their JSON names: {renamed}"


# ---------------------------------------------------------------------------- the same bounds on every interface
_CHAIN = {"n": 3, "a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0}
#: The bounds of ``k`` in each documented form: the library's tuple, the JSON array, the JSON object.
_FORMS = {"pair": [0.2, 1.5], "object": {"lo": 0.2, "hi": 1.5}}
_TENSION = {"pair": [-10.0, 10.0], "object": {"lo": -10.0, "hi": 10.0}}


def _spec(form: str) -> dict:
    return {"analysis": "design", "manipulator": _CHAIN, "grid": {"n": [3]},
            "options": {"vary": ["k"], "bounds": {"k": _FORMS[form]}, "budget": {"k": 3.6},
                        "tension": _TENSION[form]}}


@pytest.fixture(scope="module")
def api(tmp_path_factory):
    from fastapi.testclient import TestClient
    from service_helpers import service_settings

    from service.main import create_app

    db = tmp_path_factory.mktemp("vocabulary") / "jobs.sqlite3"
    with TestClient(create_app(service_settings(inline_processes=0, jobs_db=str(db)))) as client:
        yield client


def _job_force(api, spec: dict) -> float:
    import time

    from service_helpers import WAIT_SECONDS

    r = api.post("/v1/jobs", json=spec)
    assert r.status_code in (200, 201, 202), r.text
    job_id = r.json()["id"]
    deadline = time.monotonic() + WAIT_SECONDS
    while (job := api.get(f"/v1/jobs/{job_id}").json())["status"] in ("queued", "running"):
        assert time.monotonic() < deadline, job
        time.sleep(0.05)
    assert job["status"] == "done", job
    (row,) = job["results"]
    assert row["error"] is None, row
    return row["critical_force"]


@pytest.mark.slow
def test_the_same_bounds_in_every_form_give_the_same_design_everywhere(api, tmp_path):
    """``bounds.k`` and ``tension`` as ``[lo, hi]`` and as ``{"lo", "hi"}``: the library, the REST operation, a job,
    a sweep spec and the command line's sweep all take both and find one design."""
    import tensegrity_opt as to
    from tensegrity_opt.applications import sweeps
    from tensegrity_opt.applications.cli import main as cli_main

    m = to.Manipulator.uniform(3)
    want = to.maximize_critical_force(m, ["k"], {"k": (0.2, 1.5)}, {"k": 3.6}, tension=(-10.0, 10.0)).critical_force
    got = {}
    for form in _FORMS:
        got[f"library {form}"] = to.maximize_critical_force(m, ["k"], {"k": _FORMS[form]}, {"k": 3.6},
                                                            tension=_TENSION[form]).critical_force
        r = api.post("/v1/design/critical-force", json={"manipulator": _CHAIN, "vary": ["k"],
                                                         "bounds": {"k": _FORMS[form]}, "budget": {"k": 3.6},
                                                         "tension": _TENSION[form]})
        assert r.status_code == 200, r.text
        got[f"REST {form}"] = r.json()["critical_force"]
        got[f"job {form}"] = _job_force(api, _spec(form))
        got[f"sweep {form}"] = float(sweeps.sweep(_spec(form), scheduler="serial").rows[0]["critical_force"])
        path, out = tmp_path / f"{form}.json", tmp_path / f"{form}-rows.json"
        path.write_text(json.dumps(_spec(form)), encoding="utf-8")
        assert cli_main(["sweep", str(path), "-o", str(out), "--scheduler", "serial"]) == 0
        rows = json.loads(out.read_text(encoding="utf-8"))
        got[f"CLI {form}"] = (rows["rows"] if isinstance(rows, dict) else rows)[0]["critical_force"]
    assert want < 0
    for where, value in got.items():
        assert value == pytest.approx(want, rel=1e-6), (where, got)


def test_the_stream_and_the_plan_take_seconds_as_one_declared_type():
    """A time (``times``, ``dt``: seconds, > 0) is declared once, by the control schemas, and the stream's
    messages take that declaration."""
    from service.schemas import control, stream

    assert stream.Seconds is control.Seconds
    assert "Seconds = " not in (ROOT / "service" / "schemas" / "stream.py").read_text(encoding="utf-8")
