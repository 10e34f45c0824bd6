"""The numerics' building blocks: named layouts, the per-thread cache, the one build helper."""

import json
import os
import subprocess
import sys
import textwrap
import threading

import numpy as np
import pytest

from tensegrity_opt.numerics import Layout, buckling_design_nlp, build, preload_nlp, stiffness_nlp
from tensegrity_opt.numerics.design_nlp import tril_size
from tensegrity_opt.numerics.per_thread import per_thread


# ----------------------------------------------------------------------------- layouts
def test_layout_packs_and_unpacks_by_name():
    lay = Layout(q=3, F=2, norm=(), tip=2)
    assert lay.size == len(lay) == 8 and lay["q"] == slice(0, 3) and lay["norm"] == 5
    x = lay.pack(q=[1.0, 2.0, 3.0], F=[4.0, 5.0], norm=6.0, tip=-1.0)
    assert x.tolist() == [1, 2, 3, 4, 5, 6, -1, -1]
    parts = lay.unpack(x)
    assert parts["q"].tolist() == [1, 2, 3] and parts["norm"] == 6.0 and parts["tip"].tolist() == [-1, -1]
    rows = np.vstack([x, 2 * x])                         # rows unpack block by block
    assert lay.unpack(rows)["F"].tolist() == [[4, 5], [8, 10]] and lay.unpack(rows)["norm"].tolist() == [6, 12]
    with pytest.raises(ValueError, match="missing"):
        lay.pack(q=[1, 2, 3], F=[0, 0], norm=1.0)
    with pytest.raises(ValueError, match="unknown"):
        lay.pack(q=[1, 2, 3], F=[0, 0], norm=1.0, tip=0.0, extra=1.0)
    with pytest.raises(ValueError):
        lay.pack(q=[1, 2], F=[0, 0], norm=1.0, tip=0.0)   # a block of the wrong size
    with pytest.raises(ValueError):
        lay.unpack(np.zeros(7))


@pytest.mark.parametrize("n", [2, 4])
def test_each_design_nlp_names_every_variable_row_and_parameter(n):
    """The layouts cover the NLP's vectors exactly (sizes counted here from the problems' definitions)."""
    m = tril_size(n)
    for nlp, nx, ng, npar in [
        (preload_nlp(n), 3 * n + 1 + m, n + 3 + m + 3 * n, 6 * n + 2 + 5 + 3),
        (stiffness_nlp(n), 3 * n + 1 + m + 2 * n + 1, n + 3 + m + 2 * n + n + 3 + 3 + 4, 6 * n + 2 + 3 + 3 + 2 + 2),
        (buckling_design_nlp(n, False), 4 * n + 1 + m, m + 5 + 2 * n, n + 2),
    ]:
        assert (nlp.variables.size, nlp.constraints.size, nlp.parameters.size) == (nx, ng, npar)
        assert (nlp.solver.nnz_in("x0"), nlp.solver.nnz_in("lbg"), nlp.solver.nnz_in("p")) == (nx, ng, npar)
        floor = nlp.factor_floor
        assert floor.size == nlp.variables.unpack(np.zeros(nx))["L"].size
        assert np.all(floor[nlp.diag] == 0.0) and np.sum(np.isinf(floor)) == floor.size - len(nlp.diag)


def test_stiffness_rows_unpack_to_the_named_blocks():
    """The K rows read through the layout are the stiffness rows of the NLP (K + s and K - s around K)."""
    n = 3
    nlp = stiffness_nlp(n)
    rng = np.random.default_rng(1)
    x = nlp.variables.pack(phi=rng.uniform(-0.3, 0.3, n), L10=1.0, L20=1.1, mu=0.01, L=0.5, Y=rng.normal(size=2 * n),
                           s=0.25)
    p = nlp.parameters.pack(a=1.0, b=1.0, k1=1.0, k2=1.0, F=[0.0, 0.0], L0nom=1.0, Kd=0.0, w=0.0, eig=0.0,
                            scales=[1.0, 1.0])
    g = nlp.constraints.unpack(nlp.rows(x, p))
    np.testing.assert_allclose(g["K_lo"] - g["K_hi"], 0.5, atol=1e-12)
    np.testing.assert_allclose(g["q"], np.diff(np.concatenate([[0.0], x[nlp.variables["phi"]]])), atol=1e-15)
    assert g["angle"] == pytest.approx(x[nlp.variables["phi"]][-1])


# ----------------------------------------------------------------------------- the per-thread cache
def test_per_thread_cache_is_bounded_and_never_shared_between_threads():
    calls = []

    @per_thread(maxsize=3, built=lambda v: calls.append(("built", v[0])))
    def make(k):
        calls.append(k)
        return [k]

    a = make(1)
    assert make(1) is a and calls == [1, ("built", 1)]
    for k in (2, 3, 4):                                  # 1 is the least recently used: evicted
        make(k)
    assert make(1) is not a
    make(2)
    assert make(4) is make(4)
    other = {}
    t = threading.Thread(target=lambda: other.setdefault("v", make(4)))
    t.start()
    t.join()
    assert other["v"] == [4] and other["v"] is not make(4)   # the other thread built its own


# ----------------------------------------------------------------------------- the build helper
_CHILD = textwrap.dedent("""
    import json, warnings
    warnings.simplefilter("always")
    with warnings.catch_warnings(record=True) as caught:
        from tensegrity_opt.numerics import build, kernels
        from tensegrity_opt.numerics.inverse_statics import inverse_statics
        from tensegrity_opt.numerics.path_system import path_system
        modes = [kernels.build(3).mode, path_system(3).mode, inverse_statics(3, True).mode, kernels.build(3).mode]
    print(json.dumps({"modes": modes, "warnings": [str(w.message) for w in caught],
                      "libraries": sorted(build.libraries())}))
""")


def _child(tmp_path, **env):
    e = {**os.environ, "TENSEGRITY_CACHE_DIR": str(tmp_path / "cache"), **env}
    r = subprocess.run([sys.executable, "-c", _CHILD], env=e, capture_output=True, text=True, timeout=600)
    assert r.returncode == 0, r.stderr
    return json.loads(r.stdout.strip().splitlines()[-1])


def test_every_compiled_part_falls_back_with_one_warning_per_process(tmp_path):
    got = _child(tmp_path, TENSEGRITY_COMPILE="off")
    assert got["modes"] == ["virtual machine"] * 4
    assert len(got["warnings"]) == 1 and "TENSEGRITY_COMPILE=off" in got["warnings"][0], got["warnings"]
    assert got["libraries"] == ["tensegrity_inverse_n3a", "tensegrity_kernels_n3", "tensegrity_paths_n3"]


@pytest.mark.slow                                       # three libraries compiled from scratch (~20 s)
@pytest.mark.skipif(build.compiler() is None, reason="no C compiler on this machine (or TENSEGRITY_COMPILE=0)")
def test_every_compiled_part_is_compiled_once_into_the_cache(tmp_path):
    got = _child(tmp_path, TENSEGRITY_COMPILE="1")
    assert got["modes"] == ["compiled"] * 4 and not got["warnings"]
    libs = sorted(p.name.rsplit("_", 1)[0] for p in (tmp_path / "cache").glob("*.so"))
    assert libs == ["tensegrity_inverse_n3a", "tensegrity_kernels_n3", "tensegrity_paths_n3"]
