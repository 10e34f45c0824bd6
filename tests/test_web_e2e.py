"""End-to-end: the web page in headless Chromium against a real server process.

Needs Debian's ``chromium`` and ``chromium-driver`` (``apt-get install chromium chromium-driver``) and
``selenium`` (``pip install selenium``); skipped with the reason otherwise. Override the binaries with
``CHROMIUM_BIN`` / ``CHROMEDRIVER_BIN``. The screenshot is written to ``tmp_path / "web_page.png"``.
"""

from __future__ import annotations

import math
import os
import shutil
from pathlib import Path

import pytest

import tensegrity_opt as to
from servers import clean_env, free_port, running_server, uvicorn_factory_command

HERE = Path(__file__).resolve().parent


def create_web_test_app():
    """uvicorn factory: the service's app with the page (``service.routes.web``) registered."""
    from starlette.routing import NoMatchFound

    from service.main import create_app
    from service.routes import web

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


@pytest.fixture
def server():
    pytest.importorskip("httpx")
    env = clean_env(TENSEGRITY_WORKERS="2", TENSEGRITY_WARMUP="false")
    cmd = uvicorn_factory_command("test_web_e2e:create_web_test_app", free_port(), "--app-dir", str(HERE))
    with running_server(cmd, env, ready="/readyz", timeout=30) as (_, base):
        yield base


@pytest.fixture
def browser(tmp_path):
    chromium = _binary("CHROMIUM_BIN", "chromium", "chromium-browser")
    driver_bin = _binary("CHROMEDRIVER_BIN", "chromedriver")
    if chromium is None or driver_bin is None:
        pytest.skip("headless browser test: Chromium and chromedriver are not installed "
                    "(Debian: apt-get install chromium chromium-driver)")
    webdriver = pytest.importorskip("selenium.webdriver", reason="headless browser test: pip install selenium")
    from selenium.webdriver.chrome.service import Service

    opts = webdriver.ChromeOptions()
    opts.binary_location = chromium
    for flag in ("--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
                 "--disable-background-networking", "--disable-component-update", "--disable-sync",
                 "--disable-dev-shm-usage", "--window-size=1280,1900", f"--user-data-dir={tmp_path / 'profile'}"):
        opts.add_argument(flag)
    opts.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    drv = webdriver.Chrome(service=Service(executable_path=driver_bin), options=opts)
    drv.set_page_load_timeout(30)
    try:
        yield drv
    finally:
        drv.quit()


def _wait(drv, predicate, what: str, timeout: float = 30.0):
    from selenium.webdriver.support.ui import WebDriverWait

    return WebDriverWait(drv, timeout, poll_frequency=0.05).until(lambda d: predicate(d), message=what)


def _solve(drv, **values: str) -> None:
    from selenium.webdriver.common.by import By

    for name, value in values.items():
        box = drv.find_element(By.ID, f"in-{name}")
        box.clear()
        box.send_keys(value)
    drv.find_element(By.ID, "solve").click()
    _wait(drv, lambda d: d.execute_script("return document.body.dataset.state") == "done"
          and d.find_element(By.ID, "solve").is_enabled(), "the solve to finish")


def test_page_in_headless_chromium(browser, server, tmp_path):   # browser first: skip before starting a server
    from selenium.webdriver.common.by import By

    drv = browser
    drv.get(server + "/")
    assert "chain explorer" in drv.title
    # The page solves its defaults on load; then the user asks for dx = 0.3.
    _wait(drv, lambda d: d.execute_script("return document.body.dataset.state") == "done", "the first solve")
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

    # The force-deflection curve: 60 points from 0 to dx, the buckling jump at dx -> 0+ marked.
    curve = drv.find_element(By.ID, "curve")
    assert curve.get_attribute("data-dx") == str(dx)
    assert curve.get_attribute("data-points") == "60"
    assert len(curve.find_elements(By.CSS_SELECTOR, ".series-fx circle.pt")) == 60
    assert curve.find_elements(By.CSS_SELECTOR, ".series-fx polyline")
    assert curve.find_elements(By.CSS_SELECTOR, ".series-fy polyline")
    assert int(curve.get_attribute("data-jumps")) >= 1 and curve.find_elements(By.CSS_SELECTOR, "circle.jump")
    assert "buckling" in drv.find_element(By.ID, "jumps").text

    # Buckling: the paper's three critical loads, one row and one drawing per mode.
    bk = to.critical_force(m)
    rows = drv.find_elements(By.CSS_SELECTOR, "#modes tbody tr")
    assert len(rows) == len(bk.loads) == 3
    for row, load in zip(rows, bk.loads):
        cell = row.find_elements(By.TAG_NAME, "td")[1]
        assert float(cell.get_attribute("data-value")) == pytest.approx(load, rel=1e-9)
        assert len(row.find_elements(By.CSS_SELECTOR, "svg polygon.triangle")) == 2 * m.n
    assert [r.find_elements(By.TAG_NAME, "td")[2].text for r in rows] == ["U", "ZU", "Z"]

    shot = tmp_path / "web_page.png"
    assert drv.save_screenshot(str(shot)) and shot.stat().st_size > 10_000

    # An API refusal is shown in the error box (the target is beyond the chain's reach).
    _solve(drv, dx="100")
    box = drv.find_element(By.ID, "error")
    assert box.is_displayed()
    assert "unreachable_target" in box.text and "field: dx" in box.text
    assert drv.find_elements(By.CSS_SELECTOR, "#chain polygon.triangle") == []
    drv.save_screenshot(str(tmp_path / "web_page_error.png"))

    # No script errors, no blocked (external) loads: only the API's 422 answers may be logged.
    logs = [e for e in drv.get_log("browser") if e["level"] == "SEVERE" and "422" not in e["message"]]
    assert not logs, logs
