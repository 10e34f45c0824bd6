/* tensegrity-opt chain explorer: plain JavaScript, no dependencies, no network beyond this server.
 *
 * Calls POST v1/equilibrium, v1/force-deflection, v1/equilibria and v1/buckling (URLs relative to the
 * page) and draws the results in SVG. Each panel shows its answer as soon as it arrives; until then the
 * previous answer stays, dimmed and marked stale. Physical answers the service gives as 422 (the
 * straight chain unstable or no equilibrium, no stable equilibrium) are shown as results in their
 * panel; only refusals and failures go to the error box. Geometry (`docs/model.md`): the base half-link b_1
 * runs along +x from the origin to joint 1 at (b_1, 0); absolute link angles phi_j = q_1 + ... + q_j; the link
 * after joint j has length b_j + b_{j+1} (the last one b_n). Each segment is two rigid triangles
 * (half-height a, half-length b) with their apexes at the joint; spring 1 joins their outer
 * vertices on the +a side (length 2c cos(beta + q/2)), spring 2 those on the -a side.
 */
"use strict";

(function () {
  const CURVE_POINTS = 60;
  const MAX_ROWS = 24;                       // table rows shown (the JSON download has them all)
  const MAX_MODE_ROWS = 12;
  const DETAIL_MAX_N = 40;                   // longer chains: small drawings show the centre line only
  const PANELS = ["shape-panel", "curve-panel", "equilibria-panel", "buckling-panel"];
  let runId = 0;
  let last = null;                           // the last solve: inputs, requests and answers (JSON download)

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
      this.body = body || null;
    }
  }

  /** Codes that say something about the chain, not about the request: shown as results. */
  const PHYSICAL = new Set(["straight_unstable", "straight_not_equilibrium", "no_equilibrium"]);
  /** Codes of a request the service will not take (bad input, limits, auth). */
  const REFUSALS = new Set(["validation_error", "invalid_parameter", "unreachable_target", "unsupported",
    "too_many_segments", "too_many_points", "too_many_steps", "response_too_large", "unauthorized",
    "body_too_large", "batch_too_large", "atlas_too_large"]);

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

  function errorTitle() {
    const codes = Array.from($("error-list").children).map((li) => li.dataset.code);
    $("error-title").textContent = codes.every((c) => REFUSALS.has(c)) ? "The service refused a request"
      : "A request failed";
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
    errorTitle();
    $("error").hidden = false;
  }

  function setStatus(text) {
    $("status-text").textContent = text;
  }

  /** A neutral result sentence in a panel (text), or hide it (null). */
  function setResult(id, text, kind) {
    const el = $(id);
    el.hidden = !text;
    el.textContent = text || "";
    if (text) el.dataset.kind = kind || "result";
    else delete el.dataset.kind;
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
    if (opts.small && segs.length > DETAIL_MAX_N) return drawCentreLines(svg, [{ g, stable: opts.stable }], segs);
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

  /** Centre lines (base, joints, tip) of several chains in one drawing: [{g, stable, colour, label}]. */
  function drawCentreLines(svg, chains, segs) {
    const amax = Math.max(...segs.map((s) => s.a));
    // Nearly flat shapes (long chains): y exaggerated by a round factor, written in the drawing.
    const px = [], py = [];
    for (const c of chains) for (const p of c.g.path) { px.push(p[0]); py.push(p[1]); }
    const xspan = Math.max(...px) - Math.min(...px), yspan = Math.max(...py.map(Math.abs)) * 2;
    let yx = 1;
    if (yspan > 0 && yspan < 0.05 * xspan) yx = Math.pow(10, Math.floor(Math.log10(0.25 * xspan / yspan)));
    if (yx > 1) {
      chains = chains.map((c) => Object.assign({}, c, { g: Object.assign({}, c.g, {
        path: c.g.path.map((p) => [p[0], yx * p[1]]), joints: c.g.joints.map((p) => [p[0], yx * p[1]]),
        tip: [c.g.tip[0], yx * c.g.tip[1]] }) }));
    }
    const all = [[0, 1.3 * amax], [0, -1.3 * amax]];
    for (const c of chains) all.push(...c.g.path);
    const xs = all.map((p) => p[0]), ys = all.map((p) => p[1]);
    const span = Math.max(Math.max(...xs) - Math.min(...xs), Math.max(...ys) - Math.min(...ys));
    const pad = 0.04 * span;
    const x0 = Math.min(...xs) - pad, x1 = Math.max(...xs) + pad;
    const y0 = Math.min(...ys) - pad, y1 = Math.max(...ys) + pad;
    svg.setAttribute("viewBox", [x0, -y1, x1 - x0, y1 - y0].map((v) => v.toFixed(6)).join(" "));
    const root = svgEl("g", { class: "chain centre-lines" }, svg);
    const ground = svgEl("g", { class: "ground" }, root);
    svgEl("line", { x1: 0, y1: -1.3 * amax, x2: 0, y2: 1.3 * amax }, ground);
    const r = 0.012 * span;
    chains.forEach((c, i) => {
      const g = svgEl("g", { class: "centre " + (c.stable === false ? "unstable" : "stable"), "data-index": i }, root);
      if (c.colour) {                      // CSSOM, not a style attribute (the page's CSP: style-src 'self')
        g.style.stroke = c.colour;
        g.style.fill = c.colour;
      }
      const line = svgEl("polyline", { class: "centre-line", points: c.g.path.map(pt).join(" ") }, g);
      if (c.label) svgEl("title", {}, line).textContent = c.label;
      if (segs.length <= DETAIL_MAX_N) {
        for (const p of c.g.joints) svgEl("circle", { class: "centre-joint", cx: p[0], cy: -p[1], r }, g);
      }
      svgEl("circle", { class: "centre-tip", cx: c.g.tip[0], cy: -c.g.tip[1], r: 1.3 * r }, g);
    });
    svg.dataset.yScale = String(yx);
    if (yx > 1) {
      svgEl("text", { class: "exaggeration", x: x0 + pad, y: -y1 + pad + 0.025 * span, "font-size": 0.025 * span },
        root).textContent = "y exaggerated " + yx + " times";
    }
    return chains.length ? chains[0].g : null;
  }

  // ---------------------------------------------------------------- equilibrium

  function renderEquilibrium(eq, inp) {
    const n = eq.q.length;
    const segs = segmentsOf(inp.manipulator, n);
    const L = 2 * segs.reduce((s, x) => s + x.b, 0);
    const svg = $("chain");
    setResult("eq-result", null);
    drawChain(svg, eq.q, segs, { target: [L - inp.dx, inp.dy], stable: eq.stable });
    svg.dataset.dx = String(inp.dx);
    svg.dataset.dy = String(inp.dy);
    $("chain-desc").textContent = "Chain of " + n + " segments at dx = " + fmt(inp.dx) + ", dy = " + fmt(inp.dy) +
      ": shape " + eq.shape + ", " + (eq.stable ? "stable" : "unstable") + ", energy " + fmt(eq.energy) + ".";
    setNumber("out-energy", eq.energy);
    setNumber("out-fx", eq.force.fx);
    setNumber("out-fy", eq.force.fy);
    $("out-shape").textContent = eq.shape + " (signs " + eq.signs + ")";
    $("out-shape").title = eq.signs;
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

  function clearEquilibrium(err) {
    const svg = $("chain");
    const physical = err && PHYSICAL.has(err.code);
    setResult("eq-result", physical ? "No stable equilibrium at this deflection: " + err.message + "." : null);
    clearSvg(svg, physical ? "no stable equilibrium to draw" : "no equilibrium to draw (see the message above)");
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

  /** A power of ten to divide the tick labels by (none for values between 0.001 and 10000). */
  function axisExponent(values) {
    const m = Math.max(...values.map(Math.abs));
    if (!(m > 0)) return 0;
    const e = Math.floor(Math.log10(m));
    return e < -2 || e > 3 ? e : 0;
  }

  function ticks(lo, hi, count) {
    const step = niceStep(hi - lo, count);
    const out = [];
    for (let v = Math.ceil(lo / step - 1e-9) * step; v <= hi + step * 1e-9; v += step) {
      out.push(Math.abs(v) < step * 1e-9 ? 0 : v);
    }
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

  // Jumps: the service's label when it gives one; else the kind and the sign of the force change
  // (fx > 0 tensile, fx < 0 compressive). Only a compressive jump off the straight chain is buckling.
  const KIND_WORDS = {
    buckling: "jump off the straight chain", leave_straight: "leaving the straight chain",
    snap: "snap to another stable branch", switch: "switch of the least-energy branch",
    branch_switch: "branch switch",
  };

  function signed(v) {
    return (v > 0 ? "+" : "") + fmt(v, 3);
  }

  function sense(v) {
    return v > 0 ? "tensile" : v < 0 ? "compressive" : "no change in Fx";
  }

  function jumpLabel(j) {
    if (j.label) return j.label;
    const d = j.delta ? j.delta.fx : j.force_after.fx - j.force_before.fx;
    if (j.kind === "buckling" && d < 0) {
      return "buckling of the straight chain: Fx " + fmt(j.force_before.fx, 3) + " \u2192 " +
        fmt(j.force_after.fx, 3) + " (compressive)";
    }
    return (KIND_WORDS[j.kind] || String(j.kind).replace(/_/g, " ")) + ": dFx = " + signed(d) + " (" + sense(d) + ")";
  }

  /** One plot area of the curve chart: axes for comp ("fx" or "fy") in the box [top, top + h]. */
  function curvePanel(svg, out, inp, comp, box, X, xlo, xhi, showX) {
    const pts = out.points;
    const { ml, mr, W, top, h } = box;
    const fs = [0];
    for (const p of pts) fs.push(p[comp]);
    for (const j of out.jumps) fs.push(j.force_before[comp], j.force_after[comp]);
    const finite = (v) => Number.isFinite(v);
    let ylo = Math.min(...fs.filter(finite)), yhi = Math.max(...fs.filter(finite));
    if (yhi - ylo < 1e-12) { ylo -= 0.5; yhi += 0.5; }
    const ypad = 0.06 * (yhi - ylo);
    ylo -= ypad; yhi += ypad;
    const Y = (v) => top + (yhi - v) / (yhi - ylo) * h;

    const axes = svgEl("g", { class: "axes axes-" + comp }, svg);
    for (const t of ticks(xlo, xhi, 6)) {
      svgEl("line", { class: "grid", x1: X(t), y1: top, x2: X(t), y2: top + h }, axes);
      if (showX) svgEl("text", { x: X(t), y: top + h + 16, "text-anchor": "middle" }, axes).textContent = fmt(t, 4);
    }
    const yt = ticks(ylo, yhi, 5);
    const ye = axisExponent(yt);
    for (const t of yt) {
      svgEl("line", { class: "grid", x1: ml, y1: Y(t), x2: W - mr, y2: Y(t) }, axes);
      svgEl("text", { x: ml - 6, y: Y(t) + 4, "text-anchor": "end" }, axes).textContent = fmt(t / Math.pow(10, ye), 4);
    }
    if (ylo < 0 && yhi > 0) svgEl("line", { class: "zero", x1: ml, y1: Y(0), x2: W - mr, y2: Y(0) }, axes);
    svgEl("rect", { class: "frame", x: ml, y: top, width: W - ml - mr, height: h }, axes);
    const yl = top + h / 2;
    svgEl("text", { class: "label label-" + comp, x: 14, y: yl, "text-anchor": "middle",
      transform: "rotate(-90 14 " + yl + ")" }, axes).textContent = "tip force " + (comp === "fx" ? "Fx" : "Fy") +
      (ye ? " (units of 1e" + ye + ")" : "");

    svgEl("line", { class: "selected", x1: X(inp.dx), y1: top, x2: X(inp.dx), y2: top + h }, svg);
    if (out.ended_at && finite(out.ended_at.dx)) {
      const xe = X(out.ended_at.dx);
      svgEl("line", { class: "branch-end", x1: xe, y1: top, x2: xe, y2: top + h }, svg);
      if (comp === "fx") {
        svgEl("text", { class: "branch-end-label", x: xe - 4, y: top + 14, "text-anchor": "end" }, svg).textContent =
          "stable branch ends";
      }
    }

    // A polyline per run of points on the same branch (a jump breaks the line).
    const jumpAt = new Set(out.jumps.map((j) => j.dx_after));
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
      const c = svgEl("circle", { class: "pt" + (p.stable ? "" : " pt-unstable"), cx: X(p.dx), cy: Y(p[comp]),
                                  r: 2.2 }, g);
      svgEl("title", {}, c).textContent = comp + " = " + fmt(p[comp]) + " at dx = " + fmt(p.dx) + " (" + p.shape + ")";
    }
    // Jumps: dashed connectors from the force before to the force after, with a marker.
    const jg = svgEl("g", { class: "jumps" }, svg);
    for (const j of out.jumps) {
      const xa = X(j.dx_before), ya = Y(j.force_before[comp]), xb = X(j.dx_after), yb = Y(j.force_after[comp]);
      if (!(Math.abs(ya - yb) < 0.5 && Math.abs(xa - xb) < 0.5)) {
        svgEl("line", { class: "jump-line", x1: xa, y1: ya, x2: xb, y2: yb }, jg);
      }
      const m = svgEl("circle", { class: "jump", cx: xb, cy: yb, r: 5 }, jg);
      svgEl("title", {}, m).textContent = jumpLabel(j) + " (between dx = " + fmt(j.dx_before) + " and " +
        fmt(j.dx_after) + ")";
    }
  }

  function renderCurve(out, inp) {
    const svg = $("curve");
    clearSvg(svg);
    const W = 640, H = 520, ml = 64, mr = 16, mt = 12, gap = 22, mb = 44;
    const h = (H - mt - gap - mb) / 2;
    svg.setAttribute("viewBox", "0 0 " + W + " " + H);
    const pts = out.points || [];
    out = Object.assign({ jumps: [] }, out, { points: pts });
    svg.dataset.points = String(pts.length);
    svg.dataset.jumps = String(out.jumps.length);
    svg.dataset.dx = String(inp.dx);
    svg.dataset.complete = String(out.success !== false);
    const finite = (v) => Number.isFinite(v);
    const dxs = pts.map((p) => p.dx).concat([inp.dx]);
    let xlo = Math.min(0, ...dxs.filter(finite)), xhi = Math.max(0, ...dxs.filter(finite));
    if (xhi - xlo < 1e-12) { xlo -= 0.5; xhi += 0.5; }
    const X = (v) => ml + (v - xlo) / (xhi - xlo) * (W - ml - mr);
    curvePanel(svg, out, inp, "fx", { ml, mr, W, top: mt, h }, X, xlo, xhi, false);
    curvePanel(svg, out, inp, "fy", { ml, mr, W, top: mt + h + gap, h }, X, xlo, xhi, true);
    svgEl("text", { class: "label", x: (ml + W - mr) / 2, y: H - 8, "text-anchor": "middle" }, svg).textContent =
      "tip deflection dx" + (inp.dy ? " (dy = " + fmt(inp.dy) + ")" : "");

    const partial = out.success === false || (out.ended_at !== undefined && out.ended_at !== null);
    let note = partial ? (out.message || (out.ended_at && out.ended_at.message) || "The curve ends early.") : null;
    if (partial && out.source_code) note += " (the service answered " + out.source_code + ")";
    setResult("curve-note", note, "partial");
    $("curve-desc").textContent = "Fx (top) and Fy (bottom) against dx from " + fmt(pts.length ? pts[0].dx : 0) +
      " to " + fmt(inp.dx) + ", " + pts.length + " points, " + out.jumps.length + " jump(s)." +
      (note ? " " + note : "");

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
      li.dataset.kind = j.kind;
      li.textContent = jumpLabel(j) + ", between dx = " + fmt(j.dx_before) + " and " + fmt(j.dx_after) +
        " (Fx " + fmt(j.force_before.fx) + " \u2192 " + fmt(j.force_after.fx) + ", Fy " + fmt(j.force_before.fy) +
        " \u2192 " + fmt(j.force_after.fy) + "; branch " + j.branch_before + " \u2192 " + j.branch_after + ")";
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

  function clearCurve(err) {
    const svg = $("curve");
    const physical = err && PHYSICAL.has(err.code);
    clearSvg(svg, physical ? "no stable curve to plot" : "no curve to plot (see the message above)");
    delete svg.dataset.dx;
    delete svg.dataset.points;
    delete svg.dataset.jumps;
    delete svg.dataset.complete;
    setResult("curve-note", physical ? "The stable branch ends before the chosen dx: " + err.message +
      " (no points were returned)." : null, "partial");
    $("curve-desc").textContent = "No curve.";
    $("jumps").textContent = "";
    $("curve-table").tBodies[0].textContent = "";
  }

  // ---------------------------------------------------------------- every equilibrium

  /** A colour per equilibrium (hue steps of the golden angle). */
  function colour(i) {
    return "hsl(" + Math.round((i * 137.508 + 210) % 360) + ", 65%, 42%)";
  }

  function renderEquilibria(out, inp) {
    const eqs = out.equilibria;
    const n = inp.manipulator.n;
    const segs = segmentsOf(inp.manipulator, n);
    const stable = eqs.filter((e) => e.stable).length;
    const summary = $("equilibria-summary");
    summary.textContent = eqs.length + " equilibri" + (eqs.length === 1 ? "um" : "a") + " (" + stable +
      " stable) at dx = " + fmt(inp.dx) + ", dy = " + fmt(inp.dy) + "; method " + out.method +
      (out.certified ? ", certified complete" : ", complete in practice, not certified") +
      (eqs.length > MAX_ROWS ? "; the first " + MAX_ROWS + " are listed and drawn (the JSON download has all)"
                             : "") + ".";
    summary.dataset.count = String(eqs.length);
    summary.dataset.stable = String(stable);
    const shown = eqs.slice(0, MAX_ROWS);
    const svg = $("equilibria-shapes");
    clearSvg(svg);
    if (shown.length) {
      drawCentreLines(svg, shown.map((e, i) => ({
        g: chainGeometry(e.q, segs), stable: e.stable, colour: colour(i),
        label: "#" + (i + 1) + ": " + e.shape + ", energy " + fmt(e.energy) + (e.stable ? ", stable" : ", unstable"),
      })), segs);
    } else {
      clearSvg(svg, "no equilibrium found");
    }
    svg.dataset.count = String(shown.length);
    $("equilibria-desc").textContent = "Centre lines of " + shown.length +
      " equilibria (solid: stable, dashed: unstable).";
    const body = $("equilibria").tBodies[0];
    body.textContent = "";
    shown.forEach((e, i) => {
      const tr = body.insertRow();
      tr.className = "eq-row";
      const num = tr.insertCell();
      const sw = document.createElement("span");
      sw.className = "swatch";
      sw.style.background = colour(i);
      num.append(sw, String(i + 1));
      const en = tr.insertCell();
      en.textContent = fmt(e.energy);
      en.dataset.value = String(e.energy);
      tr.insertCell().textContent = String(e.morse_index);
      tr.insertCell().textContent = e.kind;
      const st = tr.insertCell();
      st.textContent = e.stable ? "yes" : "no";
      st.className = e.stable ? "ok" : "bad";
      tr.insertCell().textContent = e.shape;
      const sg = tr.insertCell();
      sg.className = "signs";
      sg.textContent = e.signs;
      sg.title = e.signs;
      tr.insertCell().textContent = fmt(e.force.fx);
      tr.insertCell().textContent = fmt(e.force.fy);
    });
  }

  function clearEquilibria(err) {
    // A search that converged to no equilibrium at all is an answer too (details.found = 0).
    const none = err && (PHYSICAL.has(err.code) || (err.code === "solver_failed" && err.body && err.body.details &&
      err.body.details.found === 0));
    const summary = $("equilibria-summary");
    summary.textContent = none ? "No equilibrium found inside the physical joint range: " + err.message + "."
      : "No result (see the message above).";
    summary.dataset.count = none ? "0" : "";
    delete summary.dataset.stable;
    clearSvg($("equilibria-shapes"), none ? "no equilibrium found" : "nothing to draw");
    $("equilibria-desc").textContent = "No equilibria.";
    $("equilibria").tBodies[0].textContent = "";
    return none;
  }

  // ---------------------------------------------------------------- buckling

  function renderBuckling(out, inp) {
    const cr = $("critical");
    cr.textContent = "Critical force Fx0 = " + fmt(out.critical_force) + " (" + out.boundary + " tip)";
    cr.dataset.value = String(out.critical_force);
    cr.dataset.kind = "load";
    const body = $("modes").tBodies[0];
    body.textContent = "";
    const beta = Math.atan2(inp.manipulator.a, inp.manipulator.b);
    const qAmp = Math.min(0.35, 0.45 * (Math.PI - 2 * beta));
    const shown = out.modes.slice(0, MAX_MODE_ROWS);
    const note = $("modes-note");
    note.hidden = shown.length === out.modes.length;
    note.textContent = note.hidden ? "" : "The " + shown.length + " lowest of " + out.modes.length +
      " modes are listed (the JSON download has all).";
    $("modes").hidden = false;
    shown.forEach((m, i) => {
      const tr = body.insertRow();
      tr.className = "mode-row";
      tr.insertCell().textContent = String(i + 1);
      const load = tr.insertCell();
      load.textContent = fmt(m.load);
      load.dataset.value = String(m.load);
      tr.insertCell().textContent = m.shape;
      const sg = tr.insertCell();
      sg.className = "signs";
      sg.textContent = m.signs;
      sg.title = m.signs;
      const st = tr.insertCell();
      st.textContent = m.stable ? "yes" : "no";
      st.className = m.stable ? "ok" : "bad";
      tr.insertCell().textContent = fmt(m.energy_factor);
      const cell = tr.insertCell();
      const qmax = Math.max(...m.q.map(Math.abs));
      if (qmax > 0 && m.q.length > DETAIL_MAX_N) {
        const svg = svgEl("svg", { class: "mode-drawing profile-drawing" + (m.stable ? "" : " unstable"), role: "img",
          viewBox: "0 -1.1 " + (m.q.length - 1) + " 2.2", preserveAspectRatio: "none" }, cell);
        svgEl("title", {}, svg).textContent = "mode " + (i + 1) + ": joint angles q_i against the joint index i";
        svgEl("line", { class: "profile-zero", x1: 0, y1: 0, x2: m.q.length - 1, y2: 0 }, svg);
        svgEl("polyline", { class: "profile", points: m.q.map((v, j) => j + "," + (-v / qmax).toFixed(4)).join(" ") },
          svg);
      } else if (qmax > 0) {
        const q = m.q.map((v) => v * qAmp / qmax);
        const svg = svgEl("svg", { class: "mode-drawing", role: "img", preserveAspectRatio: "xMidYMid meet" }, cell);
        svgEl("title", {}, svg).textContent = "mode " + (i + 1) + ": shape " + m.shape + " (signs " + m.signs + ")";
        drawChain(svg, q, segmentsOf(inp.manipulator, q.length), { stable: m.stable, small: true });
      }
    });
  }

  /** The sentence for a physical answer of v1/buckling (a result, not an error). */
  function bucklingAnswer(err) {
    const why = err.message.replace(/\.$/, "");
    if (err.code === "straight_unstable") {
      return "The straight chain is unstable unloaded (joint stiffness K <= 0): no buckling load; it snaps into a " +
        "bent shape without any load. The service: " + why + ".";
    }
    if (err.code === "straight_not_equilibrium") {
      return "The straight chain is not an equilibrium: no buckling load; the chain is bent even unloaded. " +
        "The service: " + why + ".";
    }
    return "No buckling load: " + why + ".";
  }

  function clearBuckling(err) {
    const cr = $("critical");
    const physical = err && PHYSICAL.has(err.code);
    cr.textContent = physical ? bucklingAnswer(err) : "No buckling result (see the message above).";
    cr.dataset.kind = physical ? "result" : "none";
    if (physical) cr.dataset.code = err.code;
    else delete cr.dataset.code;
    delete cr.dataset.value;
    $("modes").tBodies[0].textContent = "";
    $("modes").hidden = physical;
    $("modes-note").hidden = true;
    return physical;
  }

  // ---------------------------------------------------------------- exports

  function download(name, blob) {
    const url = URL.createObjectURL(blob);
    const a = document.createElement("a");
    a.href = url;
    a.download = name;
    document.body.appendChild(a);
    a.click();
    a.remove();
    setTimeout(() => URL.revokeObjectURL(url), 60000);
    // For tests and embedding pages: what was offered for download.
    document.dispatchEvent(new CustomEvent("explorer-download", { detail: { name, blob } }));
  }

  function baseName() {
    const m = last ? last.inputs.manipulator : readInputs().manipulator;
    const d = last ? last.inputs : readInputs();
    return "chain_n" + m.n + "_dx" + d.dx + "_dy" + d.dy;
  }

  function downloadJson() {
    if (!last) return;
    const text = JSON.stringify(last, null, 2) + "\n";
    download(baseName() + ".json", new Blob([text], { type: "application/json" }));
  }

  /** A stand-alone copy of one of the page's figures: the page's style sheet inlined, white background. */
  function figureSvg(id) {
    const svg = $(id);
    const clone = svg.cloneNode(true);
    const box = svg.getBoundingClientRect();
    const w = Math.max(1, Math.round(box.width)), h = Math.max(1, Math.round(box.height));
    clone.setAttribute("xmlns", SVGNS);
    clone.setAttribute("width", String(w));
    clone.setAttribute("height", String(h));
    clone.style.background = "#ffffff";
    let css = "";
    for (const sheet of Array.from(document.styleSheets)) {
      try {
        for (const rule of Array.from(sheet.cssRules)) css += rule.cssText + "\n";
      } catch (err) { /* not readable: skip */ }
    }
    const style = document.createElementNS(SVGNS, "style");
    style.textContent = css;
    clone.insertBefore(style, clone.firstChild);
    const text = '<?xml version="1.0" encoding="utf-8"?>\n' + new XMLSerializer().serializeToString(clone) + "\n";
    return { text, w, h };
  }

  function downloadFigure(id, format) {
    const { text, w, h } = figureSvg(id);
    const name = baseName() + "_" + id + "." + format;
    if (format === "svg") {
      download(name, new Blob([text], { type: "image/svg+xml" }));
      return;
    }
    const img = new Image();
    img.onload = () => {
      const scale = 2;
      const canvas = document.createElement("canvas");
      canvas.width = w * scale;
      canvas.height = h * scale;
      const ctx = canvas.getContext("2d");
      ctx.fillStyle = "#ffffff";
      ctx.fillRect(0, 0, canvas.width, canvas.height);
      ctx.drawImage(img, 0, 0, canvas.width, canvas.height);
      canvas.toBlob((blob) => {
        if (blob) download(name, blob);
        else showError("Download PNG", new ApiError(0, { code: "display_error", message: "the browser made no PNG" }));
      }, "image/png");
    };
    img.onerror = () => showError("Download PNG", new ApiError(0, { code: "display_error",
      message: "the browser could not draw the figure" }));
    img.src = "data:image/svg+xml;charset=utf-8," + encodeURIComponent(text);
  }

  // ---------------------------------------------------------------- solve

  async function solve(event) {
    if (event) event.preventDefault();
    const my = ++runId;
    const inp = readInputs();
    clearErrors();
    document.body.dataset.state = "busy";
    $("solve").disabled = true;
    for (const id of PANELS) {
      $(id).setAttribute("aria-busy", "true");
      // The previous answer stays visible, dimmed and marked stale, until the new one arrives.
      if ($(id).dataset.filled) $(id).dataset.stale = "true";
    }
    setStatus("Solving\u2026");

    const man = inp.manipulator;
    const eqBody = { manipulator: man, dx: inp.dx, dy: inp.dy };
    const requests = {
      equilibrium: ["v1/equilibrium", eqBody],
      curve: ["v1/force-deflection", curveRequest(inp)],
      equilibria: ["v1/equilibria", eqBody],
      buckling: ["v1/buckling", { manipulator: man, boundary: inp.boundary }],
    };
    const record = { inputs: Object.assign({}, inp, { key: undefined }), requests: {}, answers: {}, errors: {} };
    const tasks = [
      ["equilibrium", "Equilibrium", "shape-panel", api("v1/equilibrium", eqBody, inp.key), renderEquilibrium,
        clearEquilibrium],
      ["curve", "Force\u2013deflection curve", "curve-panel", api("v1/force-deflection", requests.curve[1], inp.key),
        renderCurve, clearCurve],
      ["equilibria", "Every equilibrium", "equilibria-panel", api("v1/equilibria", eqBody, inp.key),
        renderEquilibria, clearEquilibria],
      ["buckling", "Buckling", "buckling-panel", api("v1/buckling", requests.buckling[1], inp.key), renderBuckling,
        clearBuckling],
    ];
    for (const [name, [path, body]] of Object.entries(requests)) record.requests[name] = { path, body };
    let failed = 0;
    await Promise.all(tasks.map(async ([name, what, panel, promise, render, clear]) => {
      let value = null, reason = null;
      try {
        value = await promise;
      } catch (err) {
        reason = err;
      }
      if (my !== runId) return;              // a newer solve started meanwhile
      // A curve refused with the points computed before it ended (older services): draw them.
      if (reason && name === "curve" && reason.body && Array.isArray(reason.body.points)) {
        value = Object.assign({ success: false, source_code: reason.httpStatus }, reason.body);
        reason = null;
      }
      if (!reason) {
        try {
          render(value, inp);
          record.answers[name] = value;
        } catch (err) {
          reason = new ApiError(0, { code: "display_error", message: String(err && err.message || err) });
        }
      }
      if (reason) {
        record.errors[name] = reason.body || { code: reason.code, message: reason.message };
        const answered = clear(reason) || PHYSICAL.has(reason.code);   // a physical answer: a result
        if (!answered) {
          failed += 1;
          showError(what, reason);
        }
      }
      $(panel).removeAttribute("aria-busy");
      delete $(panel).dataset.stale;
      $(panel).dataset.filled = "true";
    }));
    if (my !== runId) return;
    last = record;
    $("dl-json").disabled = false;
    $("solve").disabled = false;
    setStatus(failed ? failed + " of " + tasks.length + " requests failed: see the messages above." : "Done.");
    document.body.dataset.state = "done";
  }

  function init() {
    SVGNS = $("chain").namespaceURI;
    $("controls").addEventListener("submit", solve);
    $("dl-json").addEventListener("click", downloadJson);
    for (const b of document.querySelectorAll("button[data-figure]")) {
      b.addEventListener("click", () => downloadFigure(b.dataset.figure, b.dataset.format));
    }
    solve();
  }

  if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", init);
  else init();
})();
