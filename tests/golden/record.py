"""Golden recording of the project's answers: HTTP bodies, CLI ``--json`` output and library results.

Used to prove that a restructuring changes no answer. ``record`` runs every request example of the
committed OpenAPI document against the in-process app (and each again with other chains: bistable,
heterogeneous, asymmetric preloads), a set of CLI commands and library calls, and writes the requests
with their answers to a JSON file; ``replay`` reruns the *same requests* (read from that file) on the
current tree and writes a second file; ``compare`` lists every difference, ignoring fields the second
recording adds and the volatile ones (job ids, times, versions).

    python tests/golden/record.py record  /tmp/golden-before.json
    python tests/golden/record.py replay  /tmp/golden-before.json /tmp/golden-after.json
    python tests/golden/record.py compare /tmp/golden-before.json /tmp/golden-after.json
"""

from __future__ import annotations

import copy
import hashlib
import json
import math
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]

#: Chains substituted for the example's manipulator (the paper's chain is the examples' own).
CHAINS = {
    "bistable": {"n": 4, "a": 0.5, "b": 1.0, "k": 1.0, "L0": 1.0},
    "mixed": {"segments": [
        {"a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0},
        {"a": 0.8, "b": 1.2, "k": [1.5, 1.0], "L0": [1.3, 1.1]},
        {"a": 0.5, "b": 1.0, "k": 2.0, "L0": 1.0},
        {"a": 1.1, "b": 0.9, "k": 0.7, "L0": [0.9, 1.0]},
    ]},
}

#: Keys whose values change from run to run (not answers).
VOLATILE = {"id", "job_id", "created", "created_at", "updated", "updated_at", "started", "started_at",
            "finished", "finished_at", "elapsed", "elapsed_s", "seconds", "wall", "version", "versions",
            "python", "casadi", "numpy", "uptime", "request_id", "location", "duration", "eta"}


def _app():
    from fastapi.testclient import TestClient

    from service.config import Settings
    from service.main import create_app

    return TestClient(create_app(Settings()))


def _examples() -> list[tuple[str, str, dict]]:
    spec = json.loads((ROOT / "openapi" / "openapi.json").read_text())
    out = []
    for path, ops in sorted(spec["paths"].items()):
        for method, op in ops.items():
            content = op.get("requestBody", {}).get("content", {})
            for media in content.values():
                if "example" in media:
                    out.append((op["operationId"], path, media["example"]))
                for name, ex in sorted(media.get("examples", {}).items()):
                    if "value" in ex:
                        out.append((f"{op['operationId']}:{name}", path, ex["value"]))
    return out


def _variants(name: str, path: str, body: dict) -> list[tuple[str, str, dict]]:
    out = [(name, path, body)]
    if isinstance(body, dict) and "manipulator" in body and not path.startswith("/v1/jobs"):
        for cname, chain in CHAINS.items():
            b = copy.deepcopy(body)
            b["manipulator"] = chain
            out.append((f"{name}@{cname}", path, b))
    return out


#: Bodies that must be refused (the error answers are part of the contract).
ERRORS = [
    ("err:typo", "/v1/equilibrium", {"manipulator": {"n": 4}, "dX": 0.1}),
    ("err:unreachable", "/v1/equilibrium", {"manipulator": {"n": 4}, "dx": 9.0}),
    ("err:bad-n", "/v1/buckling", {"manipulator": {"n": 0}}),
    ("err:unstable-straight", "/v1/force-deflection",
     {"manipulator": {"n": 4, "a": 0.5, "b": 1, "k": 1, "L0": 1}, "dx": {"start": 0, "stop": 1, "num": 5}}),
    ("err:asym-buckling", "/v1/buckling",
     {"manipulator": {"segments": [{"a": 1, "b": 1, "k": 1, "L0": [1.0, 1.2]}] * 3}}),
    ("err:nan", "/v1/equilibrium", {"manipulator": {"n": 4}, "dx": "NaN"}),
    ("curve:bistable-partial", "/v1/force-deflection",
     {"manipulator": {"n": 4, "a": 1, "b": 1, "k": 1, "L0": 1}, "dx": {"start": 0, "stop": 4, "num": 81}}),
    ("equilibria:homotopy-3", "/v1/equilibria",
     {"manipulator": {"n": 3, "a": 0.5, "b": 1, "k": 1, "L0": 1}, "dx": 0.2, "dy": 0.1, "method": "homotopy"}),
    ("equilibrium:dy", "/v1/equilibrium", {"manipulator": {"n": 6, "a": 0.9, "b": 1, "k": 1, "L0": 1.2},
                                           "dx": 1.5, "dy": 2.0}),
    ("equilibrium:long", "/v1/equilibrium", {"manipulator": {"n": 20}, "dx": 0.5, "dy": 0.3}),
]

#: CLI commands (``--json`` where the command has it).
CLI = [
    ["buckling", "--json"],
    ["buckling", "--n", "5", "--a", "0.8", "--boundary", "free", "--json"],
    ["equilibrium", "--dx", "0.1", "--json"],
    ["equilibrium", "--fx", "-0.3", "--json"],
    ["equilibria", "--dx", "0.1", "--json"],
    ["curve", "--dx", "0", "1", "11", "--json"],
    ["rest", "--n", "3", "--a", "0.5", "--json"],
    ["limit-load", "--json"],
    ["branch", "--json"],
    ["force-estimate", "--help"],
]

#: Library calls (the verbs that have no HTTP form, and a few that do, on every family).
LIBRARY = [
    "to.critical_force(P).to_dict()",
    "to.critical_force(P, 'free').to_dict()",
    "to.solve_equilibrium(P, 0.1).to_dict()",
    "to.solve_equilibrium(B, 0.3, 0.2).to_dict()",
    "to.solve_equilibrium(H, 0.4, -0.3).to_dict()",
    "to.solve_equilibrium_under_force(P, -0.3, 0.0).to_dict()",
    "[e.to_dict() for e in to.find_equilibria(P, 0.1)]",
    "[e.to_dict() for e in to.find_equilibria(B, 0.2, 0.1)]",
    "[e.to_dict() for e in to.find_equilibria_under_force(B, -0.05, 0.01)]",
    "to.rest_configuration(B).to_dict()",
    "to.force_deflection(P, np.linspace(0, 1, 11)).to_dict()",
    "to.force_deflection(H, np.linspace(0, 1, 11), 0.2).to_dict()",
    "np.asarray(to.cartesian_stiffness(P, to.solve_equilibrium(P, 0.1))).tolist()",
    "{k: np.asarray(v).tolist() for k, v in to.critical_load_sensitivity(P).items()}",
    "{k: np.asarray(v).tolist() for k, v in to.equilibrium_sensitivity(P, to.solve_equilibrium(P, 0.1)).items()}",
    "[e.to_dict() if hasattr(e, 'to_dict') else repr(e) for e in to.solve_equilibria_batch(P, [(0.05, 0), (0.1, 0.01), (0.2, 0.0)])]",  # noqa: E501 (the expression is the answer's key)
    "to.limit_load(P).to_dict()",
    "to.limit_load(B, boundary='guided').to_dict()",
    "to.trace_branch(P, control='guided', t_max=1.0, max_points=200).to_dict()",
    "to.energy_landscape(P, 0.1, grid=9).to_dict()",
    "to.estimate_tip_force(P, to.solve_equilibrium_under_force(P, -0.1, 0.05).q).to_dict()",
    "to.maximize_critical_force(P, vary=['k'], bounds={'k': (0.2, 5)}, budget={'k': 4}).to_dict()",
    "to.choose_preloads(P, (7.8, 0.5)).to_dict()",
    "to.load_capacity(P, directions=8).to_dict()",
    "to.stability_boundary(P, 'guided', 'asymmetry', p_min=-0.03, p_max=0.03, max_points=60).to_dict()",
    "to.stability_atlas(P, [0.1, 0.5], [0.0, 0.3]).to_dict()",
    "to.simulate(P, loads=[(-0.1 * i, 0.0) for i in range(6)]).to_dict()",
    "to.plan_preloads(P, [(7.95, 0.1), (7.9, 0.2)]).to_dict()",
    "to.preloads_for_stiffness(P, (7.9, 0.3)).to_dict()",
    "to.preloads_for_critical_force(P, 0.8).to_dict()",
]


def _digest(resp) -> object:
    ctype = resp.headers.get("content-type", "")
    if ctype.startswith("application/json"):
        return resp.json()
    if ctype.startswith("image/png"):
        return {"png_sha256": hashlib.sha256(resp.content).hexdigest(), "bytes": len(resp.content)}
    if ctype.startswith("image/svg"):
        return {"svg_bytes": len(resp.content)}
    return {"content_type": ctype, "text": resp.text[:2000]}


def _http(requests: list[tuple[str, str, dict]]) -> list[dict]:
    client = _app()
    out = []
    with client:
        for name, path, body in requests:
            t0 = time.perf_counter()
            r = client.post(path, json=body)
            if path == "/v1/jobs" and r.status_code == 202:
                jid = r.json()["id"]
                for _ in range(600):
                    j = client.get(f"/v1/jobs/{jid}").json()
                    if j.get("status") in ("done", "failed", "cancelled", "interrupted"):
                        break
                    time.sleep(0.2)
                res = client.get(f"/v1/jobs/{jid}/results")
                body_out = {"job": _digest(client.get(f"/v1/jobs/{jid}")), "results": _digest(res)}
            else:
                body_out = _digest(r)
            out.append({"name": name, "path": path, "request": body, "status": r.status_code,
                        "body": body_out, "seconds": round(time.perf_counter() - t0, 3)})
            print(f"{r.status_code} {name} ({time.perf_counter() - t0:.1f} s)", file=sys.stderr)
    return out


def _cli(commands: list[list[str]]) -> list[dict]:
    out = []
    exe = Path(sys.executable).with_name("tensegrity-opt")
    for argv in commands:
        p = subprocess.run([str(exe), *argv], capture_output=True, text=True, timeout=600)
        try:
            stdout: object = json.loads(p.stdout)
        except ValueError:
            stdout = p.stdout
        out.append({"argv": argv, "rc": p.returncode, "stdout": stdout, "stderr": p.stderr.strip()[-500:]})
        print(f"{p.returncode} cli {' '.join(argv)}", file=sys.stderr)
    return out


def _library(calls: list[str], rename: dict[str, str] | None = None) -> list[dict]:
    import numpy as np

    import tensegrity_opt as to

    ns = {"to": to, "np": np,
          "P": to.Manipulator.uniform(4, a=1, b=1, k=1, L0=1),
          "B": to.Manipulator.uniform(4, a=0.5, b=1, k=1, L0=1),
          "H": to.Manipulator.from_dict(CHAINS["mixed"])}
    out = []
    for call in calls:
        expr = call
        for old, new in (rename or {}).items():
            expr = expr.replace(old, new)
        try:
            value = eval(expr, ns)  # noqa: S307 - our own fixed expressions
            out.append({"call": call, "value": json.loads(json.dumps(value, default=_default))})
        except Exception as exc:  # noqa: BLE001 - an exception is an answer too
            out.append({"call": call, "error": f"{type(exc).__name__}: {exc}"})
        print(f"lib {call[:70]}", file=sys.stderr)
    return out


def _default(o):
    import numpy as np

    if isinstance(o, np.ndarray):
        return o.tolist()
    if isinstance(o, (np.floating, np.integer, np.bool_)):
        return o.item()
    return repr(o)


def record(path: str) -> None:
    reqs = [v for ex in _examples() for v in _variants(*ex)] + ERRORS
    doc = {"http": _http(reqs), "cli": _cli(CLI), "library": _library(LIBRARY)}
    Path(path).write_text(json.dumps(doc, indent=1, sort_keys=True, allow_nan=True))


def replay(before: str, after: str, rename: dict[str, str] | None = None) -> None:
    doc = json.loads(Path(before).read_text())
    reqs = [(h["name"], h["path"], h["request"]) for h in doc["http"]]
    new = {"http": _http(reqs), "cli": _cli([c["argv"] for c in doc["cli"]]),
           "library": _library([c["call"] for c in doc["library"]], rename)}
    Path(after).write_text(json.dumps(new, indent=1, sort_keys=True, allow_nan=True))


def _diff(a, b, where: str, out: list[str], rtol: float) -> None:
    if isinstance(a, dict) and isinstance(b, dict):
        for k in a:
            if k in VOLATILE:
                continue
            if k not in b:
                out.append(f"{where}.{k}: missing after")
            else:
                _diff(a[k], b[k], f"{where}.{k}", out, rtol)
        return
    if isinstance(a, list) and isinstance(b, list):
        if len(a) != len(b):
            out.append(f"{where}: length {len(a)} -> {len(b)}")
            return
        for i, (x, y) in enumerate(zip(a, b)):
            _diff(x, y, f"{where}[{i}]", out, rtol)
        return
    if isinstance(a, float) and isinstance(b, (int, float)) and not isinstance(b, bool):
        if (math.isnan(a) and math.isnan(b)) or a == b:
            return
        if abs(a - b) <= rtol * max(abs(a), abs(b), 1e-300):
            return
    if a != b:
        out.append(f"{where}: {str(a)[:120]!s} -> {str(b)[:120]!s}")


def compare(before: str, after: str, rtol: float = 0.0) -> int:
    a, b = json.loads(Path(before).read_text()), json.loads(Path(after).read_text())
    out: list[str] = []
    for part in ("http", "cli", "library"):
        for x, y in zip(a[part], b[part]):
            label = x.get("name") or " ".join(x.get("argv", [])) or x.get("call")
            _diff({k: v for k, v in x.items() if k != "seconds"}, y, f"{part}:{label}", out, rtol)
    for line in out:
        print(line)
    total = sum(len(a[p]) for p in ("http", "cli", "library"))
    print(f"{total} recorded answers, {len(out)} differences (rtol {rtol})")
    return 1 if out else 0


if __name__ == "__main__":
    os.environ.setdefault("MPLBACKEND", "Agg")
    os.environ.setdefault("TENSEGRITY_JOBS_DB", str(Path(tempfile.mkdtemp()) / "jobs.sqlite3"))
    sys.path.insert(0, str(ROOT))
    verb = sys.argv[1]
    if verb == "record":
        record(sys.argv[2])
    elif verb == "replay":
        rename = json.loads(sys.argv[4]) if len(sys.argv) > 4 else None
        replay(sys.argv[2], sys.argv[3], rename)
    elif verb == "compare":
        sys.exit(compare(sys.argv[2], sys.argv[3], float(sys.argv[4]) if len(sys.argv) > 4 else 0.0))
