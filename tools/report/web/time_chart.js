// Draws the report's time charts with uPlot (inlined before this script). Each chart's data sits in a
// <script type="application/json"> beside its <div>; tools/report/time_chart.cpp writes it: x as
// float32 seconds after x0, each series as uint16 steps of `scale` above `offset` (65535: no value),
// little-endian, base64. Drag to zoom, double-click to see the whole run; all time charts of one report
// zoom together. With #selftest in the address the page zooms its first chart by synthetic mouse
// events and writes what happened into a pre element, id mrd-selftest
// (tests/tools/report/report_in_chromium.sh).
(function () {
  "use strict";
  var errors = [];
  window.addEventListener("error", function (e) { errors.push(String(e.message)); });

  function bytes(b64) {
    var text = atob(b64), out = new Uint8Array(text.length);
    for (var i = 0; i < text.length; ++i) out[i] = text.charCodeAt(i);
    return out.buffer;
  }

  function xs(chart) {
    var rel = new Float32Array(bytes(chart.x)), out = new Float64Array(rel.length);
    for (var i = 0; i < rel.length; ++i) out[i] = chart.x0 + rel[i];
    return out;
  }

  function ys(series) {
    var q = new Uint16Array(bytes(series.q)), out = new Array(q.length);
    for (var i = 0; i < q.length; ++i) out[i] = q[i] === 65535 ? null : series.offset + series.scale * q[i];
    return out;
  }

  // Run boundaries: a dotted line each, named at the top.
  function drawMarkers(markers) {
    return function (u) {
      var ctx = u.ctx, top = u.bbox.top, bottom = u.bbox.top + u.bbox.height;
      ctx.save();
      ctx.strokeStyle = "#888888";
      ctx.fillStyle = "#444444";
      ctx.setLineDash([2, 4]);
      ctx.font = Math.round(10 * devicePixelRatio) + "px sans-serif";
      markers.forEach(function (m) {
        if (m.at < u.scales.x.min || m.at > u.scales.x.max) return;
        var x = u.valToPos(m.at, "x", true);
        ctx.beginPath();
        ctx.moveTo(x, top);
        ctx.lineTo(x, bottom);
        ctx.stroke();
        if (m.label) ctx.fillText(m.label, x + 3, top + 12 * devicePixelRatio);
      });
      ctx.restore();
    };
  }

  var charts = [], syncing = false;

  function followZoom(u, key) {
    if (key !== "x" || syncing) return;
    syncing = true;
    charts.forEach(function (other) {
      if (other !== u) other.setScale("x", { min: u.scales.x.min, max: u.scales.x.max });
    });
    syncing = false;
  }

  function draw(holder) {
    var chart = JSON.parse(holder.querySelector("script[type='application/json']").textContent);
    var target = holder.querySelector(".mrd-chart-plot");
    var series = [{ label: chart.x_label }], data = [xs(chart)];
    chart.series.forEach(function (s) {
      // Sparse values (samples set aside) as markers: a line between gaps would draw nothing.
      series.push(s.points ? { label: s.label, stroke: s.colour, fill: s.colour, width: s.width, paths: function () { return null; },
                               points: { show: true, size: 5, stroke: s.colour, fill: s.colour } }
                           : { label: s.label, stroke: s.colour, width: s.width, spanGaps: false });
      data.push(ys(s));
    });
    var u = new uPlot({
      width: Math.max(320, Math.min(960, target.clientWidth || 900)),
      height: 360,
      scales: { x: { time: false } },
      series: series,
      axes: [{ label: chart.x_label }, { label: chart.y_label, size: 70 }],
      cursor: { drag: { x: true, y: false, setScale: true } },
      hooks: { setScale: [followZoom], draw: [drawMarkers(chart.markers || [])] }
    }, data, target);
    charts.push(u);
  }

  function mouse(type, target, x, y, dx) {
    target.dispatchEvent(new MouseEvent(type, {
      bubbles: true, cancelable: true, view: window, button: 0, buttons: type === "mouseup" ? 0 : 1,
      clientX: x, clientY: y, movementX: dx || 0, movementY: 0
    }));
  }

  // Runs the steps 50 ms apart: uPlot applies a drag's moves on the next animation frame.
  function inFrames(steps) {
    if (steps.length) setTimeout(function () { steps[0](); inFrames(steps.slice(1)); }, 50);
  }

  // Drags over the middle fifth of the first chart, checks every chart shows that span, then
  // double-clicks and checks the whole run is back.
  function selftest() {
    var out = document.createElement("pre");
    out.id = "mrd-selftest";
    document.body.appendChild(out);
    if (!charts.length) { out.textContent = "selftest: FAIL no chart"; return; }
    var u = charts[0], over = u.over, r = over.getBoundingClientRect();
    var full = [u.scales.x.min, u.scales.x.max], span = full[1] - full[0], y = r.top + r.height / 2;
    var x1 = r.left + 0.4 * r.width, x2 = r.left + 0.6 * r.width, problems = [], zoomed = [];
    inFrames([
      function () { mouse("mouseenter", over, x1, y); mouse("mousemove", over, x1, y, 1); mouse("mousedown", over, x1, y); },
      function () { mouse("mousemove", over, x2, y, x2 - x1); },
      function () { mouse("mouseup", document, x2, y); },
      function () {
        var want = [full[0] + 0.4 * span, full[0] + 0.6 * span];
        charts.forEach(function (c, i) {
          if (Math.abs(c.scales.x.min - want[0]) > 0.02 * span || Math.abs(c.scales.x.max - want[1]) > 0.02 * span)
            problems.push("chart " + i + " shows " + c.scales.x.min + ".." + c.scales.x.max + " not " + want[0] + ".." + want[1]);
        });
        zoomed = [u.scales.x.min, u.scales.x.max];
        over.dispatchEvent(new MouseEvent("dblclick", { bubbles: true, cancelable: true, view: window, button: 0 }));
      },
      function () {
        charts.forEach(function (c, i) {
          if (Math.abs(c.scales.x.min - full[0]) > 1e-6 * span || Math.abs(c.scales.x.max - full[1]) > 1e-6 * span)
            problems.push("after the double-click chart " + i + " shows " + c.scales.x.min + ".." + c.scales.x.max);
        });
        problems = problems.concat(errors);
        out.textContent = problems.length ? "selftest: FAIL " + problems.join("; ")
          : "selftest: ok " + charts.length + " charts zoomed to " + zoomed[0].toFixed(4) + ".." + zoomed[1].toFixed(4) +
            " of " + full[0].toFixed(4) + ".." + full[1].toFixed(4) + " and back";
      }
    ]);
  }

  document.querySelectorAll(".mrd-chart").forEach(function (holder) {
    try { draw(holder); } catch (e) { errors.push("chart " + holder.id + ": " + e.message); }
  });
  // uPlot sets its scales in a microtask after construction: test once they are there.
  if (location.hash === "#selftest") inFrames([selftest]);
})();
