// gyro-sim serve's panels: in come the scene's controls (inline JSON) and the view page's
// `window.gyroView`; out go sliders and number boxes whose changes re-run the scene on the
// server (POST /api/run, the latest change only while one is running), the run redrawn, the
// second window (uPlot: a y axis per group of series of like size and unit), a save button
// (POST /api/scene) and errors shown as the server gives them. `window.gyroState` exposes the
// values, the run drawn, the plot and the latency of each redraw.

const serve = JSON.parse(document.getElementById('serve-data').textContent);
const errorLine = document.getElementById('serve-error');
const statusLine = document.getElementById('serve-status');
const values = Object.fromEntries(serve.controls.map((c) => [c.name, c.value]));
const inputs = {};
let plot = null;
let drawnGroups = ''; // the groups of series it draws on y axes of their own, as JSON
let running = false;
let queued = null; // the change waiting for the run in progress: { values, since }

window.gyroState = {
  values,
  redraws: 0,
  answers: 0, // runs answered: drawn, or refused with the error shown
  latencies: [],
  error: '',
  data: () => window.gyroView?.data(),
  valueAt: (name, t) => window.gyroView?.valueAt(name, t),
  set: (name, value) => change(name, value),
  plot: () => plot, // the second window's uPlot
};

/** A column's model value as plotted: angles in degrees, other columns in their declared unit. */
function shown(name, v, scales) {
  return v * (scales[name] ?? 1);
}

/** The plotted columns in groups, each on a y axis of its own (the server parts series whose
 * largest magnitudes differ more than tenfold, or whose units differ; one group without its
 * word). */
function plotGroups(data) {
  return data.plot_groups ?? [data.plot];
}

/** The plot's series: t, then each plotted column, group by group (angles in degrees, the rest in their declared units). */
function plotData(data) {
  const names = plotGroups(data).flat();
  return [data.t, ...names.map((n) => data.columns[n].map((v) => shown(n, v, data.scales)))];
}

/** A y axis's width in CSS pixels (its name aside): its ticks, gap and widest tick label, so
 * that no tick label is cut. */
function axisSize(u, values, index, cycle) {
  const axis = u.axes[index];
  if (cycle > 1) return axis._size; // settled: uPlot sizes axes again until they stop changing
  u.ctx.font = axis.font[0];
  const widest = Math.max(0, ...(values ?? []).map((v) => u.ctx.measureText(String(v)).width / devicePixelRatio));
  return Math.ceil(axis.ticks.size + axis.gap + widest + 4);
}

/** The options of the second window for these groups: a y axis each (left, right, then
 * outside those), named and coloured after its series when there are several. */
function plotOptions(data, groups) {
  const colours = ['#1f77b4', '#d62728', '#2ca02c'];
  const colour = (n) => colours[data.plot.indexOf(n) % colours.length];
  const degrees = (n) => ['DEG', 'RAD'].includes((data.units[n] ?? '').toUpperCase());
  const series = [{ label: 't' }];
  const axes = [{ label: 't (s)' }];
  groups.forEach((names, k) => {
    const scale = k === 0 ? 'y' : 'y' + k;
    for (const n of names) series.push({ label: degrees(n) ? n + ' (deg)' : n, stroke: colour(n), width: 1.5, scale });
    const axis = { scale, side: k % 2 === 0 ? 3 : 1, grid: { show: k === 0 }, size: axisSize };
    if (groups.length > 1) axis.label = names.join(', ') + (degrees(names[0]) ? ' (deg)' : '');
    if (groups.length > 1 && names.length === 1) axis.stroke = colour(names[0]);
    axes.push(axis);
  });
  const width = 420 + 70 * (groups.length - 1);
  return { width, height: 220, scales: { x: { time: false } }, axes, series };
}

/** Draws the second window for `data`, building it again when its groups change. */
function drawPlot(data) {
  const groups = JSON.stringify(plotGroups(data));
  if (plot && groups === drawnGroups) {
    plot.setData(plotData(data));
    return;
  }
  plot?.destroy();
  drawnGroups = groups;
  plot = new uPlot(plotOptions(data, plotGroups(data)), plotData(data), document.getElementById('plot-area'));
  // The EJS window's title for a top; what is plotted for any other model.
  const elevation = data.plot.some((n) => n === 'ELEVATION' || n === 'L_ELEVATION');
  document.querySelector('#plot .title').textContent = elevation
    ? 'Elevation against time'
    : data.plot.join(', ') + ' against time';
}

/** A slider, a number box and the unit for one control. */
function addControl(c) {
  const row = document.createElement('div');
  row.className = 'control';
  const name = document.createElement('label');
  name.textContent = c.name;
  const slider = document.createElement('input');
  Object.assign(slider, { type: 'range', min: c.min, max: c.max, step: c.step, value: c.value });
  slider.id = 'control-' + c.name;
  const box = document.createElement('input');
  Object.assign(box, { type: 'number', min: c.min, max: c.max, step: c.step, value: c.value });
  const unit = document.createElement('span');
  unit.className = 'unit';
  unit.textContent = c.unit ?? '';
  slider.addEventListener('input', () => change(c.name, Number(slider.value)));
  box.addEventListener('change', () => change(c.name, box.value === '' ? NaN : Number(box.value)));
  row.append(name, slider, box, unit);
  document.getElementById('serve-controls').append(row);
  inputs[c.name] = { slider, box };
}

/** A control moved: show it, and run with it (after the run in progress, if any). */
function change(name, value) {
  values[name] = value;
  const input = inputs[name];
  if (input) {
    if (Number.isFinite(value)) input.slider.value = String(value);
    input.box.value = Number.isFinite(value) ? String(value) : '';
  }
  queued = { values: { ...values }, since: performance.now() };
  if (!running) runQueued();
  return new Promise((resolve) => waiters.push(resolve));
}

const waiters = []; // resolved when no change is left to run

/** Runs the latest change, then any change made meanwhile. */
async function runQueued() {
  running = true;
  while (queued) {
    const { values: asked, since } = queued;
    queued = null;
    await runOnce(asked, since);
  }
  running = false;
  for (const resolve of waiters.splice(0)) resolve(window.gyroState);
}

/** One run on the server; its answer drawn, or its error shown. */
async function runOnce(asked, since) {
  let answer;
  try {
    const response = await fetch('/api/run', { method: 'POST', body: JSON.stringify({ values: finiteOrNull(asked) }) });
    answer = await response.json();
    if (!response.ok) throw new Error(answer.error ?? 'the server answered ' + response.status);
  } catch (e) {
    showError(String(e.message ?? e));
    window.gyroState.answers += 1;
    return;
  }
  window.gyroView.load(answer);
  drawPlot(answer);
  await new Promise((resolve) => requestAnimationFrame(resolve));
  const ms = performance.now() - since;
  const state = window.gyroState;
  state.redraws += 1;
  state.answers += 1;
  state.latencies.push(ms);
  state.error = '';
  errorLine.textContent = '';
  statusLine.textContent = `run ${answer.wall_ms.toFixed(1)} ms, drawn ${ms.toFixed(0)} ms after the change`;
}

/** The values as JSON can carry them (NaN sent as null, for the server to refuse). */
function finiteOrNull(asked) {
  return Object.fromEntries(Object.entries(asked).map(([k, v]) => [k, Number.isFinite(v) ? v : null]));
}

/** Shows the server's (or the network's) error; the run drawn stays. */
function showError(message) {
  window.gyroState.error = message;
  errorLine.textContent = message;
}

/** Downloads the scene with the current values. */
async function save() {
  try {
    const response = await fetch('/api/scene', { method: 'POST', body: JSON.stringify({ values: finiteOrNull(values) }) });
    if (!response.ok) throw new Error((await response.json()).error);
    const url = URL.createObjectURL(await response.blob());
    const a = Object.assign(document.createElement('a'), { href: url, download: serve.file });
    a.click();
    setTimeout(() => URL.revokeObjectURL(url), 1000);
  } catch (e) {
    showError(String(e.message ?? e));
  }
}

/** Builds the panels once the view has drawn. */
function start() {
  serve.controls.forEach(addControl);
  document.getElementById('save').addEventListener('click', save);
  drawPlot(window.gyroView.data());
  window.gyroState.ready = true;
}

if (window.gyroView) start();
else addEventListener('gyroviewready', start, { once: true });
