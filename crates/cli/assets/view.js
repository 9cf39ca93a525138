// vectrix view: draws a run's bodies from its sampled poses (issue 36). Follows the inlined
// three.js (`THREE`). The data is the JSON of the element #vectrix-data (see crates/cli/src/
// view.rs): t[k], pose[(k·B + b)·7 + 0..7] = position (x, y, z) and attitude (w, x, y, z) of
// body b's link frame in the ground frame. Between samples: positions linearly, attitudes by
// slerp. Hooks for tests: window.vectrixView.
const D = JSON.parse(document.getElementById('vectrix-data').textContent);
const $ = (id) => document.getElementById(id);
const note = (s) => { $('note').textContent += ($('note').textContent ? ' · ' : '') + s; };
const V3 = (a) => new THREE.Vector3(a[0], a[1], a[2]);
const B = D.bodies.length, F = D.t.length;
const SPEEDS = [0.1, 0.25, 0.5, 1, 2, 3, 5, 7.5, 10];
const AIR = (b) => b && b.shape.kind === 'aircraft';

// ---- poses at sample k, and interpolated at time t ----
const posAt = (k, b) => { const i = (k * B + b) * 7; return new THREE.Vector3(D.pose[i], D.pose[i + 1], D.pose[i + 2]); };
const quatAt = (k, b) => { const i = (k * B + b) * 7 + 3; return new THREE.Quaternion(D.pose[i + 1], D.pose[i + 2], D.pose[i + 3], D.pose[i]); };
function sampleIndex(t) { // largest k with t[k] <= t
  let lo = 0, hi = F - 1;
  if (t <= D.t[0]) return 0;
  if (t >= D.t[hi]) return hi;
  while (hi - lo > 1) { const m = (lo + hi) >> 1; if (D.t[m] <= t) lo = m; else hi = m; }
  return lo;
}
function poseAt(t, b) {
  const k = sampleIndex(t), k1 = Math.min(k + 1, F - 1);
  const span = D.t[k1] - D.t[k], a = span > 0 ? Math.min(Math.max((t - D.t[k]) / span, 0), 1) : 0;
  const p = posAt(k, b).lerp(posAt(k1, b), a);
  const q = new THREE.Quaternion().slerpQuaternions(quatAt(k, b), quatAt(k1, b), a);
  return { p, q, k, a };
}
const worldPoint = (pose, local) => V3(local).applyQuaternion(pose.q).add(pose.p);

// ---- sizes: the extent of everything drawn ----
function shapeSize(s) {
  switch (s.kind) {
    case 'box': return Math.max(...s.sides);
    case 'sphere': case 'disk': return 2 * s.radius;
    case 'cylinder': return Math.max(2 * s.radius, s.length);
    case 'rod': return s.length;
    case 'aircraft': return s.span;
    default: return 0;
  }
}
const box = new THREE.Box3();
for (let k = 0; k < F; k++) for (let b = 0; b < B; b++) {
  box.expandByPoint(posAt(k, b));
  box.expandByPoint(V3(D.bodies[b].com).applyQuaternion(quatAt(k, b)).add(posAt(k, b)));
}
if (box.isEmpty()) box.expandByPoint(new THREE.Vector3());
const centre = box.getCenter(new THREE.Vector3()), extent = box.getSize(new THREE.Vector3());
const L = F ? Math.max(extent.length(), ...D.bodies.map((b) => shapeSize(b.shape)), 1e-6) : 1;
// a scene with an aircraft body: the camera follows the (first) aircraft, at its scale
const air = D.bodies.findIndex(AIR);
const flight = air >= 0;
const S = flight ? D.bodies[air].shape.span : L; // size of markers and triads
const up = V3(D.up).normalize();

// ---- three.js scene ----
const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
renderer.setPixelRatio(window.devicePixelRatio || 1);
$('view').appendChild(renderer.domElement);
const scene = new THREE.Scene();
scene.background = new THREE.Color(0xf4f5f7);
const camera = new THREE.PerspectiveCamera(45, 1, S * (flight ? 0.02 : 1e-3), (flight ? 1e3 * S + 4 * L : 100 * L));
camera.up.copy(up);
scene.add(new THREE.HemisphereLight(0xffffff, 0x8890a0, 2.2));
const sun = new THREE.DirectionalLight(0xffffff, 1.6);
sun.position.copy(up).multiplyScalar(3).add(new THREE.Vector3(1, 0.6, 0.3));
scene.add(sun);
const material = (color) => new THREE.MeshStandardMaterial({ color, roughness: 0.55, metalness: 0.05 });
const lineMat = (color) => new THREE.LineBasicMaterial({ color });
const COLORS = [0x3b6fb6, 0xd0713a, 0x4a9a55, 0xb0413e, 0x7d5ba6, 0x8c6d3f, 0xc45ca2, 0x5f7a85];

function label(text, size, color = '#223') {
  const c = document.createElement('canvas'), g = c.getContext('2d'), px = 48;
  g.font = `${px}px sans-serif`;
  c.width = Math.ceil(g.measureText(text).width) + 8; c.height = px + 12;
  g.font = `${px}px sans-serif`; g.fillStyle = color; g.textBaseline = 'middle';
  g.fillText(text, 4, c.height / 2);
  const sprite = new THREE.Sprite(new THREE.SpriteMaterial({ map: new THREE.CanvasTexture(c), depthTest: false }));
  sprite.scale.set(size * c.width / c.height, size, 1);
  sprite.renderOrder = 2;
  return sprite;
}
// A labelled axis triad: red x, green y, blue z (signs flip axes drawn in flipped coordinates).
function triad(name, len, names = ['x', 'y', 'z'], signs = [1, 1, 1]) {
  const g = new THREE.Group(), cols = [0xcc3333, 0x33aa33, 0x3355cc];
  for (let i = 0; i < 3; i++) {
    const d = new THREE.Vector3(); d.setComponent(i, signs[i]);
    g.add(new THREE.ArrowHelper(d, new THREE.Vector3(), len, cols[i], 0.15 * len, 0.07 * len));
    const l = label(names[i], 0.16 * len, '#' + cols[i].toString(16).padStart(6, '0'));
    l.position.copy(d).multiplyScalar(1.12 * len); g.add(l);
  }
  if (name) { const l = label(name, 0.14 * len); l.position.set(-0.1 * len, -0.1 * len, -0.1 * len); g.add(l); }
  return g;
}
// A body's drawing in its link frame: the mass shape at its centre of mass.
function bodyMesh(b, color) {
  const s = b.shape, m = material(color), g = new THREE.Group();
  let mesh = null;
  const thin = (x, big) => Math.max(x, 0.02 * big, 1e-9);
  switch (s.kind) {
    case 'box': { const big = Math.max(...s.sides); mesh = new THREE.Mesh(new THREE.BoxGeometry(...s.sides.map((x) => thin(x, big))), m);
      if (s.axes) mesh.quaternion.set(s.axes[1], s.axes[2], s.axes[3], s.axes[0]); break; }
    case 'sphere': mesh = new THREE.Mesh(new THREE.SphereGeometry(s.radius, 32, 16), m); break;
    case 'rod': mesh = new THREE.Mesh(new THREE.CylinderGeometry(thin(0.02 * s.length, s.length), thin(0.02 * s.length, s.length), s.length, 16), m);
      mesh.rotation.z = -Math.PI / 2; break; // cylinder axis y → link x
    case 'disk': mesh = new THREE.Mesh(new THREE.CylinderGeometry(s.radius, s.radius, 0.06 * s.radius, 48), m);
      mesh.rotation.x = Math.PI / 2; break; // cylinder axis y → link z
    case 'cylinder': mesh = new THREE.Mesh(new THREE.CylinderGeometry(s.radius, s.radius, s.length, 48), m);
      mesh.rotation.x = Math.PI / 2; break; // axis y → link z
    case 'particle': mesh = new THREE.Mesh(new THREE.SphereGeometry(0.025 * L, 20, 10), m); break;
    case 'massless': mesh = new THREE.Mesh(new THREE.SphereGeometry(0.012 * L, 12, 6), new THREE.MeshBasicMaterial({ color, wireframe: true })); break;
    case 'aircraft': { // fuselage along x, wing along y, fins; drawn in M-flipped body axes (z up)
      const l = s.length, w = s.span;
      mesh = new THREE.Group();
      const fus = new THREE.Mesh(new THREE.CylinderGeometry(0.045 * l, 0.03 * l, l, 16), m); fus.rotation.z = -Math.PI / 2; mesh.add(fus);
      const wing = new THREE.Mesh(new THREE.BoxGeometry(0.16 * l, w, 0.012 * l), m); wing.position.x = 0.05 * l; mesh.add(wing);
      const tail = new THREE.Mesh(new THREE.BoxGeometry(0.1 * l, 0.38 * w, 0.01 * l), m); tail.position.x = -0.44 * l; mesh.add(tail);
      const fin = new THREE.Mesh(new THREE.BoxGeometry(0.12 * l, 0.01 * l, 0.16 * l), m); fin.position.set(-0.44 * l, 0, 0.08 * l); mesh.add(fin);
      if (s.zdown) mesh.rotation.x = Math.PI; // a body scene's aircraft axes: z down, the fin up
      break;
    }
    default: break;
  }
  if (mesh) { mesh.position.add(V3(b.com)); g.add(mesh); }
  const tl = AIR(b) ? 0.6 * s.span : Math.max(0.7 * shapeSize(s), 0.12 * L);
  g.add(AIR(b) ? triad(b.name, tl, ['x_B', 'y_B', 'z_B'], s.zdown ? [1, 1, 1] : [1, -1, -1]) : triad(b.name, tl));
  return g;
}
const bodyGroups = D.bodies.map((b, i) => { const g = bodyMesh(b, COLORS[i % COLORS.length]); scene.add(g); return g; });

// ground: grid perpendicular to up, below everything; the ground triad and the named frames
// (a flight's grid is small and moves under the aircraft by whole cells: SwiftShader drops the
// near part of a grid whose lines reach far behind the camera)
const cell = Math.pow(10, Math.floor(Math.log10(flight ? S : L / 2)));
const gridSize = cell * (flight ? 40 : Math.ceil(3 * L / cell));
const grid = new THREE.GridHelper(gridSize, Math.round(gridSize / cell), 0x9aa3b2, 0xd0d5de);
grid.quaternion.setFromUnitVectors(new THREE.Vector3(0, 1, 0), up);
let lowest = Infinity;
for (const c of [box.min, box.max]) lowest = Math.min(lowest, c.dot(up));
const drop = flight ? 4 * S : 0.15 * L + Math.max(0, ...D.bodies.map((b) => shapeSize(b.shape) / 2));
const gridLevel = lowest - drop;
scene.add(grid);
if (!flight) {
  scene.add(triad('ground', 0.2 * L));
  for (const f of D.frames) { const t = triad(f.name, 0.16 * L); t.quaternion.set(f.q[1], f.q[2], f.q[3], f.q[0]); scene.add(t); }
}
if (D.gravity) {
  const g = V3(D.gravity), n = g.length();
  if (n > 0) {
    const R = flight ? 1.5 * S : L; // beside the aircraft, which it follows; else beside the scene
    const at = centre.clone().addScaledVector(up, 0.5 * R).add(new THREE.Vector3(0.6 * R, 0, 0).projectOnPlane(up));
    const arrow = new THREE.ArrowHelper(g.clone().divideScalar(n), at, 0.35 * S, 0x666666, 0.08 * S, 0.04 * S);
    const l = label(`g = ${n.toPrecision(4)}`, 0.05 * S); l.position.copy(at).addScaledVector(up, 0.06 * S);
    const gravity = new THREE.Group(); gravity.add(arrow, l); scene.add(gravity);
    gravity.userData.offset = at.clone().sub(centre);
    scene.userData.gravity = gravity;
  }
}
for (const c of D.centres) { const m = new THREE.Mesh(new THREE.SphereGeometry(0.03 * L, 16, 8), material(0x444444)); m.position.copy(V3(c)); scene.add(m); }

// joints (parent point → joint point → link origin → centre of mass) and loops, force elements
const jointLines = D.bodies.map(() => { const l = new THREE.Line(new THREE.BufferGeometry().setFromPoints([0, 1, 2, 3].map(() => new THREE.Vector3())), lineMat(0x555555)); scene.add(l); return l; });
const marker = (color, r) => { const m = new THREE.Mesh(new THREE.SphereGeometry(r, 12, 8), material(color)); scene.add(m); return m; };
const jointMarks = D.bodies.map(() => marker(0x333333, 0.012 * S));
const LINK_COLORS = { spring: 0x2a8a8a, dashpot: 0x8a5a2a, inerter: 0x6a2a8a };
const links = D.links.map((l) => ({ l, line: (() => { const x = new THREE.Line(new THREE.BufferGeometry().setFromPoints([new THREE.Vector3(), new THREE.Vector3()]), lineMat(LINK_COLORS[l.kind] || 0xaa2222)); scene.add(x); return x; })(),
  ma: marker(LINK_COLORS[l.kind] || 0xaa2222, 0.014 * S), mb: marker(LINK_COLORS[l.kind] || 0xaa2222, 0.01 * S) }));

// trails of the bodies whose positions are outputs (the centre of mass at every sample)
const trails = D.trails.map((b, i) => {
  const pts = new Float32Array(3 * F);
  for (let k = 0; k < F; k++) V3(D.bodies[b].com).applyQuaternion(quatAt(k, b)).add(posAt(k, b)).toArray(pts, 3 * k);
  const geo = new THREE.BufferGeometry(); geo.setAttribute('position', new THREE.BufferAttribute(pts, 3));
  const line = new THREE.Line(geo, lineMat(COLORS[(b + i) % COLORS.length])); scene.add(line);
  return line;
});

// ---- camera: orbit, pan, zoom (own controls: no addon to inline) ----
const view = { target: new THREE.Vector3(), dist: 1, yaw: 0, pitch: 0, follow: -1, followAt: null };
// the default view looks across the plane of least motion (a planar mechanism face on)
function resetCamera() {
  const e = [extent.x, extent.y, extent.z], big = Math.max(...e);
  let dir = new THREE.Vector3(1, -1.4, 0.9).normalize();
  const flat = e.indexOf(Math.min(...e));
  if (!flight && big > 0.05 * L && e[flat] < 0.1 * big) { dir = new THREE.Vector3(); dir.setComponent(flat, 1); dir.addScaledVector(up, 0.35).normalize(); }
  if (flight) dir = new THREE.Vector3(-1, -1.2, 0).projectOnPlane(up).addScaledVector(up, 0.5).normalize();
  const basis = basisOf(); // yaw/pitch relative to up
  view.pitch = Math.asin(Math.max(-0.99, Math.min(0.99, dir.dot(up))));
  view.yaw = Math.atan2(dir.dot(basis[1]), dir.dot(basis[0]));
  view.target.copy(flight ? poseAt(now.t, air).p : centre);
  view.dist = flight ? 3 * S : 1.9 * L;
  view.follow = flight ? air : -1; $('follow').value = String(view.follow); view.followAt = null;
}
function basisOf() { // two unit vectors perpendicular to up
  const a = Math.abs(up.x) < 0.9 ? new THREE.Vector3(1, 0, 0) : new THREE.Vector3(0, 1, 0);
  const e1 = a.projectOnPlane(up).normalize(), e2 = new THREE.Vector3().crossVectors(up, e1);
  return [e1, e2];
}
function placeCamera() {
  const [e1, e2] = basisOf(), c = Math.cos(view.pitch);
  const dir = e1.multiplyScalar(c * Math.cos(view.yaw)).addScaledVector(e2, c * Math.sin(view.yaw)).addScaledVector(up, Math.sin(view.pitch));
  camera.position.copy(view.target).addScaledVector(dir, view.dist);
  camera.lookAt(view.target);
}
let drag = null;
const canvas = renderer.domElement;
canvas.addEventListener('contextmenu', (e) => e.preventDefault());
canvas.addEventListener('pointerdown', (e) => { drag = { x: e.clientX, y: e.clientY, pan: e.button === 2 || e.shiftKey }; canvas.setPointerCapture(e.pointerId); });
canvas.addEventListener('pointerup', () => { drag = null; });
canvas.addEventListener('pointermove', (e) => {
  if (!drag) return;
  const dx = e.clientX - drag.x, dy = e.clientY - drag.y; drag.x = e.clientX; drag.y = e.clientY;
  if (drag.pan) {
    const s = view.dist * 0.0015, right = new THREE.Vector3().setFromMatrixColumn(camera.matrix, 0), upc = new THREE.Vector3().setFromMatrixColumn(camera.matrix, 1);
    view.target.addScaledVector(right, -dx * s).addScaledVector(upc, dy * s);
  } else { view.yaw -= dx * 0.008; view.pitch = Math.max(-1.5, Math.min(1.5, view.pitch + dy * 0.008)); }
  redraw();
});
canvas.addEventListener('wheel', (e) => { e.preventDefault(); view.dist *= Math.exp(e.deltaY * 0.001); redraw(); }, { passive: false });

// ---- time ----
const t0 = F ? D.t[0] : 0, tEnd = F ? D.t[F - 1] : 0;
const rate = tEnd - t0 > 60 ? (tEnd - t0) / 60 : 1; // seconds of t per second at 1×
const now = { t: t0, playing: false, speed: 1, last: null, drawn: NaN };
const intervals = [], renders = [];
function hudText(t) {
  const h = D.hud, n = h.names.length;
  $('hud-t').textContent = `${D.name}  t = ${t.toFixed(3)} s of ${tEnd.toPrecision(6)} s  (${now.speed}×, 1× = ${rate.toPrecision(3)} s per s)${D.complete ? '' : '  [run incomplete]'}`;
  if (!n || !F) { $('hud-out').textContent = ''; return; }
  const k = sampleIndex(t), k1 = Math.min(k + 1, F - 1), span = D.t[k1] - D.t[k], a = span > 0 ? (t - D.t[k]) / span : 0;
  const parts = [];
  for (let i = 0; i < n; i++) {
    const v = (1 - a) * h.values[k * n + i] + a * h.values[k1 * n + i];
    parts.push(`${h.names[i]} = ${v.toPrecision(6)}${h.units[i] && h.units[i] !== '1' ? ' ' + h.units[i] : ''}`);
  }
  $('hud-out').textContent = parts.join('   ');
}
function update(t) {
  const poses = D.bodies.map((_, b) => poseAt(t, b));
  poses.forEach((p, b) => {
    bodyGroups[b].position.copy(p.p); bodyGroups[b].quaternion.copy(p.q);
    const body = D.bodies[b], par = body.parent >= 0 ? poses[body.parent] : null;
    const j = par ? worldPoint(par, body.offset) : V3(body.offset);
    const from = par ? worldPoint(par, D.bodies[body.parent].com) : j;
    jointLines[b].geometry.setFromPoints([from, j, p.p, worldPoint(p, body.com)]);
    jointMarks[b].position.copy(j);
  });
  for (const x of links) {
    const at = (a) => (a[0] >= 0 ? worldPoint(poses[a[0]], a.slice(1)) : V3(a.slice(1)));
    const pa = at(x.l.a), pb = at(x.l.b);
    x.line.geometry.setFromPoints([pa, pb]); x.ma.position.copy(pa); x.mb.position.copy(pb);
  }
  const k = F ? sampleIndex(t) : 0;
  for (const tr of trails) tr.geometry.setDrawRange(0, k + 1);
  if (view.follow >= 0 && poses[view.follow]) {
    const c = worldPoint(poses[view.follow], D.bodies[view.follow].com);
    if (view.followAt) view.target.add(c.clone().sub(view.followAt));
    view.followAt = c;
  }
  // the grid stays under the scene; in flight it is moved by whole cells under the aircraft
  const base = flight && poses[air] ? poses[air].p.clone().projectOnPlane(up) : centre.clone().projectOnPlane(up);
  if (flight) base.set(Math.round(base.x / (10 * cell)) * 10 * cell, Math.round(base.y / (10 * cell)) * 10 * cell, Math.round(base.z / (10 * cell)) * 10 * cell).projectOnPlane(up);
  grid.position.copy(base).addScaledVector(up, gridLevel);
  if (flight && scene.userData.gravity && poses[air]) scene.userData.gravity.position.copy(poses[air].p).sub(centre);
  hudText(t);
  now.drawn = t;
}
function redraw() {
  const start = performance.now();
  update(now.t);
  placeCamera();
  renderer.render(scene, camera);
  renders.push(performance.now() - start); if (renders.length > 240) renders.shift();
  $('slider').value = String(tEnd > t0 ? Math.round(1000 * (now.t - t0) / (tEnd - t0)) : 0);
}
function setTime(t) { now.t = Math.min(Math.max(t, t0), tEnd); redraw(); }
function play() { if (F < 2) return; if (now.t >= tEnd) now.t = t0; now.playing = true; now.last = null; $('play').textContent = 'pause'; }
function pause() { now.playing = false; $('play').textContent = 'play'; }
function setSpeed(s) { now.speed = s; $('speed').value = String(s); hudText(now.t); }
function tick(stamp) {
  if (now.last !== null) { intervals.push(stamp - now.last); if (intervals.length > 240) intervals.shift(); }
  const dt = now.last === null ? 0 : (stamp - now.last) / 1000;
  now.last = stamp;
  if (now.playing) {
    now.t += dt * rate * now.speed;
    if (now.t > tEnd) { if ($('loop').checked) now.t = t0 + ((now.t - t0) % Math.max(tEnd - t0, 1e-300)); else { now.t = tEnd; pause(); } }
  }
  redraw();
  requestAnimationFrame(tick);
}
function resize() {
  const w = $('view').clientWidth, h = $('view').clientHeight;
  renderer.setSize(w, h); camera.aspect = w / Math.max(h, 1); camera.updateProjectionMatrix(); redraw();
}

// ---- controls ----
for (const s of SPEEDS) { const o = document.createElement('option'); o.value = String(s); o.textContent = `${s}×`; $('speed').appendChild(o); }
D.bodies.forEach((b, i) => { const o = document.createElement('option'); o.value = String(i); o.textContent = b.name; $('follow').appendChild(o); });
$('speed').value = '1';
$('speed').addEventListener('change', () => setSpeed(Number($('speed').value)));
$('play').addEventListener('click', () => (now.playing ? pause() : play()));
$('slider').addEventListener('input', () => { pause(); setTime(t0 + (tEnd - t0) * Number($('slider').value) / 1000); });
$('follow').addEventListener('change', () => { view.follow = Number($('follow').value); view.followAt = null; redraw(); });
$('reset').addEventListener('click', () => { resetCamera(); redraw(); });
window.addEventListener('keydown', (e) => {
  if (e.target && e.target.tagName === 'SELECT') return;
  const step = (tEnd - t0) / (e.shiftKey ? 10 : 100), i = SPEEDS.indexOf(now.speed);
  if (e.key === ' ') { e.preventDefault(); if (now.playing) pause(); else play(); }
  else if (e.key === 'ArrowRight') { pause(); setTime(now.t + step); }
  else if (e.key === 'ArrowLeft') { pause(); setTime(now.t - step); }
  else if (e.key === 'ArrowUp') setSpeed(SPEEDS[Math.min(i + 1, SPEEDS.length - 1)]);
  else if (e.key === 'ArrowDown') setSpeed(SPEEDS[Math.max(i - 1, 0)]);
  else if (e.key >= '1' && e.key <= '9') setSpeed(SPEEDS[Number(e.key) - 1]);
  else if (e.key === 'r') { resetCamera(); redraw(); }
});
window.addEventListener('resize', resize);

if (D.note) note(D.note);
if (D.dropped) note(`${D.dropped} samples with non-finite values dropped (not drawn)`);
if (!F) { $('play').disabled = true; $('slider').disabled = true; }
// hides or shows everything that moves (bodies, joints, loops, force elements, trails)
function showMoving(on) {
  for (const o of [...bodyGroups, ...jointLines, ...jointMarks, ...trails, ...links.flatMap((x) => [x.line, x.ma, x.mb])]) o.visible = on;
  redraw();
}
const mean = (a) => (a.length ? a.reduce((x, y) => x + y, 0) / a.length : NaN);
window.vectrixView = {
  setTime, play, pause, setSpeed, showMoving,
  time: () => now.t, drawnTime: () => now.drawn, playing: () => now.playing, speed: () => now.speed,
  start: t0, end: tEnd, frames: F, bodies: B,
  frameTimeMs: () => mean(intervals), renderMs: () => mean(renders),
};
resetCamera();
resize();
requestAnimationFrame(tick);
