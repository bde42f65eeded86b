// The knitting page's script, inlined into every page (page_writer.cpp; its style:
// page_style.cpp). The script reads the data the page embeds (#skein-data, the cells and yarn as
// base64 typed arrays), so it is the same for every model. Query flags: ?selftest=1 steps through
// every stitch and checks text, counts and 3D agree; ?selftest=reload checks progress survives a
// reload; ?selftest=perf only times. Each reports into <pre id="selftest">, for `chromium
// --headless --dump-dom`.
#include "hand_web/page_writer.hpp"

namespace skein::hand_web {

const char* const kPageScript = R"JS(
(function () {
'use strict';
const scriptStart = performance.now();
const $ = (id) => document.getElementById(id);
const D = JSON.parse($('skein-data').textContent);
const O = D.order, N = O.stitch.length;
const query = new URLSearchParams(location.search);
const KEY = 'skein-page:' + D.key;
const COLOURS = { done: [0x43, 0xa0, 0x47], current: [0xe5, 0x39, 0x35], todo: [0xc7, 0xc7, 0xc7] };
let cur = 0;

function bytes(id) {
  const text = $(id).textContent, raw = atob(text);
  const out = new Uint8Array(raw.length);
  for (let i = 0; i < raw.length; ++i) out[i] = raw.charCodeAt(i);
  return out;
}
const cells = new Float32Array(bytes('skein-cells').buffer);
const yarn = new Uint32Array(bytes('skein-yarn').buffer);
const yarnPiece = new Uint32Array(bytes('skein-yarn-piece').buffer);
const indexOf = new Int32Array(D.stitches).fill(-1);  // model stitch -> program index
for (let i = 0; i < N; ++i) indexOf[O.stitch[i]] = i;

// ---- the page's skeleton -------------------------------------------------------------------
document.body.insertAdjacentHTML('afterbegin', `
<header><h1 id="title"></h1><span id="counter" aria-live="polite"></span>
<button id="yarn" title="Show or hide the yarn (Y)">Yarn</button>
<button id="big" title="Large print (B)">Aa</button>
<button id="reset" title="Start again from the first stitch">Reset</button></header>
<section id="view" aria-label="The model in 3D"><div id="toast"></div></section>
<section id="panel">
<div id="heading"></div><div id="where"></div><p id="instr"></p><div id="said"></div>
<figure id="chart" hidden><figcaption>This piece's chart, as seen from the RS: a blank square
is k on RS rows and p on WS rows, a dot p on RS rows and k on WS rows; RS rows are read from
right to left, WS rows from left to right.</figcaption><div id="chartScroll"></div></figure>
<div id="counts"></div>
<div id="legend"><span style="background:var(--done)"></span>Done<span
 style="background:var(--current)"></span>Now<span style="background:var(--todo)"></span>To do
<span style="background:#1565c0;border-radius:50%"></span>Marker</div>
<div id="steps">
<button id="prevSection" title="Previous section (Shift+Up)">&laquo; Section</button>
<button id="prevRow" title="Previous row (Down)">&lsaquo; Row</button>
<button id="prev" title="Previous stitch (Left, Backspace)">&lsaquo; St</button>
<button id="nextSection" title="Next section (Shift+Down)">Section &raquo;</button>
<button id="nextRow" title="Next row (Up)">Row &rsaquo;</button>
</div>
<button id="next" title="Next stitch (Right, Space, PageDown)">Next stitch</button>
<p id="note"></p>
<details><summary>Whole pattern</summary><pre id="pattern"></pre><p id="proof"></p></details>
<details><summary>Keys</summary><p>Right, Space, PageDown: next stitch. Left, Backspace,
PageUp: previous. Up / Down: next / previous row. Shift+Up / Shift+Down: section. B: large
print. Y: yarn shown or hidden. Click a stitch in the model to go there.</p></details>
<pre id="perf"></pre><pre id="selftest"></pre>
</section>`);
$('title').textContent = D.title;
$('pattern').textContent = new TextDecoder().decode(bytes('skein-pattern'));
$('proof').textContent = 'Proven: ' + D.proof;
$('note').textContent = D.note;

const esc = (s) => s.replace(/&/g, '&amp;').replace(/</g, '&lt;');

// ---- the 3D view ---------------------------------------------------------------------------
const view = { ok: false };
function buildView() {
  if (!window.THREE || cells.length === 0) {
    $('view').insertAdjacentHTML('beforeend', '<p id="no3d">' + (window.THREE
      ? 'This model has no stitch positions to draw.'
      : 'three.js (Debian package libjs-three) was not found when this page was written: ' +
        'no 3D view.') + '</p>');
    return;
  }
  const T = THREE, S = D.stitches;
  const renderer = new T.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(Math.min(window.devicePixelRatio || 1, 2));
  $('view').prepend(renderer.domElement);
  const scene = new T.Scene();
  scene.background = new T.Color(getComputedStyle(document.body).backgroundColor);
  const geometry = new T.BufferGeometry();
  geometry.setAttribute('position', new T.BufferAttribute(cells, 3));
  const colour = new Uint8Array(S * 12);
  for (let s = 0; s < S; ++s) paint(colour, s, COLOURS.todo);
  const colourAttr = new T.BufferAttribute(colour, 3, true);
  colourAttr.setUsage && colourAttr.setUsage(T.DynamicDrawUsage);
  geometry.setAttribute('color', colourAttr);
  const index = new Uint32Array(S * 6);
  for (let s = 0, k = 0; s < S; ++s, k += 6) {
    index[k] = index[k + 3] = 4 * s;
    index[k + 1] = 4 * s + 1;
    index[k + 2] = index[k + 4] = 4 * s + 2;
    index[k + 5] = 4 * s + 3;
  }
  geometry.setIndex(new T.BufferAttribute(index, 1));
  geometry.computeVertexNormals();
  geometry.computeBoundingSphere();
  const mesh = new T.Mesh(geometry, new T.MeshLambertMaterial({
    vertexColors: T.VertexColors, side: T.DoubleSide, polygonOffset: true,
    polygonOffsetFactor: 1, polygonOffsetUnits: 1 }));
  scene.add(mesh);
  scene.add(new T.HemisphereLight(0xffffff, 0x666666, 0.9));
  const sun = new T.DirectionalLight(0xffffff, 0.5);
  scene.add(sun);
  // The yarn: a line through the cells' centres, one colour per piece.
  const centre = new Float32Array(S * 3);
  for (let s = 0; s < S; ++s)
    for (let d = 0; d < 3; ++d)
      centre[3 * s + d] = (cells[12 * s + d] + cells[12 * s + 3 + d] + cells[12 * s + 6 + d] + cells[12 * s + 9 + d]) / 4;
  const yarnPos = new Float32Array(yarn.length * 3), yarnCol = new Float32Array(yarn.length * 3);
  const hue = new T.Color();
  for (let k = 0; k < yarn.length; ++k) {
    yarnPos.set(centre.subarray(3 * yarn[k], 3 * yarn[k] + 3), 3 * k);
    // Blues, purples and browns: never the green, red or grey that tell done, now and to do.
    const piece = yarnPiece[yarn[k]];
    hue.setHSL([0.6, 0.75, 0.08, 0.52, 0.85, 0.68][piece % 6], 0.6, piece % 12 < 6 ? 0.3 : 0.45);
    yarnCol.set([hue.r, hue.g, hue.b], 3 * k);
  }
  const yarnGeometry = new T.BufferGeometry();
  yarnGeometry.setAttribute('position', new T.BufferAttribute(yarnPos, 3));
  yarnGeometry.setAttribute('color', new T.BufferAttribute(yarnCol, 3));
  const yarnLines = new T.LineSegments(yarnGeometry, new T.LineBasicMaterial({ vertexColors: T.VertexColors, transparent: true, opacity: 0.45 }));
  yarnLines.visible = query.get('yarn') !== '0';
  scene.add(yarnLines);
  // Markers of the current row, and a ring on the current stitch.
  const markerGeometry = new T.BufferGeometry();
  markerGeometry.setAttribute('position', new T.BufferAttribute(new Float32Array(3), 3));
  const markers = new T.Points(markerGeometry, new T.PointsMaterial({ color: 0x1565c0, size: 9, sizeAttenuation: false }));
  scene.add(markers);
  const here = new T.Points(new T.BufferGeometry(), new T.PointsMaterial({ color: 0xe53935, size: 14, sizeAttenuation: false }));
  here.geometry.setAttribute('position', new T.BufferAttribute(new Float32Array(3), 3));
  scene.add(here);

  const sphere = geometry.boundingSphere;
  const camera = new T.PerspectiveCamera(40, 1, sphere.radius / 100, sphere.radius * 100);
  camera.position.copy(sphere.center).add(new T.Vector3(0, sphere.radius * 0.8, sphere.radius * 3.0));
  const controls = new T.OrbitControls(camera, renderer.domElement);
  controls.target.copy(sphere.center);
  controls.update();
  let queued = false;
  const pixel = new Uint8Array(4);
  const render = (wait) => {
    queued = false;
    sun.position.copy(camera.position);
    renderer.render(scene, camera);
    if (wait || !view.firstFrame) {
      const gl = renderer.getContext();  // wait for the frame to be drawn, not only queued
      gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
    }
    if (!view.firstFrame) {
      view.firstFrame = performance.now();
      window.__skeinFirstFrame = view.firstFrame;
    }
  };
  const requestRender = () => { if (!queued) { queued = true; requestAnimationFrame(render); } };
  controls.addEventListener('change', requestRender);
  const resize = () => {
    const box = $('view').getBoundingClientRect();
    renderer.setSize(Math.max(1, box.width), Math.max(1, box.height), false);
    camera.aspect = Math.max(1, box.width) / Math.max(1, box.height);
    camera.updateProjectionMatrix();
    requestRender();
  };
  window.addEventListener('resize', resize);
  resize();

  // Click (not drag) on a stitch: go there.
  const raycaster = new T.Raycaster(), down = { x: 0, y: 0 };
  renderer.domElement.addEventListener('pointerdown', (e) => { down.x = e.clientX; down.y = e.clientY; });
  renderer.domElement.addEventListener('pointerup', (e) => {
    if (Math.hypot(e.clientX - down.x, e.clientY - down.y) > 5) return;
    const box = renderer.domElement.getBoundingClientRect();
    const ndc = new T.Vector2(((e.clientX - box.left) / box.width) * 2 - 1, -((e.clientY - box.top) / box.height) * 2 + 1);
    camera.updateMatrixWorld();
    raycaster.setFromCamera(ndc, camera);
    const hit = raycaster.intersectObject(mesh)[0];
    if (hit && indexOf[Math.floor(hit.faceIndex / 2)] >= 0) go(indexOf[Math.floor(hit.faceIndex / 2)]);
  });

  let shown = -1;  // the program index the colours show as current
  function show(i) {
    let lo = Math.min(i, shown < 0 ? 0 : shown), hi = Math.max(i, shown < 0 ? N - 1 : shown);
    if (shown < 0) { lo = 0; hi = N - 1; }
    let first = Infinity, last = -1;
    for (let k = lo; k <= hi; ++k) {
      const s = O.stitch[k];
      paint(colour, s, k < i ? COLOURS.done : k === i ? COLOURS.current : COLOURS.todo);
      first = Math.min(first, s); last = Math.max(last, s);
    }
    colourAttr.updateRange = { offset: first * 12, count: (last - first + 1) * 12 };
    colourAttr.needsUpdate = true;
    shown = i;
    const s = O.stitch[i], normal = new T.Vector3(), a = new T.Vector3(), b = new T.Vector3();
    a.fromArray(cells, 12 * s + 6).sub(new T.Vector3().fromArray(cells, 12 * s));
    b.fromArray(cells, 12 * s + 9).sub(new T.Vector3().fromArray(cells, 12 * s + 3));
    normal.crossVectors(a, b).normalize().multiplyScalar(a.length() * 0.3);
    here.geometry.attributes.position.array.set(centre.subarray(3 * s, 3 * s + 3));
    here.geometry.attributes.position.array[0] += normal.x;
    here.geometry.attributes.position.array[1] += normal.y;
    here.geometry.attributes.position.array[2] += normal.z;
    here.geometry.attributes.position.needsUpdate = true;
    here.geometry.computeBoundingSphere();
    keepInView(new T.Vector3().fromArray(centre, 3 * s), normal);
    requestRender();
  }
  function showMarkers(list) {
    const at = new Float32Array(Math.max(1, list.length) * 3);
    list.forEach((s, k) => {  // the marker sits at the stitch's edge where the yarn enters
      for (let d = 0; d < 3; ++d) at[3 * k + d] = (cells[12 * s + d] + cells[12 * s + 9 + d]) / 2;
    });
    markerGeometry.setAttribute('position', new T.BufferAttribute(at, 3));
    markerGeometry.setDrawRange(0, list.length);
    markerGeometry.computeBoundingSphere();
  }
  // The current stitch stays in view: when it leaves the middle of the picture the view pans to
  // it, and when its right side faces away the camera goes round to face it.
  function keepInView(p, normal) {
    camera.updateMatrixWorld();
    const ndc = p.clone().project(camera);
    const toCamera = camera.position.clone().sub(p);
    if (normal.lengthSq() > 0 && normal.dot(toCamera) < 0) {
      const distance = camera.position.distanceTo(controls.target);
      controls.target.copy(p);
      camera.position.copy(p).add(normal.clone().normalize().multiplyScalar(distance));
      camera.position.y += distance * 0.3;  // from a little above, as the work is held
      controls.update();
      return;
    }
    if (Math.abs(ndc.x) < 0.7 && Math.abs(ndc.y) < 0.7 && ndc.z < 1) return;
    const shift = p.clone().sub(controls.target);
    controls.target.add(shift);
    camera.position.add(shift);
    controls.update();
  }
  // The program index the colours show as current, read back from the colour buffer (the
  // self-test checks the picture agrees with the text).
  function currentInPicture() {
    let found = -1, count = 0;
    for (let s = 0; s < S; ++s)
      if (colour[12 * s] === COLOURS.current[0] && colour[12 * s + 1] === COLOURS.current[1]) { found = s; ++count; }
    return { stitch: found, count };
  }
  const stateOf = (s) => {
    const c = colour[12 * s];
    return c === COLOURS.done[0] ? 'done' : c === COLOURS.current[0] ? 'current' : 'todo';
  };
  // Where a stitch's centre is drawn, in the window's pixels.
  function screenPoint(s) {
    camera.updateMatrixWorld();  // the controls may have moved it since the last frame
    const p = new T.Vector3().fromArray(centre, 3 * s).project(camera);
    const box = renderer.domElement.getBoundingClientRect();
    return { x: box.left + ((p.x + 1) / 2) * box.width, y: box.top + ((1 - p.y) / 2) * box.height };
  }
  const toggleYarn = () => { yarnLines.visible = !yarnLines.visible; requestRender(); };
  const distance = (s) => camera.position.distanceTo(new T.Vector3().fromArray(centre, 3 * s));
  view.built = performance.now();
  Object.assign(view, { ok: true, show, showMarkers, currentInPicture, stateOf, render, renderer, camera, screenPoint, distance, toggleYarn });
}

function paint(colour, s, c) {
  for (let v = 0; v < 4; ++v) colour.set(c, 12 * s + 3 * v);
}

// ---- where the knitter is ------------------------------------------------------------------
const rowStart = (i) => { while (i > 0 && O.row[i - 1] === O.row[i]) --i; return i; };
const rowEnd = (i) => { while (i + 1 < N && O.row[i + 1] === O.row[i]) ++i; return i; };
const pieceOf = (i) => D.rows[O.row[i]].p;
let markedRow = -1;

function render(i) {
  const row = D.rows[O.row[i]], b = O.b[i], e = O.e[i];
  $('heading').textContent = row.h;
  const rep = O.reps[i] ? ` \u00b7 repeat ${O.rep[i]} of ${O.reps[i]}` : '';
  $('where').textContent = `${row.l} \u00b7 st ${O.pos[i]} of ${row.n}${rep}`;
  $('instr').innerHTML = b < 0 ? '<mark class="line">' + esc(row.t) + '</mark>'
    : esc(row.t.slice(0, b)) + '<mark>' + esc(row.t.slice(b, e)) + '</mark>' + esc(row.t.slice(e));
  $('instr').dataset.stitch = O.stitch[i];
  $('said').textContent = row.s ? 'Worked as: ' + row.s : '';
  renderChart(i);
  $('counts').textContent = `Stitch ${i + 1} of ${N} \u00b7 ${Math.round((100 * i) / N)}% done` +
    (O.mark[i] ? ' \u00b7 marker before this stitch' : '');
  $('counter').textContent = `${O.row[i]} of ${D.rows.length} rows done \u00b7 st ${i + 1} / ${N}`;
  if (view.ok) {
    view.show(i);
    if (markedRow !== O.row[i]) {
      markedRow = O.row[i];
      const list = [];
      for (let k = rowStart(i), end = rowEnd(i); k <= end; ++k) if (O.mark[k]) list.push(O.stitch[k]);
      view.showMarkers(list);
    }
  }
}

// ---- the row's chart (pieces of knits and purls alone, as the printable page charts) -------
const CHART_CELL = 10, CHART_MARGIN = 26;
const chart = { shown: -1, row: -1 };
const chartHeight = (c) => c.cells.length * CHART_CELL + 4;
const chartY = (c, r) => chartHeight(c) - 2 - (r + 1) * CHART_CELL;  // its first row at the bottom
function chartSvg(c) {
  const cols = c.cells[0].length, C = CHART_CELL, M = CHART_MARGIN;
  const w = cols * C + 2 * M, h = chartHeight(c);
  const out = [`<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 ${w} ${h}" style="--cols:${cols}" role="img">`];
  c.cells.forEach((squares, r) => {
    const y = chartY(c, r);
    for (let x = 0; x < cols; ++x) {
      out.push(`<rect class="sq" x="${M + x * C}" y="${y}" width="${C}" height="${C}"/>`);
      if (squares[x] === 'p') out.push(`<circle class="dot" cx="${M + x * C + C / 2}" cy="${y + C / 2}" r="2"/>`);
    }
    const right = c.left[r];  // the number where the row starts
    out.push(`<text x="${right ? w - M + 3 : M - 3}" y="${y + C - 2}" text-anchor="${right ? 'start' : 'end'}">${c.num[r]}</text>`);
  });
  out.push(`<rect id="chartRow" x="${M}" width="${cols * C}" height="${C}"/><rect id="chartSt" width="${C}" height="${C}"/></svg>`);
  return out.join('');
}
// The current row's chart with that row and the current stitch's square marked; none where
// its piece has no chart.
function renderChart(i) {
  const row = D.rows[O.row[i]], box = $('chartScroll');
  $('chart').hidden = row.c < 0;
  if (row.c < 0) return;
  const c = D.charts[row.c];
  if (chart.shown !== row.c) { box.innerHTML = chartSvg(c); chart.shown = row.c; chart.row = -1; }
  const cols = c.cells[row.cr].length, col = c.left[row.cr] ? cols - O.pos[i] : O.pos[i] - 1;
  const y = chartY(c, row.cr);
  $('chartSt').setAttribute('x', CHART_MARGIN + col * CHART_CELL);
  $('chartSt').setAttribute('y', y);
  box.dataset.col = col;
  if (box.scrollWidth > box.clientWidth) {  // a wide chart (large print) scrolls to the square
    const scale = box.firstChild.getBoundingClientRect().width / box.firstChild.viewBox.baseVal.width;
    const x = (CHART_MARGIN + (col + 0.5) * CHART_CELL) * scale;
    if (x < box.scrollLeft || x > box.scrollLeft + box.clientWidth) box.scrollLeft = x - box.clientWidth / 2;
  }
  if (chart.row === row.cr) return;
  chart.row = row.cr;
  box.dataset.row = row.cr;
  $('chartRow').setAttribute('y', y);
  if (box.scrollHeight > box.clientHeight) {  // a tall chart scrolls: its current row in the middle
    const svg = box.firstChild, scale = svg.getBoundingClientRect().height / chartHeight(c);
    box.scrollTop = (y + CHART_CELL / 2) * scale - box.clientHeight / 2;
  }
}

function save() {
  try { localStorage.setItem(KEY, String(cur)); } catch (err) { /* private mode: no storage */ }
  history.replaceState(null, '', location.pathname + location.search + '#s=' + cur);
}
function restore() {
  const hash = /#s=(\d+)/.exec(location.hash);
  let stored = null;
  try { stored = localStorage.getItem(KEY); } catch (err) { /* no storage */ }
  const at = hash ? Number(hash[1]) : stored !== null ? Number(stored) : 0;
  return Number.isFinite(at) ? Math.min(Math.max(0, at), N - 1) : 0;
}

let toastTimer = 0;
function go(i, quiet) {
  cur = Math.min(Math.max(0, i), N - 1);
  render(cur);
  save();
  if (quiet) return;
  $('toast').textContent = `Stitch ${cur + 1}`;
  $('toast').classList.add('on');
  clearTimeout(toastTimer);
  toastTimer = setTimeout(() => $('toast').classList.remove('on'), 700);
}
const nextRow = () => go(rowEnd(cur) + 1);
const prevRow = () => go(cur === rowStart(cur) ? rowStart(Math.max(0, cur - 1)) : rowStart(cur));
function nextSection() {
  let i = cur;
  while (i + 1 < N && pieceOf(i + 1) === pieceOf(cur)) ++i;
  go(i + 1);
}
function prevSection() {
  let i = cur;
  while (i > 0 && pieceOf(i - 1) === pieceOf(cur)) --i;
  if (i === cur && i > 0) { --i; while (i > 0 && pieceOf(i - 1) === pieceOf(cur - 1)) --i; }
  go(i);
}

const actions = {
  next: () => go(cur + 1), prev: () => go(cur - 1), nextRow, prevRow, nextSection, prevSection,
  yarn: () => { if (view.ok) view.toggleYarn(); },
  big: () => { document.body.classList.toggle('big'); localStorage.setItem('skein-page:big', document.body.classList.contains('big') ? '1' : ''); },
  reset: () => { if (query.has('selftest') || confirm('Start again from the first stitch?')) go(0); },
};
for (const [id, act] of Object.entries(actions)) if ($(id)) $(id).addEventListener('click', act);

// Keys (a foot pedal or page turner sends these); a second press within 250 ms that is not a
// key held down is a pedal's bounce.
let lastKey = '', lastTime = 0;
document.addEventListener('keydown', (e) => {
  const map = { ArrowRight: 'next', ' ': 'next', PageDown: 'next', ArrowLeft: 'prev',
    Backspace: 'prev', PageUp: 'prev', ArrowUp: e.shiftKey ? 'nextSection' : 'nextRow',
    ArrowDown: e.shiftKey ? 'prevSection' : 'prevRow', b: 'big', B: 'big', y: 'yarn', Y: 'yarn' };
  const act = map[e.key];
  if (!act || e.ctrlKey || e.metaKey || e.altKey) return;
  e.preventDefault();
  const now = performance.now();
  if (!e.repeat && e.key === lastKey && now - lastTime < 250) return;
  lastKey = e.key; lastTime = now;
  actions[act]();
});

// ---- self-tests ----------------------------------------------------------------------------
function report(text) { $('selftest').textContent = text; document.title = text.split('\n')[0]; }

function selftestSteps() {
  const t0 = performance.now(), errors = [], seen = new Uint8Array(D.stitches);
  let rows = 0, inRow = 0, charted = 0;
  for (let i = 0; i < N && errors.length < 10; ++i) {
    go(i, true);
    const s = O.stitch[i], row = D.rows[O.row[i]];
    if (seen[s]++) errors.push(`stitch ${s} comes twice (program index ${i})`);
    if (Number($('instr').dataset.stitch) !== s) errors.push(`step ${i}: the text names another stitch`);
    const where = $('where').textContent;
    if (!where.includes(`st ${O.pos[i]} of ${row.n}`)) errors.push(`step ${i}: '${where}'`);
    const mark = $('instr').querySelector('mark');
    if (!mark || !mark.textContent) errors.push(`step ${i}: nothing marked in the text`);
    if (view.ok) {
      if (view.stateOf(s) !== 'current') errors.push(`step ${i}: stitch ${s} is not current in 3D`);
      if (i > 0 && view.stateOf(O.stitch[i - 1]) !== 'done') errors.push(`step ${i}: the stitch before is not done in 3D`);
      if (i + 1 < N && view.stateOf(O.stitch[i + 1]) !== 'todo') errors.push(`step ${i}: the stitch after is not to do in 3D`);
    }
    checkChart(i, errors);
    ++inRow;
    if (i + 1 === N || O.row[i + 1] !== O.row[i]) {  // the row's end: the counts agree
      ++rows;
      charted += row.c >= 0 ? 1 : 0;
      if (view.ok) {
        const pic = view.currentInPicture();
        if (pic.count !== 1 || pic.stitch !== s) errors.push(`row ${row.l}: the picture shows ${pic.count} current stitch(es)`);
      }
      if (O.pos[i] !== row.n || inRow !== row.n) errors.push(`row ${row.l}: ${inRow} sts stepped, st ${O.pos[i]} last, the row has ${row.n}`);
      inRow = 0;
    }
  }
  const missing = seen.reduce((n, v) => n + (v === 0 ? 1 : 0), 0);
  if (missing) errors.push(`${missing} stitches never stepped on`);
  const stepMs = (performance.now() - t0) / N;
  const clicked = checkKeysAndClicks(errors);
  // The layout fits the window: nothing wider than it (a phone scrolls down, never across).
  const wide = document.documentElement.scrollWidth;
  if (wide > window.innerWidth) errors.push(`the page is ${wide} px wide in a ${window.innerWidth} px window`);
  report((errors.length ? 'selftest: FAIL\n' + errors.join('\n')
    : `selftest: ok ${N} stitches, ${rows} rows checked, 3D ${view.ok ? 'checked' : 'absent'}` +
      `${clicked ? ', click checked' : ''}${charted ? `, ${charted} chart rows checked` : ''}, window ${window.innerWidth}x${window.innerHeight}`) +
    '\n' + timings(0, stepMs));
}

// A row of a charted piece shows its chart, the row marked where the chart prints that row's
// number and the current stitch's square in it, counted from where the row starts; any other
// row shows none.
function checkChart(i, errors) {
  const row = D.rows[O.row[i]];
  if (row.c < 0) {
    if (!$('chart').hidden) errors.push(`step ${i}: ${row.l} shows a chart; its piece has none`);
    return;
  }
  const c = D.charts[row.c], r = row.cr, squares = c.cells[r];
  if ($('chart').hidden) return errors.push(`step ${i}: ${row.l} shows no chart`);
  if (!new RegExp(`^(Row|Rnd) ${c.num[r]}\\b`).test(row.l)) errors.push(`step ${i}: chart row ${c.num[r]} for ${row.l}`);
  if (squares.length !== row.n) errors.push(`${row.l}: ${row.n} sts, ${squares.length} squares in its chart row`);
  const marked = $('chartRow'), here = $('chartSt');
  const number = [...$('chartScroll').querySelectorAll('text')].find((t) => t.textContent === String(c.num[r]));
  if (!number || Number(number.getAttribute('y')) !== Number(marked.getAttribute('y')) + CHART_CELL - 2)
    errors.push(`step ${i}: the chart marks another row than ${c.num[r]}`);
  const col = (Number(here.getAttribute('x')) - CHART_MARGIN) / CHART_CELL;
  const want = c.left[r] ? squares.length - O.pos[i] : O.pos[i] - 1;
  if (here.getAttribute('y') !== marked.getAttribute('y') || col !== want)
    errors.push(`step ${i}: the chart marks square ${col} of its row, not ${want}`);
}

// Keys step as the help says (a different key each time: a second press of one key within
// 250 ms is a pedal's bounce), and a click on a stitch in the model goes there. Says whether
// the click was tried (there is a model drawn).
function checkKeysAndClicks(errors) {
  const press = (key, shiftKey) => document.dispatchEvent(new KeyboardEvent('keydown', { key, shiftKey }));
  const start = Math.min(N - 1, rowEnd(0) + 3);
  go(start, true);
  press('ArrowRight');
  press(' ');
  press('ArrowLeft');
  if (cur !== start + 1) errors.push(`keys: Right, Space, Left from ${start} went to ${cur}`);
  press('ArrowUp');
  if (cur !== Math.min(N - 1, rowEnd(start) + 1)) errors.push(`keys: Up went to ${cur}, not the next row`);
  press('ArrowDown');
  if (cur !== rowStart(start)) errors.push(`keys: Down went to ${cur}, not the row's start`);
  if (!view.ok) return false;
  // The view faces the current stitch; its neighbour along the row is in sight beside it.
  go(start, true);
  const target = start + 1 < N && O.row[start + 1] === O.row[start] ? start + 1 : start;
  const at = view.screenPoint(O.stitch[target]), canvas = view.renderer.domElement;
  for (const type of ['pointerdown', 'pointerup'])
    canvas.dispatchEvent(new PointerEvent(type, { clientX: at.x, clientY: at.y, bubbles: true }));
  // Another part of the model may hide it (the letter R's bowl): the click takes what is in front.
  const hidden = cur !== target && view.distance(O.stitch[cur]) < view.distance(O.stitch[target]);
  if (cur !== target && !hidden) errors.push(`a click on stitch ${O.stitch[target]} went to ${O.stitch[cur]}`);
  return true;
}

// What a knitter waits for: the page's start, and a step (text and colours) with and without
// its frame drawn (readPixels waits for the drawing, not only its queueing).
function timings(from, stepMs) {
  const frames = Math.min(N - from, 30), t = performance.now();
  for (let i = from; i < from + frames; ++i) { go(i, true); if (view.ok) view.render(true); }
  const frameMs = (performance.now() - t) / frames;
  go(0, true);
  return `perf: ${N} stitches, script ${Math.round(scriptStart)} ms, view built ` +
    `${Math.round(view.built || -1)} ms, first frame ${Math.round(window.__skeinFirstFrame || -1)} ms, ` +
    `step ${stepMs.toFixed(3)} ms, step with frame ${frameMs.toFixed(2)} ms`;
}

// Timings alone, from the middle of the work (for models too large to step through in a test).
function selftestPerf() {
  const from = Math.floor(N / 2), steps = Math.min(N - from, 2000), t = performance.now();
  for (let i = from; i < from + steps; ++i) go(i, true);
  report(timings(from, (performance.now() - t) / steps));
}

function selftestReload() {
  const flag = 'skein-selftest-reload';
  const want = sessionStorage.getItem(flag);
  if (want === null) {
    const at = Math.min(N - 1, 37);
    go(at, true);
    sessionStorage.setItem(flag, String(at));
    history.replaceState(null, '', location.pathname + location.search);  // restore from storage alone
    location.reload();
    return;
  }
  sessionStorage.removeItem(flag);
  report(cur === Number(want) ? `reload: ok restored stitch ${cur}` : `reload: FAIL at ${cur}, saved ${want}`);
}

// ---- start ---------------------------------------------------------------------------------
if (query.has('big') || localStorage.getItem('skein-page:big')) document.body.classList.add('big');
try { buildView(); } catch (err) { $('view').insertAdjacentHTML('beforeend', '<p id="no3d">No 3D view: ' + esc(String(err)) + '</p>'); }
go(restore(), true);
// The self-tests run before the page's load event, so that `--dump-dom` (which waits for it)
// reads their report without virtual time (which would make the timings meaningless).
const test = query.get('selftest');
if (test === 'reload') selftestReload();
else if (test) {
  if (view.ok) view.render();
  if (test === 'perf') selftestPerf(); else selftestSteps();
}
window.__skein = { go, state: () => cur, data: D };
window.__skeinReady = true;
})();
)JS";

}  // namespace skein::hand_web
