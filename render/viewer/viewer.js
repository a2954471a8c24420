// The animated schedule viewer (docs/animate.md). render/animation_page.cpp
// inlines this file into every page `gridlock animate` writes, after the
// data (<script type="application/json" id="data">, built there). Plain
// browser JavaScript, no module, no library, no network: the page must work
// opened from a file. It must not hold an HTML comment opener or a closing
// script tag, even in a comment or string (the build refuses both: the
// inlined script element would end there). Syntax is checked by node --check
// (ctest viewer_js_syntax) and the page by headless Chromium (render_tests).
'use strict';
const errors = [];
window.addEventListener('error', e => { errors.push(String(e.message || e)); try { writeState(); } catch (x) {} });
{ const ce = console.error; console.error = function (...a) { errors.push(a.map(String).join(' ')); ce.apply(console, a); }; }
const G = JSON.parse(document.getElementById('data').textContent);
const NS = 'http://www.w3.org/2000/svg';
const PAL = ['#d62728','#1f77b4','#2ca02c','#9467bd','#ff7f0e','#17becf','#8c564b','#e377c2','#bcbd22','#7f7f7f'];
const D = G.den, EV = G.events, N = G.cells.length / 2, NQ = G.couplings.length;
const $ = id => document.getElementById(id);
function el(tag, attrs, parent) {
  const e = document.createElementNS(NS, tag);
  for (const k in attrs) e.setAttribute(k, attrs[k]);
  if (parent) parent.appendChild(e);
  return e;
}
function parseQ(s) {  // "p/q" or "p" -> number of 1/D units, or null
  const m = /^\s*(-?\d+)(?:\/(\d+))?\s*$/.exec(s || '');
  if (!m) return null;
  const q = m[2] ? Number(m[2]) : 1;
  return q === 0 ? null : Number(m[1]) * D / q;
}
function fracStr(T) {  // an event time T (in 1/D units) as a reduced fraction
  let a = Math.round(T), b = D;
  const g = (x, y) => (y ? g(y, x % y) : Math.abs(x));
  const k = g(a, b) || 1;
  a /= k; b /= k;
  return b === 1 ? String(a) : a + '/' + b;
}
// Rigid parts: keyframes (event time, displacement relative to the parent
// part), linear in between; a part's position is the sum along its chain,
// which nested SVG groups compute for the drawing.
const parts = G.parts.map(a => {
  const p = { parent: a[0], q: a[1], ke: [], kx: [], ky: [], g: null, dx: NaN, dy: NaN };
  for (let i = 2; i < a.length; i += 3) { p.ke.push(EV[a[i]]); p.kx.push(a[i + 1] / D); p.ky.push(a[i + 2] / D); }
  p.moves = p.kx.some(v => v !== p.kx[0]) || p.ky.some(v => v !== p.ky[0]);
  return p;
});
function disp(p, T) {
  const ke = p.ke, L = ke.length;
  if (L === 1 || T <= ke[0]) return [p.kx[0], p.ky[0]];
  if (T >= ke[L - 1]) return [p.kx[L - 1], p.ky[L - 1]];
  let lo = 0, hi = L - 1;  // ke[lo] <= T < ke[hi]
  while (hi - lo > 1) { const m = (lo + hi) >> 1; if (ke[m] <= T) lo = m; else hi = m; }
  const f = (T - ke[lo]) / (ke[hi] - ke[lo]);
  return [p.kx[lo] + f * (p.kx[hi] - p.kx[lo]), p.ky[lo] + f * (p.ky[hi] - p.ky[lo])];
}
const partOf = G.part_of_node;
// Absolute displacements of all parts at T (parents come before children);
// a few recent times are kept.
const absCache = new Map();
function absAt(T) {
  let v = absCache.get(T);
  if (v) return v;
  const ax = new Float64Array(parts.length), ay = new Float64Array(parts.length);
  parts.forEach((p, i) => {
    const d = disp(p, T);
    ax[i] = d[0] + (p.parent >= 0 ? ax[p.parent] : 0);
    ay[i] = d[1] + (p.parent >= 0 ? ay[p.parent] : 0);
  });
  if (absCache.size >= 4) absCache.clear();
  v = [ax, ay];
  absCache.set(T, v);
  return v;
}
const cellX = i => G.cells[2 * i], cellY = i => G.cells[2 * i + 1];
// Resizing regions: [r, kind, op, base0..3, ref0..3, growFace, growSign].
const resizing = new Map();
for (const a of G.resizing) resizing.set(a[0], { r: a[0], kind: a[1], op: a[2], base: a.slice(3, 7), ref: a.slice(7, 11), gf: a[11], gs: a[12], el: null });
const progress = (q, T) => Math.min(1, Math.max(0, (T - G.start[q]) / D));
function regionRect(r, T) {  // [xlo, xhi, ylo, yhi] in grid units
  const z = resizing.get(r), A = absAt(T);
  if (!z) { const dx = A[0][partOf[r]], dy = A[1][partOf[r]]; return [cellX(r) + dx, cellX(r) + 1 + dx, cellY(r) + dy, cellY(r) + 1 + dy]; }
  const c = [0, 0, 0, 0];
  for (let f = 0; f < 4; ++f) {
    const q = partOf[z.ref[f]];
    c[f] = z.base[f] + (f < 2 ? A[0][q] : A[1][q]);
    if (z.kind === 2 && f === z.gf) c[f] += z.gs * progress(G.ops[z.op][4], T);
  }
  return c;
}
const opOfNode = new Int32Array(N).fill(-1);
G.ops.forEach((o, k) => { opOfNode[o[2]] = k; if (o[3] >= 0) opOfNode[o[3]] = k; });
const KIND = ['expand', 'grow', 'contract'];
function label(r) {
  const z = resizing.get(r);
  let s;
  if (r >= N) s = 'node ' + (z.kind === 1 ? 'inserted' : 'grown') + ' by ' + G.ops[z.op][0];
  else s = 'node (' + cellX(r) + ',' + cellY(r) + ')' + (r === G.anchor ? ', the anchor' : '');
  const k = r < N ? opOfNode[r] : z.op;
  if (k >= 0) { const o = G.ops[k]; s += '; operation ' + o[0] + ' (' + KIND[o[1]] + '), coupling ' + G.couplings[o[4]]; }
  return s;
}
// --- drawing ---
const svg = $('view'), world = $('world');
const colour = q => PAL[q % 10];
const byCoupling = Array.from({ length: NQ }, () => []);
const hit = new Set();
if (G.collision) {
  if (G.collision.kind === 'node') { hit.add(G.collision.a); hit.add(G.collision.b); }
  else for (const w of G.collision.cycle) hit.add(w);
}
function styleRegion(e, r) {
  e.dataset.r = r;
  const k = r < N ? opOfNode[r] : resizing.get(r).op;
  if (k >= 0) { const q = G.ops[k][4]; e.style.setProperty('--c', colour(q)); e.classList.add('op'); byCoupling[q].push(e); }
  if (hit.has(r)) e.classList.add('hit');
}
const inset = 0.06;
const edgesOf = parts.map(() => []);
for (let i = 0; i < G.edges.length; i += 2) {
  const a = G.edges[i], b = G.edges[i + 1];
  if (partOf[a] === partOf[b] && !resizing.has(a) && !resizing.has(b)) edgesOf[partOf[a]].push(a, b);
}
const nodesOf = parts.map(() => []);
for (let w = 0; w < N; ++w) if (!resizing.has(w)) nodesOf[partOf[w]].push(w);
parts.forEach((p, i) => {
  p.g = el('g', {}, p.parent >= 0 ? parts[p.parent].g : world);
  const E = edgesOf[i];
  for (let j = 0; j < E.length; j += 2)
    el('line', { class: 'e', x1: cellX(E[j]) + .5, y1: cellY(E[j]) + .5, x2: cellX(E[j + 1]) + .5, y2: cellY(E[j + 1]) + .5 }, p.g);
  for (const w of nodesOf[i]) {
    const e = el('rect', { class: 'n', x: cellX(w) + inset, y: cellY(w) + inset, width: 1 - 2 * inset, height: 1 - 2 * inset, rx: .08 }, p.g);
    styleRegion(e, w);
  }
});
const zg = el('g', {}, world);
for (const z of resizing.values()) { z.el = el('rect', { class: z.r < N ? 'n' : 'z', rx: .05 }, zg); styleRegion(z.el, z.r); }
el('circle', { r: .13, cx: cellX(G.anchor) + .25, cy: cellY(G.anchor) + .75, fill: '#000' }, parts[partOf[G.anchor]].g);
const overlap = el('rect', { id: 'overlap', visibility: 'hidden' }, world);
let ALL = null, VB = null, lastOv = null;
const T0 = EV[0], TSTOP = parseQ(G.stop), TC = G.collision ? parseQ(G.collision.time) : null;

// View box: the cells, the growth targets and everything the keyframes reach.
{
  let x0 = Infinity, x1 = -Infinity, y0 = Infinity, y1 = -Infinity;
  const pb = parts.map(() => [Infinity, -Infinity, Infinity, -Infinity]);
  for (let w = 0; w < N; ++w) { const b = pb[partOf[w]]; b[0] = Math.min(b[0], cellX(w)); b[1] = Math.max(b[1], cellX(w) + 1); b[2] = Math.min(b[2], cellY(w)); b[3] = Math.max(b[3], cellY(w) + 1); }
  // A part's offset lies between its chain's sums of the smallest and of the
  // largest relative keyframe.
  const lo = parts.map(() => [0, 0]), hi = parts.map(() => [0, 0]);
  parts.forEach((p, i) => {
    const up = p.parent >= 0 ? p.parent : -1;
    lo[i] = [(up >= 0 ? lo[up][0] : 0) + Math.min(...p.kx), (up >= 0 ? lo[up][1] : 0) + Math.min(...p.ky)];
    hi[i] = [(up >= 0 ? hi[up][0] : 0) + Math.max(...p.kx), (up >= 0 ? hi[up][1] : 0) + Math.max(...p.ky)];
    const b = pb[i];
    if (b[0] === Infinity) return;
    x0 = Math.min(x0, b[0] + lo[i][0]); x1 = Math.max(x1, b[1] + hi[i][0]);
    y0 = Math.min(y0, b[2] + lo[i][1]); y1 = Math.max(y1, b[3] + hi[i][1]);
  });
  for (const z of resizing.values()) {
    const q = partOf[z.ref[0]];
    x0 = Math.min(x0, z.base[0] - 1 + lo[q][0]); x1 = Math.max(x1, z.base[1] + 1 + hi[q][0]);
    y0 = Math.min(y0, z.base[2] - 1 + lo[q][1]); y1 = Math.max(y1, z.base[3] + 1 + hi[q][1]);
  }
  const m = 0.6;
  ALL = [x0 - m, -y1 - m, x1 - x0 + 2 * m, y1 - y0 + 2 * m];
  svg.setAttribute('preserveAspectRatio', 'xMidYMid meet');
  fit(true);
}
// The view: a viewBox in grid units (y negated). Wheel zooms, drag pans.
function setView(v) { VB = v; svg.setAttribute('viewBox', v.join(' ')); }
function fit(initial) {
  const r = svg.getBoundingClientRect(), W = r.width || 800, H = r.height || 600;
  // A tall or wide instance whose cells would be tiny: fit its width (or
  // height) and start at the top left instead.
  const s = Math.min(W / ALL[2], H / ALL[3]);
  if (initial && s < 6 && Math.max(W / ALL[2], H / ALL[3]) >= 6) {
    if (W / ALL[2] > H / ALL[3]) setView([ALL[0], ALL[1], ALL[2], ALL[2] * H / W]);
    else setView([ALL[0], ALL[1], ALL[3] * W / H, ALL[3]]);
    // With a collision, centre it.
    if (G.collision) {
      const c = regionRect(G.collision.kind === 'node' ? G.collision.a : G.collision.cycle[0], TSTOP);
      const cx = (c[0] + c[1]) / 2, cy = -(c[2] + c[3]) / 2;
      setView([Math.min(Math.max(cx - VB[2] / 2, ALL[0]), ALL[0] + ALL[2] - VB[2]),
               Math.min(Math.max(cy - VB[3] / 2, ALL[1]), ALL[1] + ALL[3] - VB[3]), VB[2], VB[3]]);
    }
  } else setView(ALL.slice());
}
function zoomAt(cx, cy, k) {  // cx, cy in grid units (y negated)
  setView([cx - (cx - VB[0]) * k, cy - (cy - VB[1]) * k, VB[2] * k, VB[3] * k]);
}
svg.addEventListener('wheel', e => {
  e.preventDefault();
  const p = new DOMPoint(e.clientX, e.clientY).matrixTransform(svg.getScreenCTM().inverse());
  zoomAt(p.x, p.y, Math.exp(e.deltaY * 0.0015));
  if (!playing) writeState(lastOv);
}, { passive: false });
{
  let drag = null;
  svg.addEventListener('pointerdown', e => { drag = [e.clientX, e.clientY, VB.slice()]; svg.setPointerCapture(e.pointerId); });
  svg.addEventListener('pointermove', e => {
    if (!drag) return;
    const k = 1 / svg.getScreenCTM().a;  // grid units per CSS pixel
    setView([drag[2][0] - (e.clientX - drag[0]) * k, drag[2][1] - (e.clientY - drag[1]) * k, VB[2], VB[3]]);
  });
  svg.addEventListener('pointerup', () => { drag = null; if (!playing) writeState(lastOv); });
}
function follow() {  // keep the running operations in view
  if (!$('follow').checked || !runNow.length) return;
  const k = G.couplings_first_op[runNow[0]];
  const c = regionRect(G.ops[k][2], T), cx = (c[0] + c[1]) / 2, cy = -(c[2] + c[3]) / 2;
  if (cx < VB[0] + VB[2] * .15 || cx > VB[0] + VB[2] * .85 || cy < VB[1] + VB[3] * .15 || cy > VB[1] + VB[3] * .85)
    setView([cx - VB[2] / 2, cy - VB[3] / 2, VB[2], VB[3]]);
}
// --- time ---
let T = T0, exact = fracStr(T0), playing = false, last = null, runKey = '', runNow = [];
const slider = $('slider');
function running(Tn) {
  const out = [];
  for (let q = 0; q < NQ; ++q) if (G.start[q] <= Tn && Tn < G.start[q] + D) out.push(q);
  return out;
}
function setRect(e, c, minw) {
  const key = c.join(' ') + ' ' + minw;  // only touch the DOM on a change
  if (e._k === key) return;
  e._k = key;
  const w = c[1] - c[0], h = c[3] - c[2];
  if (w <= 0 && h <= 0 || ((w <= 0 || h <= 0) && !minw)) { e.setAttribute('visibility', 'hidden'); return; }
  const ww = Math.max(w, minw || 0), hh = Math.max(h, minw || 0);
  e.setAttribute('visibility', 'visible');
  e.setAttribute('x', c[0] + (w - ww) / 2); e.setAttribute('y', c[2] + (h - hh) / 2);
  e.setAttribute('width', ww); e.setAttribute('height', hh);
}
// A harness added to the page (render/viewer/bench.js, never shipped) sets
// quiet while it draws many frames and reports through extraState.
let quiet = false;
const extraState = {};
let loadMs = null, drawMs = 0, curInterval = -1, moverParts = [], moverRegions = [];
function draw() {
  const t0 = performance.now();
  // Within one interval between events only the parts and regions that move
  // there are touched; entering another interval updates everything once.
  let lo = 0, hi = EV.length - 1;
  if (T < EV[hi]) { while (hi - lo > 1) { const m = (lo + hi) >> 1; if (EV[m] <= T) lo = m; else hi = m; } } else lo = hi;
  let ps = moverParts, zs = moverRegions;
  if (lo !== curInterval) {
    curInterval = lo;
    ps = parts; zs = Array.from(resizing.values());
    moverParts = []; moverRegions = [];
    if (lo + 1 < EV.length) {
      const a = EV[lo], b = EV[lo + 1];
      for (const p of parts) { const u = disp(p, a), v = disp(p, b); if (u[0] !== v[0] || u[1] !== v[1]) moverParts.push(p); }
      for (const z of zs) { const u = regionRect(z.r, a), v = regionRect(z.r, b); if (u.some((x, i) => x !== v[i])) moverRegions.push(z); }
    }
  }
  for (const p of ps) {
    const d = disp(p, T);
    if (d[0] !== p.dx || d[1] !== p.dy) { p.dx = d[0]; p.dy = d[1]; p.g.setAttribute('transform', 'translate(' + d[0] + ',' + d[1] + ')'); }
  }
  for (const z of zs) {
    const c = regionRect(z.r, T), w = c[1] - c[0], h = c[3] - c[2];
    const inX = Math.min(inset, w / 4), inY = Math.min(inset, h / 4);
    setRect(z.el, [c[0] + Math.max(inX, 0), c[1] - Math.max(inX, 0), c[2] + Math.max(inY, 0), c[3] - Math.max(inY, 0)], hit.has(z.r) ? 0.12 : 0);
  }
  let ov = null;
  if (G.collision && G.collision.kind === 'node' && T >= TC) {
    const a = regionRect(G.collision.a, T), b = regionRect(G.collision.b, T);
    ov = [Math.max(a[0], b[0]), Math.min(a[1], b[1]), Math.max(a[2], b[2]), Math.min(a[3], b[3])];
    if (!(ov[1] > ov[0] && ov[3] > ov[2])) ov = null;
  }
  if (ov) setRect(overlap, ov, 0); else overlap.setAttribute('visibility', 'hidden');
  lastOv = ov;
  const run = running(T), key = run.join(',');
  if (key !== runKey) {
    for (const q of runNow) for (const e of byCoupling[q]) e.classList.remove('run');
    for (const q of run) for (const e of byCoupling[q]) e.classList.add('run');
    runNow = run; runKey = key;
    const box = $('running');
    box.textContent = '';
    if (!run.length) box.textContent = 'none';
    for (const q of run.slice(0, 60)) {
      const d = document.createElement('div'), s = document.createElement('span');
      s.className = 'sw'; s.style.background = colour(q);
      d.appendChild(s); d.appendChild(document.createTextNode(G.couplings[q] + ' (' + G.coupling_ops[q] + ')'));
      box.appendChild(d);
    }
    if (run.length > 60) box.appendChild(document.createTextNode('... and ' + (run.length - 60) + ' more'));
  }
  follow();
  $('time').textContent = 't = ' + (exact !== null ? exact : '\u2248 ' + (T / D).toFixed(3)) + '  (stop ' + G.stop + ')';
  slider.value = String(Math.round(TSTOP > T0 ? 100000 * (T - T0) / (TSTOP - T0) : 0));
  $('play').innerHTML = playing ? '&#10074;&#10074;' : '&#9654;';
  drawMs = performance.now() - t0;
  if (!playing && !quiet) writeState(ov);
}
function boxOf(c) {  // grid box -> CSS pixel box [left, top, right, bottom]
  const m = world.getScreenCTM();
  const p = new DOMPoint(c[0], c[2]).matrixTransform(m), q = new DOMPoint(c[1], c[3]).matrixTransform(m);
  return [Math.min(p.x, q.x), Math.min(p.y, q.y), Math.max(p.x, q.x), Math.max(p.y, q.y)];
}
function writeState(ov) {
  const s = { t: exact, T: T / D, stop: G.stop, running: runNow.map(q => G.couplings[q]), errors: errors, draw_ms: drawMs, load_ms: loadMs };
  Object.assign(s, extraState);
  if (G.collision && G.collision.kind === 'node') {
    const a = regionRect(G.collision.a, T), b = regionRect(G.collision.b, T);
    s.a = { label: label(G.collision.a), grid: a, px: boxOf(a) };
    s.b = { label: label(G.collision.b), grid: b, px: boxOf(b) };
    s.overlap = ov === undefined || ov === null ? null : { grid: ov, px: boxOf(ov), drawn: (() => { const r = overlap.getBoundingClientRect(); return [r.left, r.top, r.right, r.bottom]; })() };
    if (s.overlap) {
      const c = s.overlap.px, e = document.elementFromPoint((c[0] + c[2]) / 2, (c[1] + c[3]) / 2);
      s.overlap.at_centre = e ? (e.id || e.tagName) : null;
    }
  }
  $('state').textContent = JSON.stringify(s);
}
function setT(Tn, ex) { T = Math.min(TSTOP, Math.max(T0, Tn)); exact = ex !== undefined ? ex : (EV.includes(T) ? fracStr(T) : null); draw(); }
function frame(ts) {
  if (!playing) return;
  if (last !== null) {
    const nt = T + (ts - last) / 1000 * Number($('speed').value) * D;
    if (nt >= TSTOP) { playing = false; setT(TSTOP, G.stop); last = null; return; }
    T = nt; exact = null; draw();
  }
  last = ts;
  requestAnimationFrame(frame);
}
function play(on) {
  playing = on; last = null;
  if (on) { if (T >= TSTOP) T = T0; requestAnimationFrame(frame); }
  draw();
}
function step(dir) {
  play(false);
  if (dir > 0) { const e = EV.find(x => x > T); if (e === undefined || e > TSTOP) setT(TSTOP, G.stop); else setT(e); }
  else { let e = T0; for (const x of EV) if (x < T) e = x; setT(e); }
}
$('fit').onclick = () => { fit(false); if (!playing) writeState(lastOv); };
$('follow').onchange = () => { follow(); if (!playing) draw(); };
$('play').onclick = () => play(!playing);
$('next').onclick = () => step(1);
$('prev').onclick = () => step(-1);
slider.oninput = () => { play(false); setT(T0 + (TSTOP - T0) * Number(slider.value) / 100000, null); };
document.addEventListener('keydown', e => {
  if (e.target.tagName === 'SELECT') return;
  if (e.key === ' ') { e.preventDefault(); play(!playing); }
  else if (e.key === 'ArrowRight') { e.preventDefault(); step(1); }
  else if (e.key === 'ArrowLeft') { e.preventDefault(); step(-1); }
});
svg.addEventListener('mousemove', e => {
  const t = e.target;
  if (t === overlap) $('hover').textContent = 'overlap of ' + label(G.collision.a) + ' and ' + label(G.collision.b);
  else if (t.dataset && t.dataset.r !== undefined) $('hover').textContent = label(Number(t.dataset.r));
});
$('title').textContent = G.title;
document.title = G.title;
$('info').textContent = N + ' nodes, ' + G.ops.length + ' operations, ' + NQ + ' couplings, ' + parts.length +
  ' rigid parts; ' + G.model + ' schedule, events 0..' + (EV.length - 1) + ' from t = ' + fracStr(EV[0]) + ' to ' + fracStr(EV[EV.length - 1]);
if (G.collision) {
  $('collision').textContent = G.collision.text + '; moving then: ' + G.collision.moving.map(q => G.couplings[q]).join(' ') +
    '. The player stops at t = ' + G.stop + ', half way to the next event, ' +
    (G.collision.kind === 'node' ? 'where the overlap shows.' : 'where the cycle is visibly torn apart.');
  const tick = $('ctick');
  tick.hidden = false;
  tick.style.left = (TSTOP > T0 ? 100 * (TC - T0) / (TSTOP - T0) : 0) + '%';
  tick.title = 'collision at t = ' + G.collision.time;
} else {
  $('collision').textContent = 'none: the schedule is collision-free';
  $('collision').style.color = '#2a7';
}
function fromHash() {
  const m = /[#&]t=([^&]+)/.exec(location.hash);
  if (!m) return false;
  const v = parseQ(decodeURIComponent(m[1]));
  if (v === null) { errors.push('bad #t=' + m[1]); writeState(); return true; }
  play(false); setT(v, decodeURIComponent(m[1]));
  return true;
}
window.addEventListener('hashchange', fromHash);
window.addEventListener('resize', () => { if (!playing) draw(); });
if (!fromHash()) { setT(T0); if (!/nostart/.test(location.hash)) play(true); }
loadMs = performance.now();  // from navigation start to a drawn page (script side)
if (!playing) writeState(lastOv);
