"""``POST /v1/plots/*``: PNG and SVG answers, reproducible SVG bytes, content negotiation, refusals as JSON, the
operations documented."""

from __future__ import annotations

import warnings

import pytest

pytest.importorskip("matplotlib")

from figures import check_png, check_svg, png_size  # noqa: E402


@pytest.fixture(scope="module")
def client():
    pytest.importorskip("fastapi")
    pytest.importorskip("httpx")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        from fastapi.testclient import TestClient
    from service_helpers import service_settings

    from service.main import create_app

    app = create_app(service_settings())        # service.main registers the plot routes
    assert app.url_path_for("plot_curve") == "/v1/plots/curve"
    with TestClient(app) as c:
        yield c


M4 = {"n": 4, "a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0}
BODIES = {
    "curve": {"manipulator": M4, "dx": {"start": 0.0, "stop": 0.5, "num": 6}},
    "landscape": {"manipulator": M4, "dx": 0.1, "grid": 31},
    "shapes": {"manipulator": {"n": 3}, "dx": 0.1},
    "modes": {"manipulator": {"n": 3, "mass": 0.2}, "dx": 0.5},
    "torque": {"segments": [{"a": 1.0, "b": 1.0, "L0": 0.5}, {"a": 1.0, "b": 1.0, "k": [1.0, 2.0]}], "num": 51},
    "map": {"manipulator": M4, "param_x": "k", "values_x": {"start": 0.5, "stop": 2.0, "num": 4},
            "param_y": "L0", "values_y": [0.5, 1.0, 1.5]},
}


def test_api_and_cli_write_pngs_of_the_same_resolution(client, tmp_path):
    import tensegrity_opt as to
    from tensegrity_opt.applications import cli, plots

    r = client.post("/v1/plots/torque", json={"segments": [{"a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0}], "num": 21})
    assert r.status_code == 200, r.text
    out = tmp_path / "torque.png"
    assert cli.main(["plot", "torque", "--num", "21", "-o", str(out)]) == 0       # the same figure, its defaults
    assert png_size(r.content) == png_size(out.read_bytes())
    w, h = plots.plot_torque(to.Segment(1.0, 1.0, 1.0, 1.0), num=21).get_size_inches()
    assert png_size(r.content) == (round(w * plots.DPI), round(h * plots.DPI))


def test_branch_figure_axes_have_one_default_on_every_interface():
    import argparse
    import inspect

    from service.schemas.plots import PlotBranchRequest
    from tensegrity_opt.applications import plots
    from tensegrity_opt.applications.cli.plot import add_plot_parser

    parser = argparse.ArgumentParser()
    add_plot_parser(parser.add_subparsers(dest="command"))
    args = parser.parse_args(["plot", "branch", "-o", "b.png"])
    sig = inspect.signature(plots.plot_branches).parameters
    fields = PlotBranchRequest.model_fields
    assert (args.x, args.y) == (sig["x"].default, sig["y"].default) == (fields["x"].default, fields["y"].default) \
        == ("t", "phi")
    assert args.dpi == plots.DPI == PlotBranchRequest.model_fields["dpi"].default


def test_limit_load_figure_draws_the_buckled_arms_by_default_on_every_interface(client):
    import argparse
    import inspect

    from service.schemas.plots import PlotLimitLoadRequest
    from tensegrity_opt.applications import plots
    from tensegrity_opt.applications.cli.plot import add_plot_parser

    parser = argparse.ArgumentParser()
    add_plot_parser(parser.add_subparsers(dest="command"))
    assert parser.parse_args(["plot", "limit-load", "-o", "l.png"]).arms is True
    assert parser.parse_args(["plot", "limit-load", "--no-arms", "-o", "l.png"]).arms is False
    assert PlotLimitLoadRequest.model_fields["arms"].default is True
    assert inspect.signature(plots.plot_limit_load).parameters["arms"].default is None     # the branches, or none
    svg = {}
    for arms in (None, False):
        body = {"manipulator": M4, "format": "svg", **({} if arms is None else {"arms": arms})}
        r = client.post("/v1/plots/limit-load", json=body)
        assert r.status_code == 200, r.text
        check_svg(r.content)
        svg[arms] = r.text
    assert 'id="arm-0-morse0-0"' in svg[None] and 'id="arm-1-morse0-0"' in svg[None] and "end angle" in svg[None]
    assert 'id="arm-0' not in svg[False] and 'id="path-morse0-0"' in svg[False]


@pytest.mark.slow
@pytest.mark.parametrize("kind", list(BODIES))
def test_api_answers_png_and_svg(client, kind):
    r = client.post(f"/v1/plots/{kind}", json={**BODIES[kind], "dpi": 40})
    assert r.status_code == 200, r.text
    assert r.headers["content-type"] == "image/png"
    check_png(r.content)
    r = client.post(f"/v1/plots/{kind}", json={**BODIES[kind], "format": "svg"})
    assert r.status_code == 200 and r.headers["content-type"].startswith("image/svg+xml")
    check_svg(r.content)


@pytest.mark.slow
@pytest.mark.parametrize("kind", ["curve", "torque"])
def test_api_svg_is_byte_identical_between_identical_requests(client, kind):
    # matplotlib salts clip-path ids with a random UUID unless svg.hashsalt is set
    body = {**BODIES[kind], "format": "svg"}
    first, second = client.post(f"/v1/plots/{kind}", json=body), client.post(f"/v1/plots/{kind}", json=body)
    assert first.status_code == second.status_code == 200
    assert b"clip-path" in first.content or b"<use " in first.content
    assert first.content == second.content


@pytest.mark.slow
def test_api_content_negotiation(client):
    body = BODIES["torque"]
    r = client.post("/v1/plots/torque", json=body, headers={"Accept": "image/svg+xml"})
    assert r.headers["content-type"].startswith("image/svg+xml")
    check_svg(r.content)
    r = client.post("/v1/plots/torque", json=body, headers={"Accept": "image/png;q=0.5, image/svg+xml;q=0.9"})
    assert r.headers["content-type"].startswith("image/svg+xml")
    r = client.post("/v1/plots/torque", json=body, headers={"Accept": "image/svg+xml;q=0.2, image/png"})
    assert r.headers["content-type"] == "image/png"
    r = client.post("/v1/plots/torque", json={**body, "format": "png"}, headers={"Accept": "image/svg+xml"})
    assert r.headers["content-type"] == "image/png"                 # the body's format wins
    r = client.post("/v1/plots/torque", json=body, headers={"Accept": "*/*"})
    assert r.headers["content-type"] == "image/png"


def test_api_refusals(client):
    r = client.post("/v1/plots/landscape", json={"manipulator": {"n": 5}, "dx": 0.1})
    assert r.status_code == 422 and r.json()["code"] == "unsupported" and r.json()["field"] == "manipulator.n"
    for kind in ("landscape", "shapes"):
        r = client.post(f"/v1/plots/{kind}", json={"manipulator": M4, "dx": 20.0})
        assert r.status_code == 422 and r.json()["code"] == "unreachable_target", kind
    r = client.post("/v1/plots/curve", json={"manipulator": M4, "dx": [0.1, -2.0]})
    assert r.status_code == 422 and r.json()["code"] == "unreachable_target"
    r = client.post("/v1/plots/curve", json={**BODIES["curve"], "format": "gif"})
    assert r.status_code == 422 and r.json()["code"] == "validation_error" and r.json()["field"] == "format"
    r = client.post("/v1/plots/map", json={**BODIES["map"], "param_y": "k"})
    assert r.status_code == 422 and r.json()["code"] == "invalid_parameter" and r.json()["field"] == "param_y"
    r = client.post("/v1/plots/map", json={**BODIES["map"], "values_y": [1.0, 0.5, 2.0]})
    assert r.status_code == 422 and r.json()["field"] == "values_y"
    r = client.post("/v1/plots/shapes", json={"manipulator": {"n": 5000}, "dx": 0.1})
    assert r.status_code == 422 and r.json()["code"] == "validation_error"
    r = client.post("/v1/plots/shapes", json={"manipulator": {"n": 300}, "dx": 0.1})
    assert r.status_code == 422 and r.json()["code"] == "validation_error"      # above the default limit: schema


def test_api_is_documented(client):
    doc = client.app.openapi()
    ids = {}
    for kind in BODIES:
        op = doc["paths"][f"/v1/plots/{kind}"]["post"]
        ids[kind] = op["operationId"]
        assert op["tags"] == ["plots"] and op["summary"]
        ok = op["responses"]["200"]["content"]
        assert set(ok) == {"image/png", "image/svg+xml"}
        assert op["requestBody"]["content"]["application/json"].get("examples")
        assert op.get("security") == [{"ApiKey": []}, {}]
        for status in ("401", "413", "422", "503", "504"):
            content = op["responses"][status]["content"]["application/json"]
            assert content["schema"]["$ref"] == "#/components/schemas/ErrorOut" and content.get("examples")
    assert ids == {k: f"plot_{k}" for k in BODIES}
    assert "unsupported" in doc["paths"]["/v1/plots/landscape"]["post"]["responses"]["422"]["content"][
        "application/json"]["examples"]
