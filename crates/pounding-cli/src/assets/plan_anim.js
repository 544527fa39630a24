// Plan-view animation of a bridge run (no library, no network): reads the JSON of
// trajectories.json embedded in the page and draws the segments at their displaced positions.
(function () {
  'use strict';
  var D = JSON.parse(document.getElementById('traj').textContent);
  var F = D.frames, n = D.segments, $ = function (id) { return document.getElementById(id); };
  var cv = $('an-plan'), gm = $('an-gm'), sl = $('an-t'), mg = $('an-mag');
  var state = { frame: 0, mag: 1, playing: false, speed: 1, zoom: null, drawn: null, markers: [] };
  // extent of the reference plan
  var xs = [], ys = [];
  D.outlines.forEach(function (o) { o.forEach(function (p) { xs.push(p[0]); ys.push(p[1]); }); });
  D.abutment_faces.forEach(function (f) { if (f) f.forEach(function (p) { xs.push(p[0]); ys.push(p[1]); }); });
  // a plan longer in y than in x is drawn turned by +90° (so that it runs across the canvas)
  var rot = Math.max.apply(null, ys) - Math.min.apply(null, ys) > Math.max.apply(null, xs) - Math.min.apply(null, xs);
  var R = function (p) { return rot ? [-p[1], p[0]] : p; }, Ri = function (p) { return rot ? [p[1], -p[0]] : p; };
  if (rot) { var t = xs.map(function (v, j) { return R([v, ys[j]]); }); xs = t.map(function (p) { return p[0]; }); ys = t.map(function (p) { return p[1]; }); }
  var x0 = Math.min.apply(null, xs), x1 = Math.max.apply(null, xs);
  var y0 = Math.min.apply(null, ys), y1 = Math.max.apply(null, ys);
  var peak = 0;
  F.forEach(function (f) { for (var i = 0; i < n; i++) peak = Math.max(peak, Math.hypot(f.q[3 * i], f.q[3 * i + 1])); });
  var ext = Math.max(x1 - x0, y1 - y0);
  var auto = 1;
  if (peak > 0) { var want = 0.04 * ext / peak; if (want > 1) { var d = Math.pow(10, Math.floor(Math.log10(want))); auto = [5, 2, 1].map(function (m) { return m * d; }).filter(function (v) { return v <= want; })[0] || 1; } }
  state.mag = auto; mg.value = auto;
  function place(i, p, q) {
    var x = trueAt(i, p, q);
    return [p[0] + state.mag * (x[0] - p[0]), p[1] + state.mag * (x[1] - p[1])];
  }
  // true (unmagnified) position of point p of segment i
  function trueAt(i, p, q) {
    var c = D.centroids[i], th = q[3 * i + 2] * Math.PI / 180, s = Math.sin(th), co = Math.cos(th);
    var rx = p[0] - c[0], ry = p[1] - c[1];
    return [c[0] + q[3 * i] + co * rx - s * ry, c[1] + q[3 * i + 1] + s * rx + co * ry];
  }
  // each seated end's displacement off its seat: max over its two corners of (p - p0).n_in
  function seatState(q) {
    return (D.seats || []).map(function (e) {
      var d = -Infinity;
      e.corners.forEach(function (p) { var x = trueAt(e.segment, p, q); d = Math.max(d, (x[0] - p[0]) * e.inward[0] + (x[1] - p[1]) * e.inward[1]); });
      return { end: e.end, support: e.support, displacement: d, remaining: e.length - d, ratio: d / e.length };
    });
  }
  var rfPeak = 0;
  (D.restrainers || []).forEach(function (r) { if (r.peak_force) rfPeak = Math.max(rfPeak, r.peak_force); });
  function view() {
    // the whole plan fits both ways (a curved plan can be as wide as it is long); a zoom fits its width
    var pad = 0.06 * ext + 1e-9, v = state.zoom || { cx: (x0 + x1) / 2, cy: (y0 + y1) / 2, w: x1 - x0 + 2 * pad, h: y1 - y0 + 2 * pad };
    var k = v.h ? Math.min(cv.width / v.w, cv.height / v.h) : cv.width / v.w;
    return function (p) { p = R(p); return [cv.width / 2 + k * (p[0] - v.cx), cv.height / 2 - k * (p[1] - v.cy)]; };
  }
  function draw() {
    var f = F[state.frame], q = f.q, T = view(), g = cv.getContext('2d');
    g.clearRect(0, 0, cv.width, cv.height);
    g.lineWidth = 1;
    // reference outlines
    g.strokeStyle = '#bbb'; g.setLineDash([4, 4]);
    D.outlines.forEach(function (o) { g.beginPath(); o.forEach(function (p, j) { var s = T(p); j ? g.lineTo(s[0], s[1]) : g.moveTo(s[0], s[1]); }); g.stroke(); });
    g.setLineDash([]);
    // abutment faces
    g.strokeStyle = '#000'; g.lineWidth = 3;
    D.abutment_faces.forEach(function (fc) { if (!fc) return; var a = T(fc[0]), b = T(fc[1]); g.beginPath(); g.moveTo(a[0], a[1]); g.lineTo(b[0], b[1]); g.stroke(); });
    // bearings: their ground points (fixed)
    g.fillStyle = '#777';
    (D.bearings || []).forEach(function (p) { var s = T(p); g.fillRect(s[0] - 2, s[1] - 2, 4, 4); });
    g.lineWidth = 1.5;
    var drawn = [];
    D.outlines.forEach(function (o, i) {
      g.beginPath(); g.fillStyle = 'rgba(70,120,200,0.35)'; g.strokeStyle = '#1f4e99';
      o.forEach(function (p, j) { var s = T(place(i, p, q)); j ? g.lineTo(s[0], s[1]) : g.moveTo(s[0], s[1]); });
      g.fill(); g.stroke();
      var c = place(i, D.centroids[i], q);
      drawn.push({ x: q[3 * i], y: q[3 * i + 1], theta_deg: q[3 * i + 2], centroid: c });
    });
    // seats: each end's seat edge, where its face would stand when it unseats (at the magnified
    // scale: the face's rest position moved by magnification × seat length inward), coloured by
    // the current ratio; the remaining seat written when zoomed (or unseated)
    var seats = seatState(q);
    (D.seats || []).forEach(function (e, j) {
      var st = seats[j], k = state.mag * e.length;
      var a = T([e.corners[0][0] + k * e.inward[0], e.corners[0][1] + k * e.inward[1]]);
      var b = T([e.corners[1][0] + k * e.inward[0], e.corners[1][1] + k * e.inward[1]]);
      g.strokeStyle = st.ratio >= 1 ? '#d00' : st.ratio >= 0.5 ? '#e80' : '#2a2';
      g.lineWidth = 2; g.setLineDash([6, 3]); g.beginPath(); g.moveTo(a[0], a[1]); g.lineTo(b[0], b[1]); g.stroke(); g.setLineDash([]);
      if (state.zoom || st.ratio >= 1) {
        g.fillStyle = g.strokeStyle; g.font = '11px sans-serif';
        g.fillText(e.end + ': ' + (st.remaining >= 0 ? st.remaining.toFixed(3) + ' m of seat left' : 'UNSEATED'), (a[0] + b[0]) / 2 + 4, (a[1] + b[1]) / 2);
      }
    });
    // restrainers: a line between the anchors, grey while slack, orange to red with tension
    var rs = [];
    (D.restrainers || []).forEach(function (r, j) {
      var fr = f.rf ? f.rf[j] : 0, pa = T(place(r.a, r.pa, q)), pb = T(place(r.b, r.pb, q));
      var x = rfPeak > 0 ? Math.min(1, Math.max(0, fr / rfPeak)) : 0;
      g.strokeStyle = fr > 0 ? 'rgb(' + Math.round(240 - 40 * x) + ',' + Math.round(160 * (1 - x)) + ',0)' : '#999';
      g.lineWidth = 1 + 3 * x; g.beginPath(); g.moveTo(pa[0], pa[1]); g.lineTo(pb[0], pb[1]); g.stroke();
      g.fillStyle = g.strokeStyle; g.beginPath(); g.arc((pa[0] + pb[0]) / 2, (pa[1] + pb[1]) / 2, 3 + 3 * x, 0, 2 * Math.PI); g.fill();
      rs.push({ joint: r.joint, force: fr, a: place(r.a, r.pa, q), b: place(r.b, r.pb, q) });
    });
    g.lineWidth = 1;
    // impacts within half a frame spacing (at least one frame) of this time
    var dt = F.length > 1 ? (F[F.length - 1].t - F[0].t) / (F.length - 1) : 0;
    var win = Math.max(dt * D.stride, dt) * 1.5, marks = [];
    D.impacts.forEach(function (im) {
      if (Math.abs(im.t - f.t) > win) return;
      var p;
      if (im.site_kind === 'joint') { var a = D.corners[im.site], b = D.corners[im.site + 1];
        var e = place(im.site, [(a[2][0] + a[3][0]) / 2, (a[2][1] + a[3][1]) / 2], q), s2 = place(im.site + 1, [(b[0][0] + b[1][0]) / 2, (b[0][1] + b[1][1]) / 2], q);
        p = [(e[0] + s2[0]) / 2, (e[1] + s2[1]) / 2];
      } else { var fc = D.abutment_faces[im.site] || [[0, 0], [0, 0]]; p = [(fc[0][0] + fc[1][0]) / 2, (fc[0][1] + fc[1][1]) / 2]; }
      marks.push({ t: im.t, site_kind: im.site_kind, site: im.site, x: p[0], y: p[1], impulse_n: im.impulse_n, peak_force: im.peak_force });
      var s = T(p); g.fillStyle = 'rgba(220,30,30,0.8)'; g.beginPath(); g.arc(s[0], s[1], 9, 0, 2 * Math.PI); g.fill();
      g.fillStyle = '#900'; g.font = '12px sans-serif';
      g.fillText(im.peak_force === null ? 'P=' + im.impulse_n.toPrecision(3) + ' N s' : 'F=' + im.peak_force.toPrecision(3) + ' N', s[0] + 10, s[1] - 10);
    });
    state.drawn = drawn; state.markers = marks; state.seats = seats; state.restrainers = rs;
    g.fillStyle = '#000'; g.font = '13px sans-serif';
    g.fillText('t = ' + f.t.toFixed(3) + ' s   displacements × ' + state.mag + (state.zoom ? '   (zoomed: double-click to reset)' : '   (click to zoom)') + (rot ? '   plan turned 90° (x up)' : ''), 8, 16);
    $('an-time').textContent = f.t.toFixed(3) + ' s';
    drawGround();
  }
  function drawGround() {
    var g = gm.getContext('2d'), w = gm.width, h = gm.height, a = 0;
    F.forEach(function (f) { a = Math.max(a, Math.abs(f.ag[0]), Math.abs(f.ag[1])); });
    a = a || 1;
    var t0 = F[0].t, t1 = F[F.length - 1].t || 1, X = function (t) { return (t - t0) / ((t1 - t0) || 1) * w; };
    g.clearRect(0, 0, w, h);
    ['#c33', '#36c'].forEach(function (col, k) {
      g.strokeStyle = col; g.beginPath();
      F.forEach(function (f, j) { var x = X(f.t), y = h / 2 - f.ag[k] / a * (h / 2 - 4); j ? g.lineTo(x, y) : g.moveTo(x, y); });
      g.stroke();
    });
    g.strokeStyle = '#000'; g.beginPath(); var cx = X(F[state.frame].t); g.moveTo(cx, 0); g.lineTo(cx, h); g.stroke();
    g.fillStyle = '#000'; g.font = '11px sans-serif'; g.fillText('ground acceleration (red x, blue y), peak ' + a.toPrecision(3) + ' m/s²', 4, 12);
  }
  function setFrame(k) { state.frame = Math.max(0, Math.min(F.length - 1, k | 0)); sl.value = state.frame; draw(); }
  function frameAt(t) { var b = 0; F.forEach(function (f, j) { if (Math.abs(f.t - t) < Math.abs(F[b].t - t)) b = j; }); return b; }
  sl.max = F.length - 1;
  sl.addEventListener('input', function () { setFrame(+sl.value); });
  mg.addEventListener('change', function () { var v = +mg.value; if (v > 0 && isFinite(v)) { state.mag = v; draw(); } });
  $('an-true').addEventListener('click', function () { state.mag = 1; mg.value = 1; draw(); });
  $('an-auto').addEventListener('click', function () { state.mag = auto; mg.value = auto; draw(); });
  $('an-speed').addEventListener('change', function () { state.speed = +$('an-speed').value; });
  var last = null;
  function tick(ts) {
    if (!state.playing) return;
    if (last !== null) {
      var t = F[state.frame].t + (ts - last) / 1000 * state.speed, k = state.frame;
      while (k < F.length - 1 && F[k + 1].t <= t) k++;
      if (k === F.length - 1) state.playing = false;
      if (k !== state.frame) setFrame(k);
    }
    last = ts; if (state.playing) requestAnimationFrame(tick); else $('an-play').textContent = 'Play';
  }
  $('an-play').addEventListener('click', function () {
    state.playing = !state.playing; $('an-play').textContent = state.playing ? 'Pause' : 'Play';
    if (state.playing) { if (state.frame === F.length - 1) setFrame(0); last = null; requestAnimationFrame(tick); }
  });
  cv.addEventListener('click', function (e) {
    var r = cv.getBoundingClientRect(), T = view(), o = T(Ri([0, 0])), u = T(Ri([1, 0])), k = u[0] - o[0];
    var px = (e.clientX - r.left) * cv.width / r.width, py = (e.clientY - r.top) * cv.height / r.height;
    var w = (state.zoom ? state.zoom.w : ext * 1.12) / 4;
    state.zoom = { cx: (px - o[0]) / k, cy: -(py - o[1]) / k, w: w }; draw();
  });
  cv.addEventListener('dblclick', function () { state.zoom = null; draw(); });
  var ev = $('an-events'), names = { first_impact: 'first impact', peak_closing: 'peak closing', peak_seat_ratio: 'peak seat ratio', unseating: 'unseating' };
  Object.keys(names).forEach(function (k) {
    var t = D.events[k]; if (t === null || t === undefined) return;
    var b = document.createElement('button'); b.textContent = names[k] + ' (' + t.toFixed(3) + ' s)';
    b.addEventListener('click', function () { setFrame(frameAt(t)); }); ev.appendChild(b);
  });
  window.poundingAnim = { state: state, data: D, setFrame: setFrame, frameAt: frameAt };
  // report.html#t=1.5 opens at that time
  var m = /[#&]t=([0-9.eE+-]+)/.exec(location.hash);
  setFrame(m ? frameAt(+m[1]) : 0);
})();
