"""End-to-end: the web page in headless Chromium against a real server process.

Needs Debian's ``chromium`` and ``chromium-driver`` (``apt-get install chromium chromium-driver``) and
``selenium`` (``pip install selenium``); skipped with the reason otherwise, except in CI
(``TENSEGRITY_REQUIRE_CHROMIUM=1``, set by ``.ci/run``, which installs them): there a missing browser fails.
Override the binaries with ``CHROMIUM_BIN`` / ``CHROMEDRIVER_BIN``. One server and one browser serve every
test of this module; screenshots are written to the tests' ``tmp_path`` (``web_page.png``, ``web_page_n200.png``).
"""

from __future__ import annotations

import json
import math
import os
import shutil
import struct
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
from servers import GENEROUS_ENV, WAIT_SECONDS, clean_env, free_port, running_server, uvicorn_factory_command

import tensegrity_opt as to

HERE = Path(__file__).resolve().parent


def create_web_test_app():
    """uvicorn factory: the service's app with the page (``service.api.routes.web``) registered."""
    from starlette.routing import NoMatchFound

    from service.api.routes import web
    from service.main import create_app

    app = create_app()
    try:
        app.url_path_for("web_page")          # service.main registers it already
    except NoMatchFound:
        app.include_router(web.router)
    return app


def _binary(env: str, *names: str) -> str | None:
    for cand in (os.environ.get(env), *names):
        if cand and (found := shutil.which(cand)):
            return found
    return None


def _missing(reason: str):
    """Skip, or fail where the browser is required (CI: ``TENSEGRITY_REQUIRE_CHROMIUM=1``)."""
    if os.environ.get("TENSEGRITY_REQUIRE_CHROMIUM") == "1":
        pytest.fail(reason + " and TENSEGRITY_REQUIRE_CHROMIUM=1 requires it")
    pytest.skip(reason)


@pytest.fixture(scope="module")
def browser(tmp_path_factory):
    chromium = _binary("CHROMIUM_BIN", "chromium", "chromium-browser")
    driver_bin = _binary("CHROMEDRIVER_BIN", "chromedriver")
    if chromium is None or driver_bin is None:
        _missing("headless browser test: Chromium and chromedriver are not installed "
                 "(Debian: apt-get install chromium chromium-driver)")
    try:
        from selenium import webdriver
        from selenium.webdriver.chrome.service import Service
    except ImportError:
        _missing("headless browser test: pip install selenium")

    tmp = tmp_path_factory.mktemp("chromium")
    opts = webdriver.ChromeOptions()
    opts.binary_location = chromium
    for flag in ("--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
                 "--disable-background-networking", "--disable-component-update", "--disable-sync",
                 "--disable-dev-shm-usage", "--window-size=1280,1900", f"--user-data-dir={tmp / 'profile'}"):
        opts.add_argument(flag)
    opts.add_experimental_option("prefs", {"download.default_directory": str(tmp / "downloads"),
                                           "download.prompt_for_download": False})
    opts.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    drv = webdriver.Chrome(service=Service(executable_path=driver_bin), options=opts)
    drv.set_page_load_timeout(WAIT_SECONDS)
    drv.set_script_timeout(WAIT_SECONDS)
    try:
        yield drv
    finally:
        drv.quit()


@pytest.fixture(scope="module")
def server(browser):   # the browser first: skip before starting a server
    pytest.importorskip("httpx")
    env = clean_env(TENSEGRITY_WORKERS="2", TENSEGRITY_WARMUP="false", **GENEROUS_ENV)
    # the app factory is this module, which imports the shared helpers of tests/support
    env["PYTHONPATH"] = os.pathsep.join(filter(None, [str(HERE.parent / "support"), env.get("PYTHONPATH")]))
    cmd = uvicorn_factory_command("test_web_e2e:create_web_test_app", free_port(), "--app-dir", str(HERE))
    with running_server(cmd, env, ready="/readyz", timeout=WAIT_SECONDS) as (_, base):
        yield base


def _wait(drv, predicate, what: str, timeout: float = WAIT_SECONDS):
    from selenium.webdriver.support.ui import WebDriverWait

    return WebDriverWait(drv, timeout, poll_frequency=0.05).until(lambda d: predicate(d), message=what)


def _done(drv) -> bool:
    return drv.execute_script("return document.body.dataset.state === 'done'"
                              " && !document.getElementById('solve').disabled")


def _load(drv, server: str) -> None:
    """The page, after the solve of its defaults on load."""
    drv.get(server + "/")
    assert "chain explorer" in drv.title
    _wait(drv, _done, "the first solve")


CHAIN = {"n": "4", "a": "1", "b": "1", "k": "1", "L0": "1", "dx": "0.1", "dy": "0"}


def _fill(drv, **values: str) -> None:
    from selenium.webdriver.common.by import By

    for name, value in {**CHAIN, **values}.items():
        box = drv.find_element(By.ID, f"in-{name}")
        box.clear()
        box.send_keys(value)


def _solve(drv, **values: str) -> None:
    from selenium.webdriver.common.by import By

    _fill(drv, **values)
    drv.find_element(By.ID, "solve").click()
    _wait(drv, _done, "the solve to finish")


def _download(drv, selector: str) -> dict:
    """Click the download button ``selector``; what the page offered (name, type, size, bytes, text)."""
    import base64

    got = drv.execute_async_script("""
        const done = arguments[arguments.length - 1];
        document.addEventListener("explorer-download", async (e) => {
          const b = e.detail.blob;
          const bytes = new Uint8Array(await b.arrayBuffer());
          let bin = "";
          for (let i = 0; i < bytes.length; i += 8192)
            bin += String.fromCharCode.apply(null, bytes.subarray(i, i + 8192));
          done({name: e.detail.name, type: b.type, size: b.size, data: btoa(bin),
                text: b.type.indexOf("png") >= 0 ? null : await b.text()});
        }, {once: true});
        document.querySelector(arguments[0]).click();""", selector)
    got["bytes"] = base64.b64decode(got.pop("data"))
    assert len(got["bytes"]) == got["size"]
    return got


def _screenshot(drv, path: Path) -> int:
    """A PNG of the whole page (beyond the window, by the DevTools protocol); its size in bytes."""
    import base64

    w, h = drv.execute_script("return [document.documentElement.scrollWidth, document.documentElement.scrollHeight];")
    shot = drv.execute_cdp_cmd("Page.captureScreenshot", {
        "format": "png", "captureBeyondViewport": True, "clip": {"x": 0, "y": 0, "width": w, "height": h, "scale": 1}})
    path.write_bytes(base64.b64decode(shot["data"]))
    return path.stat().st_size


def _severe_logs(drv) -> list:
    """Script errors and blocked loads; the API's 422 answers (refusals, physical answers) may be logged."""
    return [e for e in drv.get_log("browser") if e["level"] == "SEVERE" and "422" not in e["message"]]


def test_page_in_headless_chromium(browser, server, tmp_path):
    from selenium.webdriver.common.by import By

    drv = browser
    _load(drv, server)
    # The page solves its defaults on load; then the user asks for dx = 0.3.
    dx = 0.3
    _solve(drv, dx=str(dx), dy="0")
    assert not drv.find_element(By.ID, "error").is_displayed(), drv.find_element(By.ID, "error").text

    m = to.Manipulator.uniform(4)
    eq = to.solve_equilibrium(m, dx)

    def shown(el_id: str) -> tuple[float, float]:
        el = drv.find_element(By.ID, el_id)
        return float(el.get_attribute("data-value")), float(el.text)

    for el_id, want in (("out-energy", eq.energy), ("out-fx", eq.fx), ("out-fy", eq.fy)):
        exact, text = shown(el_id)
        assert exact == pytest.approx(want, rel=1e-9, abs=1e-12), el_id
        assert text == pytest.approx(want, rel=1e-5, abs=1e-9), el_id          # 6 significant digits
    assert drv.find_element(By.ID, "out-shape").get_attribute("data-value") == eq.shape
    assert drv.find_element(By.ID, "out-stable").get_attribute("data-value") == "true"

    # The drawing: 2 triangles and 2 springs per segment, one joint each, tip on the target.
    chain = drv.find_element(By.ID, "chain")
    assert chain.get_attribute("data-dx") == str(dx)
    assert len(chain.find_elements(By.CSS_SELECTOR, "polygon.triangle")) == 2 * m.n
    springs = chain.find_elements(By.CSS_SELECTOR, "line.spring")
    assert len(springs) == 2 * m.n
    assert len(chain.find_elements(By.CSS_SELECTOR, "circle.joint")) == m.n
    assert float(chain.get_attribute("data-tip-x")) == pytest.approx(8 - dx, abs=1e-9)
    assert float(chain.get_attribute("data-tip-y")) == pytest.approx(0.0, abs=1e-9)
    c, beta = math.hypot(1, 1), math.atan2(1, 1)
    for s in springs:
        j, which = int(s.get_attribute("data-seg")), 1 if "spring-1" in s.get_attribute("class") else 2
        x1, y1, x2, y2 = (float(s.get_attribute(a)) for a in ("x1", "y1", "x2", "y2"))
        want = 2 * c * math.cos(beta + eq.q[j] / 2) if which == 1 else 2 * c * math.cos(beta - eq.q[j] / 2)
        assert math.hypot(x2 - x1, y2 - y1) == pytest.approx(want, rel=1e-9), (j, which)

    # The force-deflection curve: 60 points from 0 to dx, the buckling jump at dx -> 0+ marked; Fx and Fy
    # each on its own axis (two frames, two labels).
    curve = drv.find_element(By.ID, "curve")
    assert curve.get_attribute("data-dx") == str(dx)
    assert curve.get_attribute("data-points") == "60"
    assert len(curve.find_elements(By.CSS_SELECTOR, ".series-fx circle.pt")) == 60
    assert len(curve.find_elements(By.CSS_SELECTOR, ".series-fy circle.pt")) == 60
    assert curve.find_elements(By.CSS_SELECTOR, ".series-fx polyline")
    assert curve.find_elements(By.CSS_SELECTOR, ".series-fy polyline")
    assert len(curve.find_elements(By.CSS_SELECTOR, "rect.frame")) == 2
    assert [t.text for t in curve.find_elements(By.CSS_SELECTOR, ".label-fx, .label-fy")] == ["tip force Fx",
                                                                                             "tip force Fy"]
    assert int(curve.get_attribute("data-jumps")) >= 1 and curve.find_elements(By.CSS_SELECTOR, "circle.jump")
    # The stable straight chain buckles under compression: a compressive jump called buckling.
    jumps = drv.find_element(By.ID, "jumps").text
    assert "buckling" in jumps.split(":")[0] and "compressive" in jumps, jumps
    assert not drv.find_element(By.ID, "curve-note").is_displayed()        # a complete curve: no note

    # Buckling: the paper's three critical loads, one row and one drawing per mode.
    bk = to.critical_force(m)
    rows = drv.find_elements(By.CSS_SELECTOR, "#modes tbody tr")
    assert len(rows) == len(bk.loads) == 3
    for row, load in zip(rows, bk.loads):
        cell = row.find_elements(By.TAG_NAME, "td")[1]
        assert float(cell.get_attribute("data-value")) == pytest.approx(load, rel=1e-9)
        assert len(row.find_elements(By.CSS_SELECTOR, "svg polygon.triangle")) == 2 * m.n
    assert [r.find_elements(By.TAG_NAME, "td")[2].text for r in rows] == ["U", "ZU", "Z"]
    # The free tip changes only the buckling panel, and the page says so next to the control.
    note = drv.find_element(By.ID, "boundary-note")
    assert note.is_displayed() and "only the buckling panel" in note.text
    assert drv.find_element(By.ID, "in-boundary").get_attribute("aria-describedby") == "boundary-note"

    assert _screenshot(drv, tmp_path / "web_page.png") > 10_000

    # Downloads. JSON: the last results, as the service answered them.
    got = _download(drv, "#dl-json")
    assert got["name"] == "chain_n4_dx0.3_dy0.json" and got["type"] == "application/json"
    data = json.loads(got["text"])
    assert data["answers"]["equilibrium"]["energy"] == pytest.approx(eq.energy, rel=1e-9)
    assert data["answers"]["buckling"]["loads"] == pytest.approx(list(bk.loads), rel=1e-9)
    assert len(data["answers"]["curve"]["points"]) == 60 and data["errors"] == {}
    assert data["requests"]["curve"]["body"]["dx"] == {"start": 0, "stop": dx, "num": 60}
    assert "key" not in data["inputs"]
    # SVG: a stand-alone copy of the figure (its style sheet inside), the same 60 + 60 points.
    got = _download(drv, 'button[data-figure="curve"][data-format="svg"]')
    (tmp_path / got["name"]).write_bytes(got["bytes"])
    assert got["name"].endswith("_curve.svg") and got["type"] == "image/svg+xml"
    root = ET.fromstring(got["text"])
    ns = "{http://www.w3.org/2000/svg}"
    assert root.tag == ns + "svg" and root.find(ns + "style") is not None
    assert "--fx" in root.find(ns + "style").text
    pts = [el for el in root.iter(ns + "circle") if "pt" in el.get("class", "").split()]
    assert len(pts) == 120
    # PNG: a real PNG at twice the figure's size on screen.
    got = _download(drv, 'button[data-figure="chain"][data-format="png"]')
    assert got["name"].endswith("_chain.png") and got["type"] == "image/png" and got["size"] > 2000
    head = got["bytes"]
    (tmp_path / got["name"]).write_bytes(head)                     # to look at
    assert head[:8] == b"\x89PNG\r\n\x1a\n" and head[12:16] == b"IHDR"
    w, h = struct.unpack(">II", head[16:24])
    box = drv.execute_script("const r = document.getElementById('chain').getBoundingClientRect();"
                             "return [Math.round(r.width), Math.round(r.height)];")
    assert (w, h) == (2 * box[0], 2 * box[1])
    got = _download(drv, 'button[data-figure="equilibria-shapes"][data-format="png"]')
    assert got["bytes"][:8] == b"\x89PNG\r\n\x1a\n"
    (tmp_path / got["name"]).write_bytes(got["bytes"])

    # While a request is in flight: the previous results dimmed and marked stale, a CSS spinner (no glyph).
    busy = drv.execute_script("""
        document.getElementById("solve").click();      // submits: solve() runs up to its first await
        const p = document.getElementById("shape-panel");
        const after = getComputedStyle(p.querySelector("h2"), "::after").content;
        const sp = getComputedStyle(document.querySelector("#status .spinner"));
        return [document.body.dataset.state, p.dataset.stale,
                getComputedStyle(document.getElementById("chain")).opacity, after, sp.display, sp.animationName,
                getComputedStyle(document.getElementById("status"), "::before").content];""")
    assert busy[:2] == ["busy", "true"]
    assert float(busy[2]) < 0.6 and "stale" in busy[3]
    assert busy[4] == "inline-block" and busy[5] == "spin" and busy[6] in ("none", "normal", "")
    _wait(drv, _done, "the solve to finish")
    assert drv.execute_script("return document.getElementById('shape-panel').dataset.stale") is None
    assert float(drv.execute_script("return getComputedStyle(document.getElementById('chain')).opacity")) == 1

    # The free tip: only the buckling panel changes (the cantilever's loads), as the note says.
    from selenium.webdriver.support.ui import Select

    energy = drv.find_element(By.ID, "out-energy").get_attribute("data-value")
    Select(drv.find_element(By.ID, "in-boundary")).select_by_value("free")
    try:
        _solve(drv, dx=str(dx))
        free = to.critical_force(m, boundary="free")
        rows = drv.find_elements(By.CSS_SELECTOR, "#modes tbody tr")
        assert [float(r.find_elements(By.TAG_NAME, "td")[1].get_attribute("data-value")) for r in rows] == \
            pytest.approx(list(free.loads), rel=1e-9)
        assert "(free tip)" in drv.find_element(By.ID, "critical").text
        assert drv.find_element(By.ID, "out-energy").get_attribute("data-value") == energy
    finally:
        Select(drv.find_element(By.ID, "in-boundary")).select_by_value("guided")

    # An API refusal is shown in the error box (the target is beyond the chain's reach).
    _solve(drv, dx="100")
    box = drv.find_element(By.ID, "error")
    assert box.is_displayed()
    assert "unreachable_target" in box.text and "field: dx" in box.text
    assert drv.find_element(By.ID, "error-title").text == "The service refused a request"
    assert drv.find_elements(By.CSS_SELECTOR, "#chain polygon.triangle") == []
    _screenshot(drv, tmp_path / "web_page_error.png")
    assert not _severe_logs(drv)


def test_long_chain_fits_the_window(browser, server, tmp_path):
    """n = 200: the sign strings and the angle list wrap or scroll inside their boxes, the document does not
    grow wider than the window."""
    from selenium.webdriver.common.by import By

    drv = browser
    _load(drv, server)
    _solve(drv, n="200")
    assert not drv.find_element(By.ID, "error").is_displayed(), drv.find_element(By.ID, "error").text
    # Every panel rendered for n = 200 (not an empty page that trivially fits).
    assert len(drv.find_elements(By.CSS_SELECTOR, "#chain polygon.triangle")) == 400
    assert drv.find_element(By.ID, "out-q").text.count(",") == 199
    assert drv.find_element(By.ID, "curve").get_attribute("data-points") == "60"
    assert int(drv.find_element(By.ID, "equilibria-summary").get_attribute("data-count")) >= 2
    rows = drv.find_elements(By.CSS_SELECTOR, "#modes tbody tr")
    assert 1 <= len(rows) <= 12 and "modes are listed" in drv.find_element(By.ID, "modes-note").text
    widths = drv.execute_script("return [document.documentElement.scrollWidth, window.innerWidth,"
                                " document.body.scrollWidth];")
    assert widths[0] <= widths[1] and widths[2] <= widths[1], widths
    # A narrower window (one column under 800 px): still no horizontal overflow.
    size = drv.get_window_size()
    try:
        drv.set_window_size(760, size["height"])
        narrow = drv.execute_script("return [document.documentElement.scrollWidth, window.innerWidth];")
        assert narrow[1] < 800 and narrow[0] <= narrow[1], narrow
    finally:
        drv.set_window_size(size["width"], size["height"])
    assert _screenshot(drv, tmp_path / "web_page_n200.png") > 10_000
    assert not _severe_logs(drv)


def test_unstable_straight_chain_is_a_result(browser, server, tmp_path):
    """a = 0.5, L0 = 0.5: K = k (b L0 - 2 (b^2 - a^2)) = 0.5 - 1.5 = -1 <= 0 (condition (4)): the straight chain is
    unstable unloaded. The buckling panel says so as a result; no error box."""
    from selenium.webdriver.common.by import By

    drv = browser
    _load(drv, server)
    _solve(drv, a="0.5", L0="0.5")
    err = drv.find_element(By.ID, "error")
    assert not err.is_displayed(), err.text
    crit = drv.find_element(By.ID, "critical")
    assert crit.get_attribute("data-kind") == "result" and crit.get_attribute("data-code") == "straight_unstable"
    text = crit.text
    assert "straight chain is unstable unloaded" in text and "no buckling load" in text and "snaps" in text
    assert "K = " in text and "= -1 <= 0" in text                           # the service's K, as computed above
    assert not drv.find_element(By.ID, "modes").is_displayed()
    # Neutral colour: not the error box's red text.
    colour = drv.execute_script("return getComputedStyle(document.getElementById('critical')).color")
    err_colour = drv.execute_script("return getComputedStyle(document.getElementById('error')).color")
    assert colour != err_colour
    # The shape panel still shows the (bent) least-energy stable equilibrium; the curve's first jump leaves the
    # straight chain towards a tensile force: not called buckling.
    assert drv.find_element(By.ID, "out-stable").get_attribute("data-value") == "true"
    jumps = drv.find_element(By.ID, "jumps").text
    assert "buckling" not in jumps and "tensile" in jumps, jumps
    _screenshot(drv, tmp_path / "web_page_unstable.png")


def test_every_equilibrium_is_listed(browser, server):
    """The paper's chain at dx = 0.1 is bistable: two mirror-image stable U shapes, and saddles between."""
    from selenium.webdriver.common.by import By

    drv = browser
    _load(drv, server)
    _solve(drv, dx="0.1")
    assert not drv.find_element(By.ID, "error").is_displayed(), drv.find_element(By.ID, "error").text
    m = to.Manipulator.uniform(4)
    least = to.solve_equilibrium(m, 0.1)          # a second method: the least-energy stable minimisation
    rows = drv.find_elements(By.CSS_SELECTOR, "#equilibria tbody tr")
    assert len(rows) >= 4
    cells = [[td.text for td in r.find_elements(By.TAG_NAME, "td")] for r in rows]
    energies = [float(r.find_elements(By.TAG_NAME, "td")[1].get_attribute("data-value")) for r in rows]
    assert energies == sorted(energies)
    stable = [c for c in cells if c[4] == "yes"]
    assert len(stable) == 2 and all(c[2] == "0" and c[5] == least.shape for c in stable)
    assert energies[0] == pytest.approx(least.energy, rel=1e-7) == energies[1]
    # Mirror images: the two stable shapes' joint signs are opposite.
    flip = str.maketrans("+-", "-+")
    assert stable[0][6] == stable[1][6].translate(flip)
    assert all(int(c[2]) > 0 and c[4] == "no" for c in cells[2:])          # the rest: saddles or maxima
    summary = drv.find_element(By.ID, "equilibria-summary")
    assert summary.get_attribute("data-count") == str(len(rows)) and summary.get_attribute("data-stable") == "2"
    # One centre line per equilibrium in the drawing, dashed (unstable) for the saddles.
    shapes = drv.find_element(By.ID, "equilibria-shapes")
    assert len(shapes.find_elements(By.CSS_SELECTOR, "polyline.centre-line")) == len(rows)
    assert len(shapes.find_elements(By.CSS_SELECTOR, "g.centre.unstable")) == len(rows) - 2


def test_a_curve_resting_on_a_stop_is_drawn_whole(browser, server, tmp_path):
    """n = 4, a = b = k = L0 = 1, dx up to 4: past dx ~ 3.12 joint 3 rests on its stop, and the stable branch goes
    on there to dx = 4 (the curve used to end at 3.15). The page draws every point the service computed, marks no
    end and shows no error. (A curve that does end is drawn as in ``test_contract_partial_curve_is_drawn``.)"""
    import httpx
    from selenium.webdriver.common.by import By

    drv = browser
    _load(drv, server)
    _solve(drv, dx="4")
    assert not drv.find_element(By.ID, "error").is_displayed(), drv.find_element(By.ID, "error").text
    _screenshot(drv, tmp_path / "web_page_dx4.png")
    body = {"manipulator": {"n": 4, "a": 1, "b": 1, "k": 1, "L0": 1}, "dx": {"start": 0, "stop": 4, "num": 60},
            "dy": 0, "branch": "stable"}
    r = httpx.post(server + "/v1/force-deflection", json=body, timeout=WAIT_SECONDS)
    assert r.status_code == 200, r.text
    out = r.json()
    assert out["success"] is True and len(out["points"]) == 60 and out["ended_at"] is None
    curve = drv.find_element(By.ID, "curve")
    assert curve.get_attribute("data-complete") == "true"
    assert curve.get_attribute("data-points") == "60"
    assert len(curve.find_elements(By.CSS_SELECTOR, ".series-fx circle.pt")) == 60
    assert not curve.find_elements(By.CSS_SELECTOR, "line.branch-end")


def test_contract_partial_curve_is_drawn(browser, server):
    """The page's side of the curves contract, before the service implements it: the curve request is answered
    (in the browser, by a stand-in for ``fetch``) with the real points up to where the stable branch ends plus
    ``success: false``, ``ended_at``, ``message`` and jump ``label``s; the page draws those points, shows the note,
    marks the end and lists the jumps by their labels. Also an error status whose body has ``points``."""
    import httpx
    from selenium.webdriver.common.by import By

    drv = browser
    _load(drv, server)
    man = {"n": 4, "a": 1, "b": 1, "k": 1, "L0": 1}
    dxs = [4 * i / 59 for i in range(60)]                    # the page's request: {start: 0, stop: 4, num: 60}
    end = 3.18644                                            # where the service finds no stable equilibrium
    kept = [d for d in dxs if d < 3.1]
    r = httpx.post(server + "/v1/force-deflection", json={"manipulator": man, "dx": kept, "dy": 0},
                   timeout=WAIT_SECONDS)
    assert r.status_code == 200, r.text
    real = r.json()
    stop = next(d for d in dxs if d >= 3.1)
    note = (f"The stable branch ends between dx = {kept[-1]:.4g} and dx = {stop:.4g} (dy = 0): no stable "
            f"equilibrium at dx = {stop:.4g}; {len(kept)} of 60 points computed.")
    label = "buckling of the straight chain: F_x 0 -> -0.573 (compressive)"
    fake = dict(real, success=False, status="no_stable_equilibrium", requested=60, message=note,
                ended_at={"success": False, "status": "no_stable_equilibrium", "message": note, "dx": stop, "dy": 0},
                jumps=[dict(j, label=label) for j in real["jumps"]])
    assert real["jumps"] and end > stop
    for status in (200, 422):
        drv.execute_script("""
            const [fake, status] = arguments;
            window.__fetch = window.__fetch || window.fetch;
            window.fetch = (url, opts) => String(url).indexOf("force-deflection") >= 0
              ? Promise.resolve(new Response(JSON.stringify(fake),
                                             {status, headers: {"Content-Type": "application/json"}}))
              : window.__fetch(url, opts);""", fake, status)
        try:
            _solve(drv, dx="3")
        finally:
            drv.execute_script("window.fetch = window.__fetch;")
        curve = drv.find_element(By.ID, "curve")
        assert curve.get_attribute("data-complete") == "false", status
        assert curve.get_attribute("data-points") == str(len(kept)), status
        assert len(curve.find_elements(By.CSS_SELECTOR, ".series-fx circle.pt")) == len(kept)
        shown = drv.find_element(By.ID, "curve-note")
        assert shown.is_displayed() and note in shown.text, (status, shown.text)
        assert len(curve.find_elements(By.CSS_SELECTOR, "line.branch-end")) == 2        # in the Fx and Fy panels
        items = drv.find_elements(By.CSS_SELECTOR, "#jumps li.jump-item")
        assert len(items) == len(real["jumps"]) and all(li.text.startswith(label) for li in items)
        assert not drv.find_element(By.ID, "error").is_displayed(), drv.find_element(By.ID, "error").text
