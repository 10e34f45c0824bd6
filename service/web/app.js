/* tensegrity-opt chain explorer: plain JavaScript, no dependencies, no network beyond this server.
 *
 * Calls POST v1/equilibrium, v1/force-deflection and v1/buckling (URLs relative to the page) and
 * draws the results in SVG. Geometry (docs: conventions.md): the base half-link b_1 runs along +x
 * from the origin to joint 1 at (b_1, 0); absolute link angles phi_j = q_1 + ... + q_j; the link
 * after joint j has length b_j + b_{j+1} (the last one b_n). Each segment is two rigid triangles
 * (half-height a, half-length b) with their apexes at the joint; spring 1 joins their outer
 * vertices on the +a side (length 2c cos(beta + q/2)), spring 2 those on the -a side.
 */
"use strict";

(function () {
  const CURVE_POINTS = 60;
  let runId = 0;

  const $ = (id) => document.getElementById(id);
  // The SVG namespace, taken from an inline <svg> of the page (no URL string in this file).
  let SVGNS = null;

  function svgEl(tag, attrs, parent) {
    const el = document.createElementNS(SVGNS, tag);
    for (const [k, v] of Object.entries(attrs || {})) el.setAttribute(k, String(v));
    if (parent) parent.appendChild(el);
    return el;
  }

  function clearSvg(svg, message) {
    // Keep <title> and <desc> (accessible name and description).
    for (const child of Array.from(svg.childNodes)) {
      if (!(child.nodeName === "title" || child.nodeName === "desc")) svg.removeChild(child);
    }
    if (message) {
      // A placeholder in the middle of the (emptied) drawing.
      const vb = (svg.getAttribute("viewBox") || "0 0 100 100").split(/[\s,]+/).map(Number);
      svg.setAttribute("viewBox", "0 0 640 " + Math.round(640 * vb[3] / vb[2]));
      svgEl("text", { class: "placeholder", x: 320, y: Math.round(320 * vb[3] / vb[2]), "text-anchor": "middle" },
        svg).textContent = message;
    }
  }

  function fmt(v, digits) {
    if (v === null || v === undefined || !Number.isFinite(Number(v))) return "n/a";
    const x = Number(v);
    if (x === 0) return "0";
    const s = x.toPrecision(digits || 6);
    return s.indexOf("e") >= 0 ? s : String(Number(s));
  }

  function setNumber(id, v) {
    const el = $(id);
    el.textContent = fmt(v);
    el.dataset.value = String(v);
  }

  // ---------------------------------------------------------------- inputs and API

  function numberOrNull(id) {
    const text = $(id).value.trim();
    if (text === "") return null;          // the API names the missing field
    const x = Number(text);
    return Number.isFinite(x) ? x : null;
  }

  function readInputs() {
    const manipulator = {
      n: numberOrNull("in-n"), a: numberOrNull("in-a"), b: numberOrNull("in-b"),
      k: numberOrNull("in-k"), L0: numberOrNull("in-L0"),
    };
    return {
      manipulator,
      dx: numberOrNull("in-dx"),
      dy: numberOrNull("in-dy"),
      boundary: $("in-boundary").value,
      key: $("in-key").value,
    };
  }

  class ApiError extends Error {
    constructor(httpStatus, body) {
      super((body && body.message) || ("HTTP " + httpStatus));
      this.httpStatus = httpStatus;
      this.code = (body && body.code) || "http_error";
      this.field = (body && body.field) || null;
      this.solverStatus = (body && body.status) || null;
    }
  }

  async function api(path, body, key) {
    const headers = { "Content-Type": "application/json", "Accept": "application/json" };
    if (key) headers["X-API-Key"] = key;
    let response;
    try {
      response = await fetch(path, { method: "POST", headers, body: JSON.stringify(body) });
    } catch (err) {
      throw new ApiError(0, { code: "network_error", message: "could not reach the service (" + err.message + ")" });
    }
    let data = null;
    try {
      data = await response.json();
    } catch (err) {
      if (response.ok) throw new ApiError(response.status, { code: "bad_response", message: "the answer is not JSON" });
    }
    if (!response.ok) {
      throw new ApiError(response.status, data && typeof data === "object" ? data
        : { code: "http_error", message: "HTTP " + response.status + " " + response.statusText });
    }
    return data;
  }

  // ---------------------------------------------------------------- errors and status

  function clearErrors() {
    $("error-list").textContent = "";
    $("error").hidden = true;
  }

  function showError(what, err) {
    const li = document.createElement("li");
    li.className = "error-item";
    li.dataset.code = err.code || "error";
    const head = document.createElement("strong");
    head.textContent = what + ": ";
    li.appendChild(head);
    const code = document.createElement("code");
    code.textContent = err.code || "error";
    li.appendChild(code);
    let tail = " " + (err.message || String(err));
    if (err.field) tail += " (field: " + err.field + ")";
    if (err.solverStatus) tail += " [solver: " + err.solverStatus + "]";
    if (err.httpStatus) tail += " \u2014 HTTP " + err.httpStatus;
    li.appendChild(document.createTextNode(tail));
    $("error-list").appendChild(li);
    $("error").hidden = false;
  }

  function setStatus(text) {
    $("status").textContent = text;
  }

  // ---------------------------------------------------------------- geometry

  /** Points of the chain at joint angles q for segments [{a, b}, ...] (model units, y up). */
  function chainGeometry(q, segs) {
    const n = q.length;
    let phi = 0;                              // direction of the link before the current joint
    let P = [segs[0].b, 0];                   // joint 1
    const joints = [], triangles = [], springs = [], path = [[0, 0]];
    for (let j = 0; j < n; j++) {
      const a = segs[j].a, b = segs[j].b;
      const u0 = [Math.cos(phi), Math.sin(phi)], n0 = [-u0[1], u0[0]];
      const phiNext = phi + q[j];
      const u1 = [Math.cos(phiNext), Math.sin(phiNext)], n1 = [-u1[1], u1[0]];
      const inA = [P[0] - b * u0[0] + a * n0[0], P[1] - b * u0[1] + a * n0[1]];
      const inB = [P[0] - b * u0[0] - a * n0[0], P[1] - b * u0[1] - a * n0[1]];
      const outA = [P[0] + b * u1[0] + a * n1[0], P[1] + b * u1[1] + a * n1[1]];
      const outB = [P[0] + b * u1[0] - a * n1[0], P[1] + b * u1[1] - a * n1[1]];
      triangles.push({ seg: j, side: "in", pts: [P, inA, inB] });
      triangles.push({ seg: j, side: "out", pts: [P, outA, outB] });
      springs.push({ seg: j, which: 1, p: inA, q: outA });
      springs.push({ seg: j, which: 2, p: inB, q: outB });
      joints.push(P);
      path.push(P);
      const len = b + (j < n - 1 ? segs[j + 1].b : 0);
      P = [P[0] + len * u1[0], P[1] + len * u1[1]];
      phi = phiNext;
    }
    path.push(P);
    return { joints, triangles, springs, path, tip: P };
  }

  function segmentsOf(manipulator, n) {
    const segs = [];
    for (let j = 0; j < n; j++) segs.push({ a: manipulator.a, b: manipulator.b });
    return segs;
  }

  const pt = (p) => p[0] + "," + (-p[1]);   // SVG y points down: draw (x, -y)

  /** Draw the chain into svg (cleared). opts: {target: [x, y], stable: bool, small: bool}. */
  function drawChain(svg, q, segs, opts) {
    opts = opts || {};
    clearSvg(svg);
    const g = chainGeometry(q, segs);
    const amax = Math.max(...segs.map((s) => s.a));
    const bmin = Math.min(...segs.map((s) => s.b));
    const all = [[0, 0], [0, 1.3 * amax], [0, -1.3 * amax], g.tip];
    for (const t of g.triangles) all.push(...t.pts);
    if (opts.target) all.push(opts.target);
    const xs = all.map((p) => p[0]), ys = all.map((p) => p[1]);
    const pad = 0.25 * Math.max(amax, bmin);
    const x0 = Math.min(...xs) - pad, x1 = Math.max(...xs) + pad;
    const y0 = Math.min(...ys) - pad, y1 = Math.max(...ys) + pad;
    svg.setAttribute("viewBox", [x0, -y1, x1 - x0, y1 - y0].map((v) => v.toFixed(6)).join(" "));

    const root = svgEl("g", { class: "chain " + (opts.stable === false ? "unstable" : "stable") }, svg);
    // Ground at the base.
    const ground = svgEl("g", { class: "ground" }, root);
    const h = 1.3 * amax, step = h / 3;
    svgEl("line", { x1: 0, y1: -h, x2: 0, y2: h }, ground);
    for (let y = -h; y < h - 1e-9; y += step) {
      svgEl("line", { x1: 0, y1: y + step, x2: -0.6 * step, y2: y + 0.4 * step }, ground);
    }
    // Centre line through the joints.
    svgEl("polyline", { class: "link", points: g.path.map(pt).join(" ") }, root);
    for (const t of g.triangles) {
      svgEl("polygon", { class: "triangle tri-" + t.side, "data-seg": t.seg, points: t.pts.map(pt).join(" ") }, root);
    }
    for (const s of g.springs) {
      const len = Math.hypot(s.q[0] - s.p[0], s.q[1] - s.p[1]);
      const line = svgEl("line", {
        class: "spring spring-" + s.which, "data-seg": s.seg, "data-length": len,
        x1: s.p[0], y1: -s.p[1], x2: s.q[0], y2: -s.q[1],
      }, root);
      if (!opts.small) svgEl("title", {}, line).textContent = "segment " + (s.seg + 1) + ", spring " + s.which +
        ": length " + fmt(len, 5);
    }
    const amin = Math.min(...segs.map((s) => s.a));
    const r = 0.08 * Math.min(bmin, 1.5 * amin);
    g.joints.forEach((p, j) => {
      const c = svgEl("circle", { class: "joint", cx: p[0], cy: -p[1], r }, root);
      if (!opts.small) svgEl("title", {}, c).textContent = "joint " + (j + 1) + ": q = " + fmt(q[j], 5) + " rad";
    });
    svgEl("circle", { class: "tip", cx: g.tip[0], cy: -g.tip[1], r: 0.7 * r }, root);
    if (opts.target) {
      const t = opts.target, d = 1.6 * r;
      const tg = svgEl("g", { class: "target" }, root);
      svgEl("line", { x1: t[0] - d, y1: -t[1] - d, x2: t[0] + d, y2: -t[1] + d }, tg);
      svgEl("line", { x1: t[0] - d, y1: -t[1] + d, x2: t[0] + d, y2: -t[1] - d }, tg);
    }
    svg.dataset.tipX = String(g.tip[0]);
    svg.dataset.tipY = String(g.tip[1]);
    return g;
  }

  // ---------------------------------------------------------------- equilibrium

  function renderEquilibrium(eq, inp) {
    const n = eq.q.length;
    const segs = segmentsOf(inp.manipulator, n);
    const L = 2 * segs.reduce((s, x) => s + x.b, 0);
    const svg = $("chain");
    drawChain(svg, eq.q, segs, { target: [L - inp.dx, inp.dy], stable: eq.stable });
    svg.dataset.dx = String(inp.dx);
    svg.dataset.dy = String(inp.dy);
    $("chain-desc").textContent = "Chain of " + n + " segments at dx = " + fmt(inp.dx) + ", dy = " + fmt(inp.dy) +
      ": shape " + eq.shape + ", " + (eq.stable ? "stable" : "unstable") + ", energy " + fmt(eq.energy) + ".";
    setNumber("out-energy", eq.energy);
    setNumber("out-fx", eq.force.fx);
    setNumber("out-fy", eq.force.fy);
    $("out-shape").textContent = eq.shape + " (signs " + eq.signs + ")";
    $("out-shape").dataset.value = eq.shape;
    const st = $("out-stable");
    st.textContent = (eq.stable ? "stable" : "unstable") + " \u2014 " + eq.kind + ", Morse index " + eq.morse_index;
    st.dataset.value = String(eq.stable);
    st.className = eq.stable ? "ok" : "bad";
    $("out-q").textContent = "[" + eq.q.map((v) => fmt(v, 5)).join(", ") + "]";
    const tiny = (v) => (Math.abs(v) < 1e-12 * L ? 0 : v);   // round-off of a straight chain
    $("out-tip").textContent = "(" + fmt(tiny(eq.tip[0])) + ", " + fmt(tiny(eq.tip[1])) + ")";
    $("out-solver").textContent = eq.solver.status + ", " + eq.solver.iterations + " iterations";
  }

  function clearEquilibrium() {
    const svg = $("chain");
    clearSvg(svg, "no equilibrium to draw (see the message above)");
    delete svg.dataset.dx;
    $("chain-desc").textContent = "No equilibrium.";
    for (const id of ["out-energy", "out-fx", "out-fy", "out-shape", "out-stable", "out-q", "out-tip", "out-solver"]) {
      $(id).textContent = "\u2013";
      delete $(id).dataset.value;
      $(id).className = "";
    }
  }

  // ---------------------------------------------------------------- force-deflection chart

  function niceStep(span, count) {
    const raw = span / Math.max(count, 1);
    const mag = Math.pow(10, Math.floor(Math.log10(raw)));
    const r = raw / mag;
    return (r <= 1 ? 1 : r <= 2 ? 2 : r <= 2.5 ? 2.5 : r <= 5 ? 5 : 10) * mag;
  }

  function ticks(lo, hi, count) {
    const step = niceStep(hi - lo, count);
    const out = [];
    for (let v = Math.ceil(lo / step - 1e-9) * step; v <= hi + step * 1e-9; v += step) out.push(Math.abs(v) < step * 1e-9 ? 0 : v);
    return out;
  }

  /** Smallest dx at which (dx, dy) is reachable for a uniform chain (the reach from joint 1 is (2n - 1) b). */
  function dxMin(inp) {
    const R = (2 * inp.manipulator.n - 1) * inp.manipulator.b;
    const dy = Math.abs(inp.dy);
    if (!Number.isFinite(R) || dy === 0 || dy > R) return 0;
    return R - Math.sqrt(R * R - dy * dy);
  }

  function curveRequest(inp) {
    let start = 0;
    if (inp.dy) {
      // At dx = dxMin the chain is fully stretched (singular): start one step inside the reachable range.
      const m = dxMin(inp);
      start = m + (inp.dx - m) / CURVE_POINTS;
    }
    const dx = inp.dx === start ? [start] : { start, stop: inp.dx, num: CURVE_POINTS };
    return { manipulator: inp.manipulator, dx, dy: inp.dy, branch: "stable" };
  }

  function renderCurve(out, inp) {
    const svg = $("curve");
    clearSvg(svg);
    const W = 640, H = 360, ml = 64, mr = 16, mt = 16, mb = 48;
    const pts = out.points;
    svg.dataset.points = String(pts.length);
    svg.dataset.jumps = String(out.jumps.length);
    svg.dataset.dx = String(inp.dx);
    const dxs = pts.map((p) => p.dx).concat([inp.dx]);
    const fs = [0];
    for (const p of pts) fs.push(p.fx, p.fy);
    for (const j of out.jumps) fs.push(j.force_before.fx, j.force_before.fy, j.force_after.fx, j.force_after.fy);
    const finite = (v) => Number.isFinite(v);
    let xlo = Math.min(0, ...dxs.filter(finite)), xhi = Math.max(0, ...dxs.filter(finite));
    let ylo = Math.min(...fs.filter(finite)), yhi = Math.max(...fs.filter(finite));
    if (xhi - xlo < 1e-12) { xlo -= 0.5; xhi += 0.5; }
    if (yhi - ylo < 1e-12) { ylo -= 0.5; yhi += 0.5; }
    const ypad = 0.06 * (yhi - ylo);
    ylo -= ypad; yhi += ypad;
    const X = (v) => ml + (v - xlo) / (xhi - xlo) * (W - ml - mr);
    const Y = (v) => mt + (yhi - v) / (yhi - ylo) * (H - mt - mb);

    const axes = svgEl("g", { class: "axes" }, svg);
    for (const t of ticks(xlo, xhi, 6)) {
      svgEl("line", { class: "grid", x1: X(t), y1: mt, x2: X(t), y2: H - mb }, axes);
      svgEl("text", { x: X(t), y: H - mb + 16, "text-anchor": "middle" }, axes).textContent = fmt(t, 4);
    }
    for (const t of ticks(ylo, yhi, 6)) {
      svgEl("line", { class: "grid", x1: ml, y1: Y(t), x2: W - mr, y2: Y(t) }, axes);
      svgEl("text", { x: ml - 6, y: Y(t) + 4, "text-anchor": "end" }, axes).textContent = fmt(t, 4);
    }
    if (ylo < 0 && yhi > 0) svgEl("line", { class: "zero", x1: ml, y1: Y(0), x2: W - mr, y2: Y(0) }, axes);
    svgEl("rect", { class: "frame", x: ml, y: mt, width: W - ml - mr, height: H - mt - mb }, axes);
    svgEl("text", { class: "label", x: (ml + W - mr) / 2, y: H - 10, "text-anchor": "middle" }, axes).textContent =
      "tip deflection dx" + (inp.dy ? " (dy = " + fmt(inp.dy) + ")" : "");
    svgEl("text", { class: "label", x: 14, y: (mt + H - mb) / 2, "text-anchor": "middle",
      transform: "rotate(-90 14 " + (mt + H - mb) / 2 + ")" }, axes).textContent = "tip force";

    // The chosen dx.
    svgEl("line", { class: "selected", x1: X(inp.dx), y1: mt, x2: X(inp.dx), y2: H - mb }, svg);

    // Curves: a polyline per run of points on the same branch (a jump breaks the line).
    const jumpAt = new Set(out.jumps.map((j) => j.dx_after));
    for (const comp of ["fx", "fy"]) {
      const g = svgEl("g", { class: "series series-" + comp }, svg);
      let run = [];
      const flush = () => {
        if (run.length > 1) svgEl("polyline", { points: run.join(" ") }, g);
        run = [];
      };
      pts.forEach((p, i) => {
        if (i > 0 && (p.branch !== pts[i - 1].branch || jumpAt.has(p.dx))) flush();
        if (finite(p[comp])) run.push(X(p.dx).toFixed(2) + "," + Y(p[comp]).toFixed(2));
      });
      flush();
      for (const p of pts) {
        if (!finite(p[comp])) continue;
        const c = svgEl("circle", { class: "pt" + (p.stable ? "" : " pt-unstable"), cx: X(p.dx), cy: Y(p[comp]), r: 2.2 }, g);
        svgEl("title", {}, c).textContent = comp + " = " + fmt(p[comp]) + " at dx = " + fmt(p.dx) + " (" + p.shape + ")";
      }
    }
    // Jumps: dashed connectors from the force before to the force after, with a marker.
    const jg = svgEl("g", { class: "jumps" }, svg);
    for (const j of out.jumps) {
      for (const comp of ["fx", "fy"]) {
        const xa = X(j.dx_before), ya = Y(j.force_before[comp]), xb = X(j.dx_after), yb = Y(j.force_after[comp]);
        if (Math.abs(ya - yb) < 0.5 && Math.abs(xa - xb) < 0.5) continue;
        svgEl("line", { class: "jump-line", x1: xa, y1: ya, x2: xb, y2: yb }, jg);
      }
      const m = svgEl("circle", { class: "jump", cx: X(j.dx_after), cy: Y(j.force_after.fx), r: 5 }, jg);
      svgEl("title", {}, m).textContent = j.kind + " between dx = " + fmt(j.dx_before) + " and " + fmt(j.dx_after);
    }
    $("curve-desc").textContent = "Fx and Fy against dx from " + fmt(pts.length ? pts[0].dx : 0) + " to " +
      fmt(inp.dx) + ", " + pts.length + " points, " + out.jumps.length + " jump(s).";

    const ul = $("jumps");
    ul.textContent = "";
    if (!out.jumps.length) {
      const li = document.createElement("li");
      li.textContent = "none in this range";
      ul.appendChild(li);
    }
    for (const j of out.jumps) {
      const li = document.createElement("li");
      li.className = "jump-item";
      li.textContent = j.kind.replace("_", " ") + " between dx = " + fmt(j.dx_before) + " and " + fmt(j.dx_after) +
        ": Fx " + fmt(j.force_before.fx) + " \u2192 " + fmt(j.force_after.fx) + ", Fy " + fmt(j.force_before.fy) +
        " \u2192 " + fmt(j.force_after.fy) + " (branch " + j.branch_before + " \u2192 " + j.branch_after + ")";
      ul.appendChild(li);
    }
    const body = $("curve-table").tBodies[0];
    body.textContent = "";
    for (const p of pts) {
      const tr = body.insertRow();
      for (const v of [fmt(p.dx), fmt(p.fx), fmt(p.fy), fmt(p.energy), p.shape, p.stable ? "yes" : "no"]) {
        tr.insertCell().textContent = v;
      }
    }
  }

  function clearCurve() {
    const svg = $("curve");
    clearSvg(svg, "no curve to plot (see the message above)");
    delete svg.dataset.dx;
    delete svg.dataset.points;
    delete svg.dataset.jumps;
    $("curve-desc").textContent = "No curve.";
    $("jumps").textContent = "";
    $("curve-table").tBodies[0].textContent = "";
  }

  // ---------------------------------------------------------------- buckling

  function renderBuckling(out, inp) {
    $("critical").textContent = "Critical force Fx0 = " + fmt(out.critical_force) + " (" + out.boundary + " tip)";
    $("critical").dataset.value = String(out.critical_force);
    const body = $("modes").tBodies[0];
    body.textContent = "";
    const beta = Math.atan2(inp.manipulator.a, inp.manipulator.b);
    const qAmp = Math.min(0.35, 0.45 * (Math.PI - 2 * beta));
    out.modes.forEach((m, i) => {
      const tr = body.insertRow();
      tr.className = "mode-row";
      tr.insertCell().textContent = String(i + 1);
      const load = tr.insertCell();
      load.textContent = fmt(m.load);
      load.dataset.value = String(m.load);
      tr.insertCell().textContent = m.shape;
      tr.insertCell().textContent = m.signs;
      const st = tr.insertCell();
      st.textContent = m.stable ? "yes" : "no";
      st.className = m.stable ? "ok" : "bad";
      tr.insertCell().textContent = fmt(m.energy_factor);
      const cell = tr.insertCell();
      const qmax = Math.max(...m.q.map(Math.abs));
      if (qmax > 0) {
        const q = m.q.map((v) => v * qAmp / qmax);
        const svg = svgEl("svg", { class: "mode-drawing", role: "img", preserveAspectRatio: "xMidYMid meet" }, cell);
        svgEl("title", {}, svg).textContent = "mode " + (i + 1) + ": shape " + m.shape + " (signs " + m.signs + ")";
        drawChain(svg, q, segmentsOf(inp.manipulator, q.length), { stable: m.stable, small: true });
      }
    });
  }

  function clearBuckling() {
    $("critical").textContent = "No buckling result (see the message above).";
    delete $("critical").dataset.value;
    $("modes").tBodies[0].textContent = "";
  }

  // ---------------------------------------------------------------- solve

  async function solve(event) {
    if (event) event.preventDefault();
    const my = ++runId;
    const inp = readInputs();
    clearErrors();
    document.body.dataset.state = "busy";
    $("solve").disabled = true;
    for (const id of ["shape-panel", "curve-panel", "buckling-panel"]) $(id).setAttribute("aria-busy", "true");
    setStatus("Solving\u2026");

    const man = inp.manipulator;
    const tasks = [
      ["Equilibrium", api("v1/equilibrium", { manipulator: man, dx: inp.dx, dy: inp.dy }, inp.key),
        renderEquilibrium, clearEquilibrium],
      ["Force\u2013deflection curve", api("v1/force-deflection", curveRequest(inp), inp.key), renderCurve, clearCurve],
      ["Buckling", api("v1/buckling", { manipulator: man, boundary: inp.boundary }, inp.key),
        renderBuckling, clearBuckling],
    ];
    const results = await Promise.allSettled(tasks.map((t) => t[1]));
    if (my !== runId) return;               // a newer solve started meanwhile
    let failed = 0;
    results.forEach((res, i) => {
      const [what, , render, clear] = tasks[i];
      if (res.status === "fulfilled") {
        try {
          render(res.value, inp);
          return;
        } catch (err) {
          res = { reason: new ApiError(0, { code: "display_error", message: String(err && err.message || err) }) };
        }
      }
      failed += 1;
      clear();
      showError(what, res.reason);
    });
    for (const id of ["shape-panel", "curve-panel", "buckling-panel"]) $(id).removeAttribute("aria-busy");
    $("solve").disabled = false;
    setStatus(failed ? failed + " of 3 requests failed: see the messages above." : "Done.");
    document.body.dataset.state = "done";
  }

  function init() {
    SVGNS = $("chain").namespaceURI;
    $("controls").addEventListener("submit", solve);
    solve();
  }

  if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", init);
  else init();
})();
