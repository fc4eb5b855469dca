// The gallery's read-off (plain JS, nothing fetched): hovering or tapping a chart shows the values
// under the pointer from the chart's own data, embedded beside its picture as JSON (the shape is
// documented in src/charts/readoff.rs), with crosshair lines to the axes; a click pins the
// read-off in a list it can be copied from. Pointer coordinates are mapped through the picture's
// displayed size, so it works at any zoom and on a phone.
//
// Test hooks, after `#`, joined by `&`: readoff=NAME:X[:Y][;NAME:X...] reads chart NAME off at
// x = X (and y = Y; without it, on the jam map's boundary, the sweep's first curve or the middle
// of a map's or a points chart's y axis) and pins
// it; click=NAME:X:Y clicks the displayed picture where (X, Y) is drawn, through the same
// pointer mapping as a user's click; aim=NAME:X:Y scrolls the displayed (X, Y) to the middle of
// the window and writes its window coordinates to the body's data-aim ("x,y") for a driver's
// real tap. NAME@P reads, clicks or aims at panel P (from 0, top to bottom; panel 0 without
// it). The body gets data-readoff="done" after them.
(function () {
  "use strict";

  function num(v) {
    if (typeof v === "string") return v === "" ? "none" : v;
    if (v === null || v === undefined || !isFinite(v)) return "none";
    return String(Number(v.toPrecision(5)));
  }
  // Plot space: ln for log axes, as the chart draws.
  function plot(a, v) { return a.log ? Math.log(v) : v; }
  function unplot(a, u) { return a.log ? Math.exp(u) : u; }
  // Fraction of the axis (0 at min, 1 at max) and back.
  function frac(a, v) { return (plot(a, v) - plot(a, a.min)) / (plot(a, a.max) - plot(a, a.min)); }
  function value(a, f) { return unplot(a, plot(a, a.min) + f * (plot(a, a.max) - plot(a, a.min))); }

  // ys at x, straight in plot space between samples (as the chart draws its lines); null off
  // the samples or where a neighbour has no value.
  function interp(xa, ya, xs, ys, x) {
    var u = plot(xa, x), i;
    for (i = 0; i + 1 < xs.length; i++) {
      var u0 = plot(xa, xs[i]), u1 = plot(xa, xs[i + 1]);
      if ((u0 <= u && u <= u1) || (u1 <= u && u <= u0)) {
        var y0 = ys[i], y1 = ys[i + 1];
        if (y0 === null || y1 === null) return Math.abs(u - u0) <= Math.abs(u1 - u) ? y0 : y1;
        if (u1 === u0) return y0;
        var t = (u - u0) / (u1 - u0);
        if (!ya) return y0 + t * (y1 - y0);
        return unplot(ya, plot(ya, y0) + t * (plot(ya, y1) - plot(ya, y0)));
      }
    }
    return null;
  }

  // The sample nearest x in plot space: [index, distance as a fraction of the axis].
  function nearest(xa, xs, x) {
    var best = -1, d = Infinity;
    for (var i = 0; i < xs.length; i++) {
      var e = Math.abs(frac(xa, xs[i]) - frac(xa, x));
      if (e < d) { d = e; best = i; }
    }
    return [best, d];
  }

  // Panel p's x axis: its own in a figure of panels whose x axes differ, else the chart's.
  function xAxis(c, p) { return c.panels[p].x || c.x; }

  // The read-off of chart `c` at (x, y) in panel `p`: text and the points to mark.
  function readJamMap(c, x, y) {
    var col = c.columns, xs = col[c.x.param], ya = c.panels[0].y;
    var tj = interp(c.x, ya, xs, col.theta_jam_deg, x);
    var xj = interp(c.x, null, xs, col.x_jam_mm, x);
    var reach = interp(c.x, null, xs, col.reach_deg, x);
    var st = col.status[nearest(c.x, xs, x)[0]];
    if (y === null) y = tj;
    var status = y === null ? "none"
      : reach !== null && y < reach ? "beyond_reach"
      : tj !== null && y <= tj ? "jam" : "slide";
    var d = c.disc, th = y === null ? NaN : y * Math.PI / 180;
    var pos = d.radius_mm / Math.tan(th / 2) + d.palm_offset_mm / Math.sin(th);
    var text = c.x.param + " = " + num(x) + "  theta_deg = " + num(y) + "  status = " + status +
      "  x_mm = " + num(pos) + " | boundary (" + c.model + ", " + st + "): theta_jam_deg = " +
      num(tj) + "  x_jam_mm = " + num(xj);
    var values = { model: c.model, theta_deg: y, status: status, x_mm: pos,
      boundary_status: st, theta_jam_deg: tj, x_jam_mm: xj };
    values[c.x.param] = x;
    return { text: text, panel: 0, y: y, marks: tj === null ? [] : [[0, x, tj]], values: values };
  }

  function readSweep(c, p, x, y) {
    var q = c.panels[p].quantity, parts = [], marks = [], curves = [];
    c.series.forEach(function (s) {
      var v, at = x;
      if (s.line) {
        v = interp(c.x, null, s.at, s[q], x);
      } else {
        var n = nearest(c.x, s.at, x);
        // Markers are read only within 2 % of the axis of the pointer.
        if (n[0] < 0 || n[1] > 0.02) return;
        at = s.at[n[0]];
        v = s[q][n[0]];
      }
      if (v === null || v === undefined) return;
      if (y === null) y = v;
      marks.push([p, at, v]);
      curves.push({ label: s.label, layer: s.layer, at: at, value: v });
      parts.push(s.label + ": " + q + " = " + num(v) + (at !== x ? " at " + c.x.param + " = " + num(at) : ""));
    });
    var text = c.x.param + " = " + num(x) + "  pointer " + q + " = " + num(y) + " | " +
      (parts.length ? parts.join(" | ") : "no curve here");
    var values = { quantity: q, pointer: y, curves: curves };
    values[c.x.param] = x;
    return { text: text, panel: p, y: y, marks: marks, values: values };
  }

  // The interval [i, i + 1] of sorted samples `vs` holding v in plot space, and the fraction
  // of the way across it; null outside.
  function bracket(a, vs, v) {
    var u = plot(a, v);
    for (var i = 0; i + 1 < vs.length; i++) {
      var u0 = plot(a, vs[i]), u1 = plot(a, vs[i + 1]);
      if (u0 <= u && u <= u1) return [i, u1 === u0 ? 0 : (u - u0) / (u1 - u0)];
    }
    return null;
  }

  // A map's cells read at (x, y): numbers bilinear in plot space between the four cells around
  // the point (the nearest cell's where one of them has none), texts from the nearest cell.
  function readGrid(c, x, y) {
    var g = c.grid, ya = c.panels[0].y, nx = g.x.length;
    if (y === null) y = value(ya, 0.5);
    var bx = bracket(c.x, g.x, x), by = bracket(ya, g.y, y);
    var values = { model: c.model }, parts = [];
    values[c.x.param] = x;
    values[ya.param] = y;
    Object.keys(g.cells).forEach(function (q) {
      var v = null, cells = g.cells[q];
      if (bx && by) {
        var i = bx[0], j = by[0], s = bx[1], t = by[1];
        var near = cells[(j + (t < 0.5 ? 0 : 1)) * nx + i + (s < 0.5 ? 0 : 1)];
        var k = [cells[j * nx + i], cells[j * nx + i + 1], cells[(j + 1) * nx + i], cells[(j + 1) * nx + i + 1]];
        var numeric = k.every(function (e) { return typeof e === "number"; });
        v = numeric ? (1 - t) * ((1 - s) * k[0] + s * k[1]) + t * ((1 - s) * k[2] + s * k[3]) : near;
      }
      values[q] = v;
      parts.push(q + " = " + (typeof v === "number" ? num(v) : v === null ? "none" : v));
    });
    var text = c.x.param + " = " + num(x) + "  " + ya.param + " = " + num(y) + " | " + c.model +
      ": " + parts.join("  ");
    return { text: text, panel: 0, y: y, marks: [[0, x, y]], values: values };
  }

  // A figure of stacked panels with their own x axes: every quantity of every series of the
  // panel's sweep at x, straight between samples (as drawn); the pointer's y on the panel's
  // quantity; the sweep's fixed inputs.
  function readPanels(c, p, x, y) {
    var pa = c.panels[p], s = c.sweeps[pa.sweep], q = pa.quantity;
    var parts = [], marks = [], curves = [], fixed = [];
    s.series.forEach(function (se) {
      var v = {}, texts = [];
      Object.keys(se).forEach(function (k) {
        if (!Array.isArray(se[k])) { v[k] = se[k]; return; }
        v[k] = interp(pa.x, null, s.at, se[k], x);
        texts.push(k + " = " + num(v[k]));
      });
      var at = v[q];
      if (at !== null && at !== undefined) {
        marks.push([p, x, at]);
        if (y === null) y = at;
      }
      curves.push(v);
      parts.push(se.label + ": " + texts.join("  "));
    });
    var values = { model: c.model, panel: p, quantity: q, pointer: y, curves: curves };
    values[s.param] = x;
    Object.keys(s.fixed || {}).forEach(function (k) {
      values[k] = s.fixed[k];
      var f = s.fixed[k];
      fixed.push(k + " = " + (Array.isArray(f) ? f.map(num).join(" to ") : num(f)));
    });
    // One line per series: a phone shows them without a line break inside a curve's values.
    var text = s.param + " = " + num(x) + (fixed.length ? " (" + fixed.join(", ") + ")" : "") +
      "  pointer " + q + " = " + num(y) + " | " + c.model + "\n" + parts.join("\n");
    return { text: text, panel: p, y: y, marks: marks, values: values };
  }

  // `row` as "key = value" pairs (nested objects as key.sub), nulls left out; and flat.
  function flatten(row, into, prefix) {
    Object.keys(row).forEach(function (k) {
      var v = row[k];
      if (v !== null && typeof v === "object" && !Array.isArray(v)) flatten(v, into, prefix + k + ".");
      else into[prefix + k] = v;
    });
    return into;
  }

  // A chart of discrete points whose data is a table: the point of panel p nearest the
  // pointer (distance in fractions of the plotting area), with its whole row.
  function readPoints(c, p, x, y) {
    var pa = c.panels[p], xa = xAxis(c, p), best = null, d = Infinity;
    if (y === null) y = value(pa.y, 0.5);
    pa.points.forEach(function (pt) {
      var e = Math.pow(frac(xa, pt[0]) - frac(xa, x), 2) + Math.pow(frac(pa.y, pt[1]) - frac(pa.y, y), 2);
      if (e < d) { d = e; best = pt; }
    });
    var at = (xa.param ? xa.param + " = " + num(x) + "  " : "") +
      (pa.y.param ? pa.y.param + " = " + num(y) + " | nearest: " : "");
    if (!best) return { text: at + "no point here", panel: p, y: null, marks: [], values: { panel: p } };
    var flat = flatten(c.rows[best[2]], {}, ""), parts = [];
    Object.keys(flat).forEach(function (k) {
      if (flat[k] !== null && flat[k] !== "") parts.push(k + " = " + num(flat[k]));
    });
    var values = Object.assign({ panel: p, row: best[2] }, flat);
    return { text: at + parts.join("  "), panel: p, x: best[0], y: best[1],
      marks: [[p, best[0], best[1]]], values: values, crosshair: c.crosshair };
  }

  function read(c, p, x, y) {
    if (c.kind === "points") return readPoints(c, p, x, y);
    if (c.kind === "panels") return readPanels(c, p, x, y);
    if (c.kind === "jam_map") return readJamMap(c, x, y);
    if (c.kind === "grid") return readGrid(c, x, y);
    return readSweep(c, p, x, y);
  }

  var NS = "http://www.w3.org/2000/svg";
  function el(tag, attrs) {
    var e = document.createElementNS(NS, tag);
    for (var k in attrs) e.setAttribute(k, attrs[k]);
    return e;
  }

  // Crosshair lines from the read point to the left and bottom axes, and a dot on each mark,
  // in a 1000 x 1000 viewBox stretched over the picture.
  function draw(chart, r, x) {
    var svg = chart.overlay, c = chart.data;
    while (svg.firstChild) svg.removeChild(svg.firstChild);
    if (!r || r.y === null || r.y === undefined) return;
    // A read-off of a point is drawn at the point, not at the pointer.
    if (r.x !== undefined) x = r.x;
    var f = c.panels[r.panel].frame, ya = c.panels[r.panel].y;
    var px = function (p, v) { var g = c.panels[p].frame; return 1000 * (g.left + frac(xAxis(c, p), v) * (g.right - g.left)); };
    var py = function (p, v) { var g = c.panels[p].frame; return 1000 * (g.bottom - frac(c.panels[p].y, v) * (g.bottom - g.top)); };
    var u = px(r.panel, x), w = py(r.panel, r.y);
    if (frac(ya, r.y) < 0 || frac(ya, r.y) > 1) return;
    var line = { stroke: "#e00", "stroke-width": 1.5, "vector-effect": "non-scaling-stroke", "stroke-dasharray": "4 3" };
    if (r.crosshair !== false) {
      svg.appendChild(el("line", Object.assign({ x1: u, y1: w, x2: u, y2: 1000 * f.bottom }, line)));
      svg.appendChild(el("line", Object.assign({ x1: 1000 * f.left, y1: w, x2: u, y2: w }, line)));
    }
    // A cell read (a matrix's points are cells of c.cell axis units): its outline.
    if (c.cell) {
      var x0 = px(r.panel, x - c.cell[0] / 2), x1 = px(r.panel, x + c.cell[0] / 2);
      var y0 = py(r.panel, r.y + c.cell[1] / 2), y1 = py(r.panel, r.y - c.cell[1] / 2);
      svg.appendChild(el("rect", { x: x0, y: y0, width: x1 - x0, height: y1 - y0, fill: "none",
        stroke: "#e00", "stroke-width": 2.5, "vector-effect": "non-scaling-stroke" }));
    }
    // A cell is outlined above; points and curves get a ring.
    if (!c.cell) r.marks.forEach(function (m) {
      svg.appendChild(el("ellipse", { cx: px(m[0], m[1]), cy: py(m[0], m[2]), rx: 5, ry: 5,
        fill: "none", stroke: "#e00", "stroke-width": 2, "vector-effect": "non-scaling-stroke" }));
    });
  }

  // Pins read-off `r` under the chart: its text, a copy button, and its values at full
  // precision in `data-values` (JSON) for scripts and tests.
  function pin(chart, r) {
    var li = document.createElement("li"), code = document.createElement("code");
    var b = document.createElement("button"), text = r.text;
    li.setAttribute("data-values", JSON.stringify(r.values));
    code.textContent = text;
    b.type = "button";
    b.textContent = "copy";
    b.addEventListener("click", function () {
      if (navigator.clipboard && navigator.clipboard.writeText) {
        navigator.clipboard.writeText(text).catch(function () { select(code); });
      } else {
        select(code);
      }
    });
    li.appendChild(code);
    li.appendChild(document.createTextNode(" "));
    li.appendChild(b);
    chart.pins.appendChild(li);
  }

  // Selects the text of `e`, so that Ctrl+C / the phone's copy copies it.
  function select(e) {
    var range = document.createRange();
    range.selectNodeContents(e);
    var s = window.getSelection();
    s.removeAllRanges();
    s.addRange(range);
  }

  function show(chart, r, x) {
    chart.live.textContent = r ? r.text : chart.hint;
    draw(chart, r, x);
  }

  // The panel under a pointer event and its data coordinates, or null off every plot.
  function at(chart, ev) {
    var box = chart.img.getBoundingClientRect();
    var fx = (ev.clientX - box.left) / box.width, fy = (ev.clientY - box.top) / box.height;
    var c = chart.data;
    for (var p = 0; p < c.panels.length; p++) {
      var f = c.panels[p].frame;
      if (fx >= f.left && fx <= f.right && fy >= f.top && fy <= f.bottom) {
        return [p, value(xAxis(c, p), (fx - f.left) / (f.right - f.left)),
          value(c.panels[p].y, (f.bottom - fy) / (f.bottom - f.top))];
      }
    }
    return null;
  }

  var charts = {};
  // Makes `fig` (a figure.readoff: its picture, data, overlay, live line and pins) read off
  // under the pointer. The live design page calls it again each time it draws a new chart.
  function attach(fig) {
    var chart = {
      data: JSON.parse(fig.querySelector("script.readoff-data").textContent),
      img: fig.querySelector("img"),
      overlay: fig.querySelector("svg.crosshair"),
      live: fig.querySelector(".live"),
      pins: fig.querySelector("ul.pins"),
      pinned: null,
    };
    chart.hint = chart.live.textContent;
    charts[fig.getAttribute("data-chart")] = chart;
    var wrap = fig.querySelector(".plot");
    wrap.addEventListener("pointermove", function (ev) {
      var a = at(chart, ev);
      if (a) show(chart, read(chart.data, a[0], a[1], a[2]), a[1]);
      else if (chart.pinned) show(chart, chart.pinned[0], chart.pinned[1]);
      else show(chart, null);
    });
    wrap.addEventListener("pointerleave", function () {
      if (chart.pinned) show(chart, chart.pinned[0], chart.pinned[1]);
      else show(chart, null);
    });
    wrap.addEventListener("click", function (ev) {
      var a = at(chart, ev);
      if (!a) return;
      var r = read(chart.data, a[0], a[1], a[2]);
      chart.pinned = [r, a[1]];
      show(chart, r, a[1]);
      pin(chart, r);
    });
    return chart;
  }
  document.querySelectorAll("figure.readoff").forEach(attach);
  window.jamchartReadOff = { attach: attach, read: read };

  // The test hooks (see the top of this file), once the pictures are laid out.
  window.addEventListener("load", function () {
    var hash = decodeURIComponent(location.hash.replace(/^#/, ""));
    hash.split("&").forEach(function (kv) {
      var m = /^(readoff|click|aim)=(.+)$/.exec(kv);
      if (!m) return;
      m[2].split(";").forEach(function (req) {
        var f = req.split(":"), name = f[0].split("@"), chart = charts[name[0]];
        var p = name.length > 1 ? parseInt(name[1], 10) : 0;
        if (!chart || !chart.data.panels[p]) return;
        var x = parseFloat(f[1]), y = f.length > 2 ? parseFloat(f[2]) : null;
        if (m[1] === "readoff") {
          var r = read(chart.data, p, x, y);
          chart.pinned = [r, x];
          show(chart, r, x);
          pin(chart, r);
          return;
        }
        // A real click at the displayed pixel of (x, y) in panel p.
        var c = chart.data, g = c.panels[p].frame, box = chart.img.getBoundingClientRect();
        var fx = g.left + frac(xAxis(c, p), x) * (g.right - g.left);
        var fy = g.bottom - frac(c.panels[p].y, y) * (g.bottom - g.top);
        if (m[1] === "aim") {
          window.scrollBy(0, box.top + fy * box.height - window.innerHeight / 2);
          box = chart.img.getBoundingClientRect();
          document.body.setAttribute("data-aim", (box.left + fx * box.width) + "," + (box.top + fy * box.height));
          return;
        }
        chart.img.parentNode.dispatchEvent(new MouseEvent("click", { bubbles: true,
          clientX: box.left + fx * box.width, clientY: box.top + fy * box.height }));
      });
    });
    document.body.setAttribute("data-readoff", "done");
  });
})();
