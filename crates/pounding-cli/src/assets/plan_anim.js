// Plan-view animation of a bridge run (no library, no network): reads the JSON of
// trajectories.json embedded in the page and draws the segments at their displaced positions.
//
// Magnification f: a point p0 of segment i is drawn at p0 + o_i + f (p(t) - p0), where the offsets
// o_i magnify the joint gaps by the same f (o_{k+1} - o_k = (f - 1)(S_{k+1} - E_k), S and E the
// rest midpoints of a start and an end face; the abutment faces likewise), so that a closed
// joint is drawn closed, not overlapping by (f - 1) times its gap.
(function () {
  'use strict';
  var D = JSON.parse(document.getElementById('traj').textContent);
  var F = D.frames, n = D.segments, S = D.dof_start, $ = function (id) { return document.getElementById(id); };
  var cv = $('an-plan'), gm = $('an-gm'), sl = $('an-t'), mg = $('an-mag');
  var state = { frame: 0, mag: 1, playing: false, speed: 1, zoom: null, drawn: null, markers: [], seats: [], restrainers: [], offsets: [] };
  var mid = function (a, b) { return [(a[0] + b[0]) / 2, (a[1] + b[1]) / 2]; };
  var add = function (a, b, k) { return [a[0] + k * b[0], a[1] + k * b[1]]; };
  var sub = function (a, b) { return [a[0] - b[0], a[1] - b[1]]; };
  var startMid = function (i) { return mid(D.corners[i][0], D.corners[i][1]); };
  var endMid = function (i) { return mid(D.corners[i][2], D.corners[i][3]); };
  // a plan longer in y than in x is drawn turned by +90° (so that it runs across the canvas)
  var xs = [], ys = [];
  D.outlines.forEach(function (o) { o.forEach(function (p) { xs.push(p[0]); ys.push(p[1]); }); });
  var rot = Math.max.apply(null, ys) - Math.min.apply(null, ys) > Math.max.apply(null, xs) - Math.min.apply(null, xs);
  var R = function (p) { return rot ? [-p[1], p[0]] : p; }, Ri = function (p) { return rot ? [p[1], -p[0]] : p; };
  var ext0 = Math.max(Math.max.apply(null, xs) - Math.min.apply(null, xs), Math.max.apply(null, ys) - Math.min.apply(null, ys));
  var spacing = F.length > 1 ? (F[F.length - 1].t - F[0].t) / (F.length - 1) : 0;
  var decimals = spacing > 0 ? Math.min(6, Math.max(3, Math.ceil(-Math.log10(spacing)))) : 3;
  var peak = 0;
  F.forEach(function (f) { for (var i = 0; i < n; i++) peak = Math.max(peak, Math.hypot(f.q[S[i]], f.q[S[i] + 1])); });
  // auto magnification: displacements about 4 % of the plan, a 1-2-5 value, at most 1000
  var auto = 1;
  if (peak > 0) { var want = Math.min(1000, 0.04 * ext0 / peak); if (want > 1) { var d = Math.pow(10, Math.floor(Math.log10(want))); auto = [5, 2, 1].map(function (m) { return m * d; }).filter(function (v) { return v <= want; })[0] || 1; } }
  state.mag = auto; mg.value = auto;
  // the gap offsets of each segment and abutment face at magnification f
  function offsets(f) {
    var o = [[0, 0]];
    for (var k = 0; k + 1 < n; k++) o.push(add(o[k], sub(startMid(k + 1), endMid(k)), f - 1));
    var c = mid(o[0], o[n - 1]);
    o = o.map(function (v) { return sub(v, c); });
    var ab = D.abutment_faces.map(function (fc, side) {
      if (!fc) return null;
      var i = side ? n - 1 : 0, m = side ? endMid(i) : startMid(i);
      return add(o[i], sub(mid(fc[0], fc[1]), m), f - 1);
    });
    return { seg: o, abut: ab };
  }
  // true (unmagnified) position of point p of segment i
  function trueAt(i, p, q) {
    var c = D.centroids[i], th = q[S[i] + 2] * Math.PI / 180, s = Math.sin(th), co = Math.cos(th);
    var rx = p[0] - c[0], ry = p[1] - c[1];
    return [c[0] + q[S[i]] + co * rx - s * ry, c[1] + q[S[i] + 1] + s * rx + co * ry];
  }
  var off = offsets(state.mag);
  function place(i, p, q) {
    var x = trueAt(i, p, q), o = off.seg[i];
    return [p[0] + o[0] + state.mag * (x[0] - p[0]), p[1] + o[1] + state.mag * (x[1] - p[1])];
  }
  // each seated end's displacement off its seat: max over its two corners of (p - p0).n_in
  function seatState(q) {
    return (D.seats || []).map(function (e) {
      var d = -Infinity;
      e.corners.forEach(function (p) { var x = trueAt(e.segment, p, q); d = Math.max(d, (x[0] - p[0]) * e.inward[0] + (x[1] - p[1]) * e.inward[1]); });
      return { end: e.end, support: e.support, displacement: d, remaining: e.length - d, ratio: d / e.length };
    });
  }
  // when each end that unseated left its seat (first frame beyond it, or the run's peak time)
  var unseatedAt = (D.seats || []).map(function (e, j) {
    if (!e.unseated) return null;
    for (var k = 0; k < F.length; k++) if (seatState(F[k].q)[j].ratio >= 1) return Math.min(F[k].t, e.peak_time);
    return e.peak_time;
  });
  // each frame's index by time (frames are in increasing time): the nearest frame to t
  function frameAt(t) {
    var lo = 0, hi = F.length - 1;
    while (hi - lo > 1) { var m = (lo + hi) >> 1; if (F[m].t <= t) lo = m; else hi = m; }
    return Math.abs(F[hi].t - t) < Math.abs(F[lo].t - t) ? hi : lo;
  }
  // every impact flashes in exactly one frame: its nearest (where its jump button lands)
  var impactsAt = F.map(function () { return []; });
  D.impacts.forEach(function (im) { impactsAt[frameAt(im.t)].push(im); });
  var rfPeak = 0;
  (D.restrainers || []).forEach(function (r) { if (r.peak_force) rfPeak = Math.max(rfPeak, r.peak_force); });
  function view() {
    // fit the magnified plan both ways; a zoom fits its width
    var X = [], Y = [];
    D.outlines.forEach(function (o, i) { o.forEach(function (p) { var s = R(add(p, off.seg[i], 1)); X.push(s[0]); Y.push(s[1]); }); });
    D.abutment_faces.forEach(function (fc, side) { if (fc) fc.forEach(function (p) { var s = R(add(p, off.abut[side], 1)); X.push(s[0]); Y.push(s[1]); }); });
    var x0 = Math.min.apply(null, X), x1 = Math.max.apply(null, X), y0 = Math.min.apply(null, Y), y1 = Math.max.apply(null, Y);
    var pad = 0.06 * Math.max(x1 - x0, y1 - y0) + 1e-9;
    var v = state.zoom || { cx: (x0 + x1) / 2, cy: (y0 + y1) / 2, w: x1 - x0 + 2 * pad, h: y1 - y0 + 2 * pad };
    var k = v.h ? Math.min(cv.width / v.w, cv.height / v.h) : cv.width / v.w;
    var T = function (p) { p = R(p); return [cv.width / 2 + k * (p[0] - v.cx), cv.height / 2 - k * (p[1] - v.cy)]; };
    T.inv = function (px, py) { return Ri([(px - cv.width / 2) / k + v.cx, -(py - cv.height / 2) / k + v.cy]); };
    T.w = v.w;
    return T;
  }
  // text at an anchor on the canvas (none off it), kept inside; `right`: ending at the anchor
  function label(g, text, x, y, right) {
    if (x < 0 || x > cv.width || y < 0 || y > cv.height) return;
    var w = g.measureText(text).width;
    if (right) x -= w;
    g.fillText(text, Math.min(Math.max(2, x), cv.width - w - 2), Math.min(Math.max(12, y), cv.height - 4));
  }
  function draw() {
    var f = F[state.frame], q = f.q, T = view(), g = cv.getContext('2d');
    g.clearRect(0, 0, cv.width, cv.height);
    g.lineWidth = 1;
    // reference outlines (at the magnified gaps)
    g.strokeStyle = '#bbb'; g.setLineDash([4, 4]);
    D.outlines.forEach(function (o, i) { g.beginPath(); o.forEach(function (p, j) { var s = T(add(p, off.seg[i], 1)); j ? g.lineTo(s[0], s[1]) : g.moveTo(s[0], s[1]); }); g.stroke(); });
    g.setLineDash([]);
    // abutment faces
    g.strokeStyle = '#000'; g.lineWidth = 3;
    D.abutment_faces.forEach(function (fc, side) { if (!fc) return; var a = T(add(fc[0], off.abut[side], 1)), b = T(add(fc[1], off.abut[side], 1)); g.beginPath(); g.moveTo(a[0], a[1]); g.lineTo(b[0], b[1]); g.stroke(); });
    // bearings: their ground points (fixed)
    g.fillStyle = '#777';
    (D.bearings || []).forEach(function (b) { var s = T(add(b.point, off.seg[b.segment], 1)); g.fillRect(s[0] - 2, s[1] - 2, 4, 4); });
    g.lineWidth = 1.5;
    var drawn = [];
    D.outlines.forEach(function (o, i) {
      g.beginPath(); g.fillStyle = 'rgba(70,120,200,0.35)'; g.strokeStyle = '#1f4e99';
      o.forEach(function (p, j) { var s = T(place(i, p, q)); j ? g.lineTo(s[0], s[1]) : g.moveTo(s[0], s[1]); });
      g.fill(); g.stroke();
      drawn.push({ x: q[S[i]], y: q[S[i] + 1], theta_deg: q[S[i] + 2], centroid: place(i, D.centroids[i], q) });
    });
    // seat gauges: at the middle of each seated end's face, a bar pointing off the seat whose
    // filled part is the seat left (green above half, orange below, red once unseated)
    var seats = seatState(q);
    g.font = '11px sans-serif';
    (D.seats || []).forEach(function (e, j) {
      var st = seats[j], m = place(e.segment, mid(e.corners[0], e.corners[1]), q);
      var a = T(m), b = T(add(m, e.inward, 1)), len = Math.hypot(b[0] - a[0], b[1] - a[1]) || 1;
      // at most 26 px, and at most a quarter of the segment as drawn (many short segments)
      var sa = T(startMid(e.segment)), sb = T(endMid(e.segment));
      var ux = (b[0] - a[0]) / len, uy = (b[1] - a[1]) / len, L = Math.max(4, Math.min(26, 0.25 * Math.hypot(sb[0] - sa[0], sb[1] - sa[1])));
      var gone = unseatedAt[j] !== null && f.t >= unseatedAt[j];
      var frac = gone ? 0 : Math.max(0, Math.min(1, st.remaining / e.length));
      var col = gone || st.ratio >= 1 ? '#d00' : st.ratio >= 0.5 ? '#e80' : '#2a2';
      g.strokeStyle = '#555'; g.lineWidth = 7; g.beginPath(); g.moveTo(a[0], a[1]); g.lineTo(a[0] + ux * L, a[1] + uy * L); g.stroke();
      g.strokeStyle = '#fff'; g.lineWidth = 5; g.stroke();
      g.strokeStyle = col; g.lineWidth = 5; g.beginPath(); g.moveTo(a[0], a[1]); g.lineTo(a[0] + ux * L * frac, a[1] + uy * L * frac); g.stroke();
      st.unseated = gone;
      if (gone || state.zoom) {
        g.fillStyle = col;
        var text = e.end + (gone ? ': UNSEATED' : ': ' + st.remaining.toFixed(3) + ' m of seat left');
        // beyond the gauge's tip, on its side (ending there when it points left), the two ends
        // of a joint one above the other
        label(g, text, a[0] + ux * (L + 4), a[1] + uy * (L + 4) + (ux < 0 ? -6 : 12), ux < -0.5);
      }
    });
    // restrainers: a line between the anchors, grey while slack, orange to red with tension (the
    // dot no wider than a sixth of a segment as drawn)
    var rs = [], d0 = T(startMid(0)), d1 = T(endMid(0)), dotMax = Math.max(1.5, Math.hypot(d1[0] - d0[0], d1[1] - d0[1]) / 12);
    (D.restrainers || []).forEach(function (r, j) {
      var fr = f.rf ? f.rf[j] : 0, A = place(r.a, r.pa, q), B = place(r.b, r.pb, q), pa = T(A), pb = T(B);
      var x = rfPeak > 0 ? Math.min(1, Math.max(0, fr / rfPeak)) : 0;
      g.strokeStyle = fr > 0 ? 'rgb(' + Math.round(240 - 40 * x) + ',' + Math.round(160 * (1 - x)) + ',0)' : '#999';
      g.lineWidth = 1 + 3 * x; g.beginPath(); g.moveTo(pa[0], pa[1]); g.lineTo(pb[0], pb[1]); g.stroke();
      g.fillStyle = g.strokeStyle; g.beginPath(); g.arc((pa[0] + pb[0]) / 2, (pa[1] + pb[1]) / 2, Math.min(3 + 3 * x, dotMax), 0, 2 * Math.PI); g.fill();
      rs.push({ joint: r.joint, force: fr, a: A, b: B });
    });
    g.lineWidth = 1;
    // the impacts whose nearest frame this is, one marker per site (the largest)
    var bySite = {}, marks = [];
    impactsAt[state.frame].forEach(function (im) {
      var key = im.site_kind + im.site, size = im.peak_force === null ? im.impulse_n : im.peak_force;
      var cur = bySite[key];
      if (cur && cur.size >= size) { cur.count++; return; }
      bySite[key] = { im: im, size: size, count: cur ? cur.count + 1 : 1 };
    });
    Object.keys(bySite).forEach(function (key) {
      var im = bySite[key].im, p;
      if (im.site_kind === 'joint') { p = mid(place(im.site, endMid(im.site), q), place(im.site + 1, startMid(im.site + 1), q)); }
      else { var fc = D.abutment_faces[im.site] || [[0, 0], [0, 0]], o = off.abut[im.site] || [0, 0]; p = add(mid(fc[0], fc[1]), o, 1); }
      marks.push({ t: im.t, site_kind: im.site_kind, site: im.site, x: p[0], y: p[1], impulse_n: im.impulse_n, peak_force: im.peak_force, impacts: bySite[key].count });
      var s = T(p); g.fillStyle = 'rgba(220,30,30,0.8)'; g.beginPath(); g.arc(s[0], s[1], 9, 0, 2 * Math.PI); g.fill();
      g.fillStyle = '#900'; g.font = '12px sans-serif';
      var text = im.peak_force === null ? 'P=' + im.impulse_n.toPrecision(3) + ' N s' : 'F=' + im.peak_force.toPrecision(3) + ' N';
      label(g, text + (bySite[key].count > 1 ? ' (' + bySite[key].count + ' impacts)' : ''), s[0] + 10, s[1] - 10);
    });
    state.drawn = drawn; state.markers = marks; state.seats = seats; state.restrainers = rs; state.offsets = off.seg;
    g.fillStyle = '#000'; g.font = '13px sans-serif';
    g.fillText('t = ' + f.t.toFixed(decimals) + ' s   displacements and gaps × ' + state.mag + (state.zoom ? '   (zoomed: double-click to reset)' : '   (click to zoom)') + (rot ? '   plan turned 90° (x up)' : ''), 8, 16);
    $('an-time').textContent = f.t.toFixed(decimals) + ' s';
    drawGround();
  }
  var agPeak = D.ag_peak || [0, 0];
  function drawGround() {
    var g = gm.getContext('2d'), w = gm.width, h = gm.height, a = Math.max(agPeak[0], agPeak[1]);
    F.forEach(function (f) { a = Math.max(a, Math.abs(f.ag[0]), Math.abs(f.ag[1])); });
    a = a || 1;
    var t0 = F[0].t, t1 = F[F.length - 1].t, X = function (t) { return (t - t0) / ((t1 - t0) || 1) * w; };
    g.clearRect(0, 0, w, h);
    ['#c33', '#36c'].forEach(function (col, k) {
      g.strokeStyle = col; g.beginPath();
      F.forEach(function (f, j) { var x = X(f.t), y = h / 2 - f.ag[k] / a * (h / 2 - 4); j ? g.lineTo(x, y) : g.moveTo(x, y); });
      g.stroke();
    });
    g.strokeStyle = '#000'; g.beginPath(); var cx = X(F[state.frame].t); g.moveTo(cx, 0); g.lineTo(cx, h); g.stroke();
    g.fillStyle = '#000'; g.font = '11px sans-serif';
    g.fillText('ground acceleration (red x, blue y; drawn at the frames), peak |a_x| ' + agPeak[0].toPrecision(3) + ', |a_y| ' + agPeak[1].toPrecision(3) + ' m/s² over every step', 4, 12);
  }
  function setFrame(k) { state.frame = Math.max(0, Math.min(F.length - 1, k | 0)); sl.value = state.frame; state.playT = F[state.frame].t; draw(); }
  function setMag(v) { state.mag = v; mg.value = v; off = offsets(v); draw(); }
  sl.max = F.length - 1;
  sl.addEventListener('input', function () { setFrame(+sl.value); });
  mg.addEventListener('change', function () { var v = +mg.value; if (mg.value !== '' && v >= 1e-3 && v <= 1e6) setMag(v); else mg.value = state.mag; });
  $('an-true').addEventListener('click', function () { setMag(1); });
  $('an-auto').addEventListener('click', function () { setMag(auto); });
  $('an-speed').addEventListener('change', function () { state.speed = +$('an-speed').value; });
  // play: the shown time advances at the chosen speed (accumulated, not reset to the frame's)
  var last = null;
  function tick(ts) {
    if (!state.playing) return;
    if (last !== null) {
      state.playT += (ts - last) / 1000 * state.speed;
      var k = state.frame;
      while (k < F.length - 1 && F[k + 1].t <= state.playT) k++;
      if (k === F.length - 1) state.playing = false;
      if (k !== state.frame) { state.frame = k; sl.value = k; draw(); }
    }
    last = ts; if (state.playing) requestAnimationFrame(tick); else $('an-play').textContent = 'Play';
  }
  $('an-play').addEventListener('click', function () {
    state.playing = !state.playing; $('an-play').textContent = state.playing ? 'Pause' : 'Play';
    if (state.playing) { if (state.frame === F.length - 1) setFrame(0); state.playT = F[state.frame].t; last = null; requestAnimationFrame(tick); }
  });
  // click: zoom 4× around the clicked point (again to zoom further); double-click: whole plan
  cv.addEventListener('click', function (e) {
    var r = cv.getBoundingClientRect(), T = view();
    var px = (e.clientX - r.left) * cv.width / r.width, py = (e.clientY - r.top) * cv.height / r.height;
    var c = R(T.inv(px, py));
    state.zoom = { cx: c[0], cy: c[1], w: T.w / 4 }; draw();
  });
  cv.addEventListener('dblclick', function () { state.zoom = null; draw(); });
  var ev = $('an-events'), names = { first_impact: 'first impact', peak_closing: 'peak closing', peak_seat_ratio: 'peak seat ratio', unseating: 'unseating' };
  Object.keys(names).forEach(function (k) {
    var t = D.events[k]; if (t === null || t === undefined) return;
    var b = document.createElement('button');
    b.textContent = names[k] + ' (' + (t > 0 && t < Math.pow(10, -decimals) ? t.toPrecision(3) : t.toFixed(decimals)) + ' s)';
    b.addEventListener('click', function () { setFrame(frameAt(t)); }); ev.appendChild(b);
  });
  window.poundingAnim = { state: state, data: D, setFrame: setFrame, frameAt: frameAt, setMag: setMag, offsets: offsets };
  // report.html#t=1.5 opens at that time
  var m = /[#&]t=([0-9.eE+-]+)/.exec(location.hash);
  setFrame(m ? frameAt(+m[1]) : 0);
})();
