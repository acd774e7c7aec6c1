// The view page's script: in come three.js (inline, as text) and the run (inline JSON: t, the
// columns the view reads, the view itself); out comes the scene, played in time. Once drawn,
// `window.gyroView` lets other scripts on the page load another run of the same view.
// Space axes N1, N2, N3 are three's x, y, z turned so that the view's `up` axis is z (a
// cyclic permutation: the data are read through SPACE).

let data = JSON.parse(document.getElementById('view-data').textContent);
const params = readParams();
const FOV = numbers('fov', 1)?.[0] ?? data.fov; // vertical field of view, degrees
const DEFAULT_AZIMUTH = 40; // degrees from N1 toward N2
const DEFAULT_ELEVATION = 20; // degrees above the horizontal plane

/** The rotation from space axes to drawn axes that puts space axis `up` (1, 2, 3) upward, or
 * its negative (-1, -2, -3) downward. */
function spaceTurn(up) {
  const m = new THREE.Matrix4();
  if (Math.abs(up) === 1) m.set(0, 1, 0, 0, 0, 0, 1, 0, 1, 0, 0, 0, 0, 0, 0, 1);
  if (Math.abs(up) === 2) m.set(0, 0, 1, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 1);
  const q = new THREE.Quaternion().setFromRotationMatrix(m);
  if (up < 0) q.premultiply(new THREE.Quaternion().setFromAxisAngle(new THREE.Vector3(1, 0, 0), Math.PI));
  return q;
}

/** The rotation turning a shape's z axis to body axis `axis` (1, 2, 3). */
function axisTurn(axis) {
  const to = [new THREE.Vector3(1, 0, 0), new THREE.Vector3(0, 1, 0), new THREE.Vector3(0, 0, 1)][(axis ?? 3) - 1];
  return new THREE.Quaternion().setFromUnitVectors(new THREE.Vector3(0, 0, 1), to);
}

/** The rotation turning a shape's axes to body axes: `turn` (rows `B_i . S_j`, an ellipsoid of
 * inertia's principal axes) when given, else its z axis to body axis `axis`. */
function shapeTurn(body) {
  if (!body.turn) return axisTurn(body.axis);
  const c = body.turn;
  const m = new THREE.Matrix4().set(c[0], c[1], c[2], 0, c[3], c[4], c[5], 0, c[6], c[7], c[8], 0, 0, 0, 0, 1);
  return new THREE.Quaternion().setFromRotationMatrix(m);
}

/** The parameters after `?` and after `#`, the latter winning. */
function readParams() {
  const merged = new URLSearchParams(location.search.slice(1));
  for (const [k, v] of new URLSearchParams(location.hash.slice(1))) merged.set(k, v);
  return merged;
}

/** Numbers in a comma list, or null when absent or malformed. */
function numbers(name, count) {
  if (!params.has(name)) return null;
  const v = params.get(name).split(',').map(Number);
  return v.length === count && v.every(Number.isFinite) ? v : null;
}

/** Where `t` falls among the rows: the row before it and the fraction toward the next. */
function rowAt(t) {
  const ts = data.t;
  if (t <= ts[0] || ts.length === 1) return { i: 0, f: 0 };
  if (t >= ts[ts.length - 1]) return { i: ts.length - 1, f: 0 };
  let lo = 0;
  let hi = ts.length - 1;
  while (hi - lo > 1) {
    const mid = (lo + hi) >> 1;
    if (ts[mid] <= t) lo = mid;
    else hi = mid;
  }
  return { i: lo, f: (t - ts[lo]) / (ts[hi] - ts[lo]) };
}

/** A column's value at a row position, interpolated linearly. */
function valueAt(name, at) {
  const c = data.columns[name];
  const a = c[at.i] ?? 0;
  return at.f === 0 ? a : a + ((c[at.i + 1] ?? a) - a) * at.f;
}

/** A body's orientation (body to space) at row `i`. */
function quaternionAtRow(orientation, i) {
  const q = new THREE.Quaternion();
  if (orientation.quaternion) {
    const [e0, e1, e2, e3] = orientation.quaternion.map((n) => data.columns[n][i] ?? 0);
    q.set(e1, e2, e3, e0);
  } else if (orientation.dcm) {
    const c = orientation.dcm.map((n) => data.columns[n][i] ?? 0);
    const m = new THREE.Matrix4().set(c[0], c[1], c[2], 0, c[3], c[4], c[5], 0, c[6], c[7], c[8], 0, 0, 0, 0, 1);
    q.setFromRotationMatrix(m);
  }
  return SPACE.clone().multiply(q.lengthSq() > 0 ? q.normalize() : q.identity());
}

/** A body's orientation at a row position: the rows' orientations slerped. */
function quaternionAt(orientation, at) {
  const q = quaternionAtRow(orientation, at.i);
  if (at.f > 0) q.slerp(quaternionAtRow(orientation, at.i + 1), at.f);
  return q;
}

/** The point whose space coordinates are the columns `names`, drawn, at a row position. */
function placeAt(names, at) {
  return new THREE.Vector3(...names.map((n) => valueAt(n, at))).applyQuaternion(SPACE);
}

/** A body's origin, drawn, at a row position: its position columns', else the origin. */
function bodyOrigin(body, at) {
  return body.position ? placeAt(body.position, at) : new THREE.Vector3();
}

/** An arrow's vector (space axes, scaled) at a row position. */
function arrowAt(arrow, at) {
  const v = new THREE.Vector3(...arrow.columns.map((n) => valueAt(n, at)));
  return v.applyQuaternion(SPACE).multiplyScalar(arrow.scale);
}

/** The geometry of a shape, in body axes about its centre; cylinders and rods along z. */
function shapeGeometry(shape) {
  switch (shape.kind) {
    case 'ellipsoid':
      return new THREE.SphereGeometry(1, 48, 24).scale(shape.a, shape.b, shape.c);
    case 'cylinder':
      return new THREE.CylinderGeometry(shape.radius, shape.radius, shape.length, 48).rotateX(Math.PI / 2);
    case 'box':
      return new THREE.BoxGeometry(shape.x, shape.y, shape.z);
    case 'ring':
      return new THREE.TorusGeometry(shape.radius, shape.tube, 16, 96);
    default: {
      const r = shape.length * 0.015;
      return new THREE.CylinderGeometry(r, r, shape.length, 12).rotateX(Math.PI / 2);
    }
  }
}

/** The farthest a shape reaches from its centre. */
function shapeReach(shape) {
  switch (shape.kind) {
    case 'ellipsoid':
      return Math.max(shape.a, shape.b, shape.c);
    case 'cylinder':
      return Math.hypot(shape.radius, shape.length / 2);
    case 'box':
      return Math.hypot(shape.x, shape.y, shape.z) / 2;
    case 'ring':
      return shape.radius + shape.tube;
    case 'axes':
      return shape.length ?? 0;
    default:
      return shape.length / 2;
  }
}

/** A small mark on a round shape's rim along body x, so that spin shows. */
function spinMark(shape, colour, opacity) {
  let rim = 0;
  let size = 0;
  if (shape.kind === 'ellipsoid') [rim, size] = [shape.a, Math.min(0.1 * shape.a, 0.6 * shape.c)];
  if (shape.kind === 'cylinder') [rim, size] = [shape.radius, Math.min(0.1 * shape.radius, 0.3 * shape.length)];
  if (rim === 0) return null;
  const mark = new THREE.Mesh(
    new THREE.SphereGeometry(size, 16, 8),
    new THREE.MeshStandardMaterial({
      color: new THREE.Color(colour).multiplyScalar(0.35),
      roughness: 0.5,
      transparent: opacity < 1,
      opacity,
    }),
  );
  mark.position.set(rim, 0, 0);
  return mark;
}

/** Every row's index, or about 2000 of them spread evenly for long runs. */
function sampleRows() {
  const step = Math.max(1, Math.floor(data.t.length / 2000));
  const rows = [];
  for (let i = 0; i < data.t.length; i += step) rows.push(i);
  if (rows[rows.length - 1] !== data.t.length - 1) rows.push(data.t.length - 1);
  return rows;
}

/** The box holding the origin, every body, trace, arrow and point over the run. */
function sceneBox() {
  const box = new THREE.Box3(new THREE.Vector3(), new THREE.Vector3());
  for (const i of sampleRows()) {
    const at = { i, f: 0 };
    for (const b of data.view.bodies) {
      const centre = new THREE.Vector3(...b.offset).applyQuaternion(quaternionAtRow(b.orientation, i));
      centre.add(bodyOrigin(b, at));
      box.expandByPoint(centre.clone().addScalar(shapeReach(b.shape)));
      box.expandByPoint(centre.addScalar(-shapeReach(b.shape)));
    }
    for (const t of data.view.traces) box.expandByPoint(tracePoint(t, i));
    for (const a of data.view.arrows) box.expandByPoint(arrowAt(a, at));
    for (const p of data.view.points ?? []) box.expandByPoint(placeAt(p.position, at));
  }
  return box;
}

/** The drawing's scale for frames' axes and points' markers: the median distance between the
 * joined points at the start, else half the scene's size (at most that). */
function drawScale() {
  const points = data.view.points ?? [];
  const at = { i: 0, f: 0 };
  const lengths = points
    .filter((p) => p.from)
    .map((p) => placeAt(p.position, at).distanceTo(placeAt(points.find((q) => q.name === p.from).position, at)))
    .filter((d) => d > size * 1e-6)
    .sort((a, b) => a - b);
  return lengths.length ? Math.min(lengths[lengths.length >> 1], size / 2) : size / 2;
}

/** A trace's point in space axes at row `i`. */
function tracePoint(trace, i) {
  const body = data.view.bodies.find((b) => b.name === trace.body);
  const point = new THREE.Vector3(...trace.point).applyQuaternion(quaternionAtRow(body.orientation, i));
  return point.add(bodyOrigin(body, { i, f: 0 }));
}

/** A text label that always faces the camera, `height` tall. */
function label(text, colour, height) {
  const canvas = document.createElement('canvas');
  const ctx = canvas.getContext('2d');
  ctx.font = 'bold 48px sans-serif';
  canvas.width = Math.ceil(ctx.measureText(text).width) + 16;
  canvas.height = 64;
  ctx.font = 'bold 48px sans-serif';
  ctx.fillStyle = colour;
  ctx.textBaseline = 'middle';
  ctx.fillText(text, 8, 34);
  const texture = new THREE.CanvasTexture(canvas);
  texture.colorSpace = THREE.SRGBColorSpace;
  const sprite = new THREE.Sprite(new THREE.SpriteMaterial({ map: texture, depthTest: false }));
  sprite.scale.set((height * canvas.width) / canvas.height, height, 1);
  sprite.renderOrder = 1;
  return sprite;
}

/** The fixed furniture: lights, support, ground grid, labelled axes. */
function addFurniture(scene, box, size) {
  scene.add(new THREE.HemisphereLight(0xffffff, 0x888888, 1.6));
  const sun = new THREE.DirectionalLight(0xffffff, 1.8);
  sun.position.set(2, 1, 4).multiplyScalar(size);
  scene.add(sun);
  const support = new THREE.Mesh(
    new THREE.SphereGeometry(size * 0.03, 24, 12),
    new THREE.MeshStandardMaterial({ color: 0x444444 }),
  );
  scene.add(support);
  const grid = new THREE.GridHelper(size * 4, 16, 0x999999, 0xcccccc);
  grid.rotateX(Math.PI / 2);
  grid.position.z = Math.min(0, box.min.z) - size * 0.01;
  scene.add(grid);
  const n = data.view.frame ?? 'N';
  const axes = [
    [n + '1', 0xb04040, new THREE.Vector3(1, 0, 0)],
    [n + '2', 0x40a040, new THREE.Vector3(0, 1, 0)],
    [n + '3', 0x4040b0, new THREE.Vector3(0, 0, 1)],
  ];
  for (const [name, colour, dir] of axes) {
    const end = dir.clone().applyQuaternion(SPACE).multiplyScalar(size * 0.6);
    const line = new THREE.Line(
      new THREE.BufferGeometry().setFromPoints([new THREE.Vector3(), end]),
      new THREE.LineBasicMaterial({ color: colour }),
    );
    scene.add(line);
    const tag = label(name, '#' + new THREE.Color(colour).getHexString(), size * 0.07);
    tag.position.copy(end.multiplyScalar(1.08));
    scene.add(tag);
  }
}

/** A frame's axes (x red, y green, z blue) with its name, `length` long. */
function axesMesh(name, colour, length, labelled, opacity) {
  const axes = new THREE.AxesHelper(length).setColors(0xb04040, 0x40a040, 0x4040b0);
  axes.material.transparent = opacity < 1;
  axes.material.opacity = opacity;
  if (labelled) {
    // Past the tip of its x axis, apart from the label of a point at its origin.
    const tag = label(name, colour, 0.3 * length);
    tag.position.set(1.2 * length, 0, 0);
    axes.add(tag);
  }
  return axes;
}

/** The bodies: a group per body turning about its origin (the origin unless its position
 * columns move it), its shape at the offset. */
function addBodies(scene) {
  const framed = data.view.bodies.filter((b) => b.shape.kind === 'axes').length;
  return data.view.bodies.map((b) => {
    const group = new THREE.Group();
    if (b.shape.kind === 'axes') {
      const axes = axesMesh(b.name, b.colour, b.shape.length ?? 0.6 * scale, framed <= MAX_LABELS, b.opacity);
      axes.position.set(...b.offset);
      axes.quaternion.copy(axisTurn(b.axis));
      group.add(axes);
      scene.add(group);
      return { spec: b, group };
    }
    const mesh = new THREE.Mesh(
      shapeGeometry(b.shape),
      new THREE.MeshStandardMaterial({
        color: b.colour,
        roughness: 0.55,
        metalness: 0.05,
        transparent: b.opacity < 1,
        opacity: b.opacity,
        depthWrite: b.opacity >= 1,
      }),
    );
    const mark = spinMark(b.shape, b.colour, b.opacity);
    if (mark) mesh.add(mark);
    mesh.position.set(...b.offset);
    mesh.quaternion.copy(shapeTurn(b));
    group.add(mesh);
    scene.add(group);
    return { spec: b, group };
  });
}

/** The arrows, each with its tip label (its tag: the label, unless that reads as the space axes)
 * and a checkbox showing or hiding both. */
function addArrows(scene, size) {
  const shown = params.has('arrows') ? new Set(params.get('arrows').split(',').filter((s) => s)) : null;
  const panel = document.getElementById('arrows');
  return data.view.arrows.map((a) => {
    const tag = label(a.tag ?? a.label, a.colour, size * 0.07);
    const helper = new THREE.ArrowHelper(new THREE.Vector3(0, 0, 1), new THREE.Vector3(), 1, a.colour);
    // Drawn after the bodies and over them: a rotor around the origin never hides L or omega.
    for (const part of [helper.line, helper.cone]) {
      part.material.depthTest = false;
      part.material.transparent = true;
      part.renderOrder = 2;
    }
    const arrow = { spec: a, helper, tag, on: shown === null || shown.has(a.label) || shown.has(a.tag) };
    scene.add(helper, tag);
    const row = document.createElement('label');
    const box = document.createElement('input');
    box.type = 'checkbox';
    box.checked = arrow.on;
    box.addEventListener('change', () => {
      arrow.on = box.checked;
      update();
    });
    const swatch = document.createElement('span');
    swatch.className = 'swatch';
    swatch.style.background = a.colour;
    row.append(box, swatch, a.tag ?? a.label);
    panel.append(row);
    return arrow;
  });
}

/** The points: a marker each (named when few) and a line to the point it hangs from. */
function addPoints(scene) {
  const points = data.view.points ?? [];
  return points.map((p) => {
    const marker = new THREE.Mesh(
      new THREE.SphereGeometry(0.06 * scale, 16, 8),
      new THREE.MeshStandardMaterial({ color: p.colour, roughness: 0.5 }),
    );
    if (points.length <= MAX_LABELS) {
      const tag = label(p.name, p.colour, 0.18 * scale);
      tag.position.set(0.12 * scale, 0, 0.12 * scale);
      marker.add(tag);
    }
    scene.add(marker);
    let line = null;
    if (p.from) {
      line = new THREE.Line(
        new THREE.BufferGeometry().setFromPoints([new THREE.Vector3(), new THREE.Vector3()]),
        new THREE.LineBasicMaterial({ color: p.colour }),
      );
      line.frustumCulled = false;
      scene.add(line);
    }
    return { spec: p, from: points.find((q) => q.name === p.from), marker, line };
  });
}

/** Every point's marker and line at a row position. */
function placePoints(at) {
  for (const p of points) {
    p.marker.position.copy(placeAt(p.spec.position, at));
    if (!p.line) continue;
    const ends = p.line.geometry.attributes.position;
    const from = placeAt(p.from.position, at);
    ends.setXYZ(0, from.x, from.y, from.z);
    ends.setXYZ(1, p.marker.position.x, p.marker.position.y, p.marker.position.z);
    ends.needsUpdate = true;
  }
}

/** The traces: each point's whole path, drawn up to the current row. */
function addTraces(scene) {
  return data.view.traces.map((t) => {
    const points = data.t.map((_, i) => tracePoint(t, i));
    const line = new THREE.Line(
      new THREE.BufferGeometry().setFromPoints(points),
      new THREE.LineBasicMaterial({ color: t.colour }),
    );
    line.frustumCulled = false;
    scene.add(line);
    return line;
  });
}

/** Sets every moving thing to time `state.t` and renders. */
function update() {
  const at = rowAt(state.t);
  for (const b of bodies) {
    b.group.quaternion.copy(quaternionAt(b.spec.orientation, at));
    b.group.position.copy(bodyOrigin(b.spec, at));
  }
  placePoints(at);
  for (const a of arrows) {
    const v = arrowAt(a.spec, at);
    const length = v.length();
    const visible = a.on && length > size * 1e-6;
    a.helper.visible = visible;
    a.tag.visible = visible;
    if (!visible) continue;
    const head = Math.min(0.25 * length, 0.12 * size);
    a.helper.setDirection(v.clone().divideScalar(length));
    a.helper.setLength(length, head, 0.5 * head);
    a.tag.position.copy(v.multiplyScalar(1 + (0.06 * size) / length));
  }
  for (const line of traces) line.geometry.setDrawRange(0, at.i + 1);
  slider.value = String(state.t);
  timeText.textContent = 't = ' + state.t.toFixed(3) + ' / ' + data.t[data.t.length - 1].toFixed(3);
  playButton.textContent = state.playing ? 'Pause' : 'Play';
  placeCamera();
  renderer.render(scene, camera);
}

/** The camera on its sphere about the target, z up. */
function placeCamera() {
  const az = THREE.MathUtils.degToRad(orbit.azimuth);
  const el = THREE.MathUtils.degToRad(orbit.elevation);
  const dir = new THREE.Vector3(Math.cos(el) * Math.cos(az), Math.cos(el) * Math.sin(az), Math.sin(el));
  camera.position.copy(orbit.target).addScaledVector(dir, orbit.distance);
  camera.lookAt(orbit.target);
}

/** Mouse: drag turns the camera about the target, the wheel zooms, a double click resets. */
function addMouse(canvas, home) {
  let drag = null;
  canvas.addEventListener('pointerdown', (e) => {
    drag = { x: e.clientX, y: e.clientY };
    canvas.setPointerCapture(e.pointerId);
  });
  canvas.addEventListener('pointerup', () => (drag = null));
  canvas.addEventListener('pointermove', (e) => {
    if (!drag) return;
    orbit.azimuth -= (e.clientX - drag.x) * 0.4;
    orbit.elevation = Math.max(-89, Math.min(89, orbit.elevation + (e.clientY - drag.y) * 0.4));
    drag = { x: e.clientX, y: e.clientY };
    update();
  });
  canvas.addEventListener('wheel', (e) => {
    e.preventDefault();
    orbit.distance *= Math.exp(e.deltaY * 0.001);
    update();
  });
  canvas.addEventListener('dblclick', () => {
    Object.assign(orbit, home());
    update();
  });
}

/** Play, pause, the slider and the speed. */
function addControls() {
  slider.min = String(data.t[0]);
  slider.max = String(data.t[data.t.length - 1]);
  slider.addEventListener('input', () => {
    state.t = Number(slider.value);
    update();
  });
  playButton.addEventListener('click', () => {
    state.playing = !state.playing;
    if (state.playing && state.t >= data.t[data.t.length - 1]) state.t = data.t[0];
    update();
  });
  speedSelect.addEventListener('change', () => (state.speed = Number(speedSelect.value)));
  const speed = params.get('speed');
  if (speed && [...speedSelect.options].some((o) => o.value === speed)) speedSelect.value = speed;
  state.speed = Number(speedSelect.value);
}

/** Advances the time while playing, looping at the end. */
function tick(now) {
  if (state.playing && state.last !== null) {
    state.t += ((now - state.last) / 1000) * state.speed;
    if (state.t > data.t[data.t.length - 1]) state.t = data.t[0];
    update();
  }
  state.last = now;
  requestAnimationFrame(tick);
}

let scene, camera, renderer, bodies, arrows, traces, points, size, scale, orbit, state, SPACE, furniture, framed;
/** A run whose drawing reaches past this many times the framed size is framed again... */
const GROWN = 1.1;
/** ... and so is one shrunk below this fraction of it. */
const SHRUNK = 1 / 3;
/** Frames or points beyond this many are drawn without their names. */
const MAX_LABELS = 24;
const slider = document.getElementById('slider');
const timeText = document.getElementById('time');
const playButton = document.getElementById('play');
const speedSelect = document.getElementById('speed');

/** Builds the scene from the data and the URL parameters, then starts the clock. */
function main() {
  SPACE = spaceTurn(data.view.up ?? 3);
  const box = sceneBox();
  // A drawing of points all at the origin has no size of its own: unit size.
  size = box.getSize(new THREE.Vector3()).length() / 2 || 1;
  scale = drawScale();
  scene = new THREE.Scene();
  scene.background = new THREE.Color(0xf2f2ee);
  furniture = new THREE.Group();
  addFurniture(furniture, box, size);
  scene.add(furniture);
  framed = { size, centre: box.getCenter(new THREE.Vector3()), refits: 0 };
  bodies = addBodies(scene);
  points = addPoints(scene);
  arrows = addArrows(scene, size);
  traces = addTraces(scene);
  const home = () => ({
    azimuth: DEFAULT_AZIMUTH,
    elevation: DEFAULT_ELEVATION,
    distance: (0.9 * framed.size) / Math.sin(THREE.MathUtils.degToRad(FOV / 2)),
    target: framed.centre.clone(),
  });
  orbit = home();
  const cam = numbers('cam', 3);
  if (cam) [orbit.azimuth, orbit.elevation, orbit.distance] = cam;
  const target = numbers('target', 3);
  if (target) orbit.target.set(...target);
  camera = new THREE.PerspectiveCamera(FOV, innerWidth / innerHeight, size * 0.01, size * 100);
  camera.up.set(0, 0, 1);
  renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(devicePixelRatio);
  renderer.setSize(innerWidth, innerHeight);
  document.getElementById('scene').append(renderer.domElement);
  addMouse(renderer.domElement, home);
  addEventListener('resize', () => {
    camera.aspect = innerWidth / innerHeight;
    camera.updateProjectionMatrix();
    renderer.setSize(innerWidth, innerHeight);
    update();
  });
  const t = Number(params.get('t'));
  const fixed = params.has('t') && Number.isFinite(t);
  if (params.get('ui') === '0') {
    for (const id of ['title', 'arrows', 'controls']) document.getElementById(id).style.display = 'none';
  }
  const playing = params.has('play') ? params.get('play') !== '0' : !fixed;
  state = { t: fixed ? t : data.t[0], playing, speed: 1, last: null };
  addControls();
  update();
  requestAnimationFrame(tick);
}

/** Draws another run of the same view (new `t` and columns, bodies resized or moved with the
 * parameters, the title), keeping the time and the camera's turn; the framing follows a
 * drawing grown out of it or shrunk well inside it. */
function load(next) {
  const reshaped = JSON.stringify(next.view.bodies) !== JSON.stringify(data.view.bodies);
  const repointed = JSON.stringify(next.view.points) !== JSON.stringify(data.view.points);
  data = next;
  const refitted = refit();
  if (reshaped || refitted) {
    for (const b of bodies) {
      scene.remove(b.group);
      b.group.traverse((o) => o.geometry?.dispose());
    }
    bodies = addBodies(scene);
  }
  if (repointed || refitted) {
    for (const p of points) {
      for (const o of [p.marker, p.line]) {
        if (!o) continue;
        scene.remove(o);
        o.traverse((part) => {
          part.geometry?.dispose();
          part.material?.map?.dispose();
          part.material?.dispose();
        });
      }
    }
    points = addPoints(scene);
  }
  for (const line of traces) {
    scene.remove(line);
    line.geometry.dispose();
  }
  traces = addTraces(scene);
  slider.min = String(data.t[0]);
  slider.max = String(data.t[data.t.length - 1]);
  state.t = Math.min(Math.max(state.t, data.t[0]), data.t[data.t.length - 1]);
  document.title = data.title;
  document.getElementById('title').textContent = data.title;
  update();
}

/** Frames the run's drawing again when it reaches past [GROWN] times the framed size or has
 * shrunk below [SHRUNK] of it: the camera keeps its turn and its zoom relative to the drawing,
 * the furniture, markers and labels are resized with it. Whether it did. */
function refit() {
  const box = sceneBox();
  const next = box.getSize(new THREE.Vector3()).length() / 2 || 1;
  const centre = box.getCenter(new THREE.Vector3());
  if (centre.distanceTo(framed.centre) + next <= GROWN * framed.size && next >= SHRUNK * framed.size) return false;
  const ratio = next / framed.size;
  orbit.target = orbit.target.clone().sub(framed.centre).multiplyScalar(ratio).add(centre);
  orbit.distance *= ratio;
  framed = { size: next, centre, refits: framed.refits + 1 };
  size = next;
  scale = drawScale();
  camera.near = size * 0.01;
  camera.far = size * 100;
  camera.updateProjectionMatrix();
  scene.remove(furniture);
  furniture.traverse((o) => {
    o.geometry?.dispose();
    o.material?.map?.dispose();
    o.material?.dispose();
  });
  furniture = new THREE.Group();
  addFurniture(furniture, box, size);
  scene.add(furniture);
  for (const a of arrows) a.tag.scale.multiplyScalar(ratio);
  return true;
}

/** What other scripts may use: load a run, read values, the time, the arrows shown and the framing. */
function expose() {
  window.gyroView = {
    load,
    data: () => data,
    valueAt: (name, t) => valueAt(name, rowAt(t)),
    time: () => state.t,
    seek(t) {
      state.t = t;
      update();
    },
    pause() {
      state.playing = false;
      update();
    },
    arrowsShown: () => Object.fromEntries(arrows.map((a) => [a.spec.label, a.helper.visible])),
    /** The arrows' tags as drawn, by label. */
    arrowTags: () => Object.fromEntries(arrows.map((a) => [a.spec.label, a.spec.tag ?? a.spec.label])),
    /** The camera's framing: the size and centre framed, how often it was framed again, the
     * camera's turn (degrees), distance and target. */
    framing: () => ({
      size: framed.size,
      centre: framed.centre.toArray(),
      refits: framed.refits,
      azimuth: orbit.azimuth,
      elevation: orbit.elevation,
      distance: orbit.distance,
      target: orbit.target.toArray(),
    }),
    /** Where a drawn point (z up) falls on the screen, -1 to 1 across and up when in view. */
    onScreen: (xyz) => new THREE.Vector3(...xyz).project(camera).toArray().slice(0, 2),
    /** Each body's drawn centre in its own axes and its drawn size (the box of its shape). */
    bodiesDrawn: () =>
      Object.fromEntries(
        bodies.map((b) => {
          const mesh = b.group.children[0];
          mesh.geometry.computeBoundingBox();
          const size = mesh.geometry.boundingBox.getSize(new THREE.Vector3());
          const origin = b.group.position.clone().applyQuaternion(SPACE.clone().invert());
          return [b.spec.name, { centre: mesh.position.toArray(), size: size.toArray(), origin: origin.toArray() }];
        }),
      ),
    /** Each point's place in space axes and as drawn (z up), and the point its line comes from. */
    pointsDrawn: () =>
      Object.fromEntries(
        points.map((p) => {
          const at = p.marker.position.clone().applyQuaternion(SPACE.clone().invert());
          const drawn = p.marker.position.toArray();
          return [p.spec.name, { at: at.toArray(), drawn, from: p.spec.from ?? null, line: p.line !== null }];
        }),
      ),
  };
  dispatchEvent(new Event('gyroviewready'));
}

let THREE;
try {
  const source = document.getElementById('three-js').textContent;
  THREE = await import(URL.createObjectURL(new Blob([source], { type: 'text/javascript' })));
  main();
  expose();
} catch (e) {
  const box = document.getElementById('error');
  box.textContent = 'The view could not start: ' + e;
  box.style.display = 'block';
  throw e;
}
