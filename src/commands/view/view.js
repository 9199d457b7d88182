// glint view: the page. It polls the server for frames (linear radiance in RGBE),
// maps them to the display here (exposure, then the sRGB curve, as glint's PNG writer
// does), and sends the controls' settings back as a URL query. No library, no network.
'use strict';

const $ = (id) => document.getElementById(id);
const form = $('settings');
const view = {
  settings: null,       // the server's /api/settings answer
  generation: 0,
  frameId: 0,
  frame: null,          // the last /api/state frame record
  pixels: null,         // Float32Array of the shown frame
  reference: null,      // Float32Array of --reference, when there is one
  width: 0,
  height: 0,
  exposure: 1,
  show: 'render',
  busy: false,
  drawn: [],            // times of the last frames drawn, for frames per second
  tunableStructure: '', // the pointers the sliders were built for
};

// ---- display mapping ------------------------------------------------------------

// Ward's RGBE (the server's frames: a mantissa byte per channel, a shared exponent byte)
// into linear float RGB.
function decodeRgbe(buffer) {
  const b = new Uint8Array(buffer);
  const out = new Float32Array((b.length / 4) * 3);
  const scale = new Float32Array(256);
  for (let e = 1; e < 256; ++e) scale[e] = Math.pow(2, e - 136);
  for (let i = 0, o = 0; i < b.length; i += 4, o += 3) {
    const e = b[i + 3];
    if (e === 0) continue;  // black
    const f = scale[e];
    out[o] = (b[i] + 0.5) * f;
    out[o + 1] = (b[i + 1] + 0.5) * f;
    out[o + 2] = (b[i + 2] + 0.5) * f;
  }
  return out;
}

function srgb(v) {  // IEC 61966-2-1, for v in [0, 1]
  return v <= 0.0031308 ? 12.92 * v : 1.055 * Math.pow(v, 1 / 2.4) - 0.055;
}

// The relative error of one pixel, as glint converge measures it (mean over channels).
function relativeError(a, r, i) {
  let e = 0;
  for (let k = 0; k < 3; ++k) {
    const d = a[i + k] - r[i + k];
    e += (d * d) / (r[i + k] * r[i + k] + 0.01);
  }
  return e / 3;
}

// False colour for log10 of the relative error in [-4, 0]: dark blue, cyan, yellow, red.
const kStops = [[0, 0, 40], [0, 120, 200], [90, 210, 160], [250, 220, 40], [220, 30, 20]];
function falseColour(e) {
  const t = Math.min(Math.max((Math.log10(Math.max(e, 1e-12)) + 4) / 4, 0), 1) * (kStops.length - 1);
  const i = Math.min(Math.floor(t), kStops.length - 2);
  const f = t - i;
  return kStops[i].map((c, k) => c + f * (kStops[i + 1][k] - c));
}

function draw() {
  const canvas = $('image');
  if (!view.pixels) return;
  if (canvas.width !== view.width || canvas.height !== view.height) {
    canvas.width = view.width;
    canvas.height = view.height;
    const scale = Math.max(1, Math.floor(512 / Math.max(view.width, view.height)));
    canvas.style.width = `${view.width * scale}px`;
  }
  const ctx = canvas.getContext('2d');
  const out = ctx.createImageData(view.width, view.height);
  const showReference = view.show === 'reference' && view.reference;
  const src = showReference ? view.reference : view.pixels;
  const n = view.width * view.height;
  if (view.show === 'error' && view.reference) {
    for (let p = 0; p < n; ++p) {
      const c = falseColour(relativeError(view.pixels, view.reference, 3 * p));
      out.data.set([c[0], c[1], c[2], 255], 4 * p);
    }
  } else {
    // The curve at 4096 steps of [0, 1], then one table look-up per channel.
    const lut = new Uint8ClampedArray(4097);
    for (let i = 0; i <= 4096; ++i) lut[i] = Math.round(255 * srgb(i / 4096));
    const scale = view.exposure * 4096;
    const data = out.data;
    for (let p = 0, q = 0; p < 3 * n; p += 3, q += 4) {
      for (let k = 0; k < 3; ++k) {
        const v = src[p + k] * scale + 0.5;
        data[q + k] = lut[v >= 4096 ? 4096 : v > 0 ? v | 0 : 0];
      }
      data[q + 3] = 255;
    }
  }
  ctx.putImageData(out, 0, 0);
}

// ---- the chart of relative MSE against time -------------------------------------

function drawChart(points) {
  const canvas = $('chart');
  const ctx = canvas.getContext('2d');
  const w = canvas.width;
  const h = canvas.height;
  const m = { l: 58, r: 12, t: 12, b: 34 };
  ctx.clearRect(0, 0, w, h);
  ctx.fillStyle = '#111';
  ctx.font = '11px system-ui, sans-serif';
  ctx.fillText('relative MSE against seconds (log-log); dashed: 1/t', m.l, h - 4);
  const good = points.filter((p) => p[0] > 0 && p[1] > 0);
  if (good.length < 1) return;
  const lx = good.map((p) => Math.log10(p[0]));
  const ly = good.map((p) => Math.log10(p[1]));
  const x0 = Math.floor(Math.min(...lx));
  const x1 = Math.max(Math.ceil(Math.max(...lx)), x0 + 1);
  const y0 = Math.floor(Math.min(...ly));
  const y1 = Math.max(Math.ceil(Math.max(...ly)), y0 + 1);
  const X = (v) => m.l + ((v - x0) / (x1 - x0)) * (w - m.l - m.r);
  const Y = (v) => h - m.b - ((v - y0) / (y1 - y0)) * (h - m.t - m.b);
  ctx.strokeStyle = '#ccc';
  ctx.beginPath();
  for (let d = x0; d <= x1; ++d) { ctx.moveTo(X(d), Y(y0)); ctx.lineTo(X(d), Y(y1)); }
  for (let d = y0; d <= y1; ++d) { ctx.moveTo(X(x0), Y(d)); ctx.lineTo(X(x1), Y(d)); }
  ctx.stroke();
  ctx.fillStyle = '#333';
  for (let d = x0; d <= x1; ++d) ctx.fillText(`1e${d}`, X(d) - 10, h - m.b + 13);
  for (let d = y0; d <= y1; ++d) ctx.fillText(`1e${d}`, 8, Y(d) + 4);
  // 1/t through the last point.
  const last = good.length - 1;
  ctx.setLineDash([4, 4]);
  ctx.strokeStyle = '#999';
  ctx.beginPath();
  ctx.moveTo(X(x0), Y(ly[last] + (lx[last] - x0)));
  ctx.lineTo(X(x1), Y(ly[last] - (x1 - lx[last])));
  ctx.save();
  ctx.rect(m.l, m.t, w - m.l - m.r, h - m.t - m.b);
  ctx.clip();
  ctx.stroke();
  ctx.restore();
  ctx.setLineDash([]);
  ctx.strokeStyle = '#2a62c9';
  ctx.lineWidth = 2;
  ctx.beginPath();
  good.forEach((p, i) => (i ? ctx.lineTo(X(lx[i]), Y(ly[i])) : ctx.moveTo(X(lx[i]), Y(ly[i]))));
  ctx.stroke();
  ctx.lineWidth = 1;
}

// ---- settings ---------------------------------------------------------------------

function message(text) {
  const box = $('message');
  box.hidden = !text;
  box.textContent = text || '';
}

// The controls' settings as a URL query (the server's names, as on the command line).
function query(sets = view.settings ? view.settings.settings.set : []) {
  const q = new URLSearchParams();
  const mode = form.elements.mode.value;
  q.append('mode', mode);
  for (const name of ['walls', 'strategy', 'branches', 'glass']) {
    if (mode === 'mc') q.append(name, form.elements[name].value);
  }
  if (mode === 'mc' && form.elements.walls.value === 'diffuse') {
    q.append('mirror-light', form.elements['mirror-light'].value);
    q.append('caustics', form.elements.caustics.value);
  }
  for (const name of ['fresnel', 'sampler', 'seed']) q.append(name, form.elements[name].value);
  if (sets.length === 0) q.append('set', '');  // none: the scene file as it is
  for (const s of sets) q.append('set', s);
  return q;
}

function pageQuery(q) {
  const page = new URLSearchParams(q);
  page.append('exposure', view.exposure.toFixed(3).replace(/\.?0+$/, ''));
  return page;
}

function updateUrl() {
  if (!view.settings) return;
  history.replaceState(null, '', `/?${pageQuery(query())}`);
  $('save-png').href = `/api/image?format=png&exposure=${view.exposure}`;
  const s = view.settings.settings;
  const parts = ['glint render', view.settings.scene, `--mode ${s.mode}`,
                 `--size ${view.settings.width}x${view.settings.height}`];
  if (s.mode === 'mc') {
    parts.push(`--walls ${s.walls}`, `--strategy ${s.strategy}`, `--branches ${s.branches}`,
               `--glass ${s.glass}`);
    if (s.walls === 'diffuse') {
      parts.push(`--mirror-light ${s['mirror-light']}`, `--caustics ${s.caustics}`);
    }
  }
  parts.push(`--fresnel ${s.fresnel}`, `--sampler ${s.sampler}`, `--seed ${s.seed}`);
  for (const set of s.set) parts.push(`--set '${set}'`);
  parts.push(`--exposure ${view.exposure.toPrecision(3)}`, '-o out.png');
  $('command').textContent = parts.join(' ');
}

// The settings' `set` list with one pointer's value replaced (the list stays as it is
// until the server accepts the new one).
function withSet(pointer, text) {
  return view.settings.settings.set.filter((s) => !s.startsWith(`${pointer}=`))
      .concat([`${pointer}=${text}`]);
}

async function send(q) {
  const res = await fetch('/api/settings', {
    method: 'POST',
    headers: { 'Content-Type': 'application/x-www-form-urlencoded' },
    body: q.toString(),
  });
  const body = await res.json();
  if (!res.ok) {
    message(body.error || `the server answered ${res.status}`);
    // The server kept the query's good settings (a bad value never drops the others).
    if (body.applied) {
      showSettings(body.applied);
      return 'partial';
    }
    return false;
  }
  message('');
  showSettings(body);
  return true;
}

// A control means something in the modes its data-modes names: 'both', 'whitted', 'mc',
// or 'mc-diffuse' (Monte Carlo with diffuse walls).
function enableForMode() {
  const mode = form.elements.mode.value;
  const current = mode === 'mc' && form.elements.walls.value === 'diffuse' ? [mode, 'mc-diffuse'] : [mode];
  for (const el of form.querySelectorAll('[data-modes]')) {
    const modes = el.dataset.modes;
    el.disabled = !(modes === 'both' || current.includes(modes));
    const row = el.closest('label, .tunable');
    if (row) row.classList.toggle('disabled', el.disabled);
  }
}

function buildTunables(tunables) {
  const box = $('tunables');
  for (const old of box.querySelectorAll('.tunable')) old.remove();
  for (const t of tunables) {
    const row = document.createElement('div');
    row.className = 'tunable';
    row.innerHTML = `<span class="label"></span><div><input type="range"><input type="number"></div>`;
    row.querySelector('.label').textContent = `${t.label}  ${t.pointer}`;
    const [range, number] = row.querySelectorAll('input');
    for (const el of [range, number]) {
      el.min = t.min;
      el.max = t.max;
      el.step = t.step;
      el.value = t.value;
      el.dataset.modes = t.modes;
      el.dataset.pointer = t.pointer;
      el.setAttribute('aria-label', t.label);
    }
    number.name = `tunable:${t.pointer}`;
    const commit = (text) => {
      const value = t.grey ? `[${text},${text},${text}]` : text;
      apply(withSet(t.pointer, value));
    };
    range.addEventListener('input', () => { number.value = range.value; });
    range.addEventListener('change', () => commit(range.value));
    number.addEventListener('change', () => { range.value = number.value; commit(number.value); });
    box.appendChild(row);
  }
}

function showSettings(body) {
  const structure = JSON.stringify(body.tunables.map((t) => t.pointer));
  const rebuild = structure !== view.tunableStructure;
  view.tunableStructure = structure;
  view.settings = body;
  view.generation = body.generation;
  const s = body.settings;
  for (const name of ['mode', 'walls', 'strategy', 'branches', 'glass', 'mirror-light',
                      'caustics', 'fresnel', 'sampler', 'seed']) {
    form.elements[name].value = s[name];
  }
  if (rebuild) buildTunables(body.tunables);
  for (const t of body.tunables) {
    for (const el of document.querySelectorAll(`[data-pointer="${t.pointer}"]`)) el.value = t.value;
  }
  $('scene').textContent = `${body.scene}, ${body.width}x${body.height}, ${body.threads} threads`;
  enableForMode();
  updateUrl();
}

let applying = Promise.resolve();
function apply(sets) {
  applying = applying.then(() => send(query(sets))).catch((e) => message(String(e)));
  return applying;
}

// ---- frames ----------------------------------------------------------------------

async function poll() {
  if (view.busy) return;
  view.busy = true;
  try {
    const state = await (await fetch('/api/state', { cache: 'no-store' })).json();
    if (state.generation !== view.generation) {
      showSettings(await (await fetch('/api/settings', { cache: 'no-store' })).json());
    }
    const f = state.frame;
    if (f && f.id !== view.frameId) {
      const res = await fetch('/api/frame', { cache: 'no-store' });
      if (res.ok) {
        const size = (res.headers.get('X-Glint-Size') || '0x0').split('x').map(Number);
        view.pixels = decodeRgbe(await res.arrayBuffer());
        [view.width, view.height] = size;
        view.frameId = Number(res.headers.get('X-Glint-Frame'));
        document.body.dataset.shownGeneration = res.headers.get('X-Glint-Generation');
        view.frame = f;
        draw();
        const now = performance.now();
        view.drawn = view.drawn.filter((t) => now - t < 2000).concat([now]);
        if (view.reference) drawChart(f.error);
      }
    }
    if (!f) $('status').textContent = 'rendering the first pass';
    else {
      const rest = state.status === 'done' ? ' (done: the --time or --max-spp limit was reached)' : '';
      const fps = view.drawn.length / 2;
      const err = f.error.length ? `, relative MSE ${f.error[f.error.length - 1][1].toExponential(2)}` : '';
      $('status').textContent = `${f.passes} passes, ${f.spp} rays/pixel, ${f.seconds.toFixed(1)} s, ` +
          `${f.mrays_per_second.toFixed(1)} Mrays/s traced, ${fps.toFixed(1)} frames/s${err}${rest}`;
    }
    document.body.dataset.frame = view.frameId;  // for the browser tests
    document.body.dataset.generation = view.generation;
  } catch (e) {
    $('status').textContent = `no answer from glint view (${e.message})`;
  } finally {
    view.busy = false;
  }
}

// ---- ray trees -------------------------------------------------------------------

const kKindColour = { camera: '#dddddd', reflected: '#cfe2ff', refracted: '#d8f5d0', diffuse: '#ffe7c2' };
const fmt = (v) => v.map((x) => Number(x).toPrecision(3)).join(' ');

function treeSvg(tree) {
  const nodes = tree.nodes;
  const isChild = new Set(nodes.flatMap((n) => n.children));
  const roots = nodes.map((_, i) => i).filter((i) => !isChild.has(i));
  const bw = 170;
  const bh = 78;
  const gx = 12;
  const gy = 34;
  const pos = [];
  let slot = 0;
  const place = (i) => {  // leaves left to right, a parent above the middle of its children
    const n = nodes[i];
    if (n.children.length === 0) pos[i] = slot++;
    else {
      n.children.forEach(place);
      pos[i] = (pos[n.children[0]] + pos[n.children[n.children.length - 1]]) / 2;
    }
  };
  roots.forEach(place);
  const depth = Math.max(...nodes.map((n) => n.depth)) + 1;
  const W = Math.max(slot, 1) * (bw + gx) + 90;  // room for the last edge label
  const H = depth * (bh + gy);
  const x = (i) => pos[i] * (bw + gx) + gx / 2;
  const y = (i) => nodes[i].depth * (bh + gy) + 4;
  const esc = (s) => String(s).replace(/[&<>"]/g, (c) => `&#${c.charCodeAt(0)};`);
  let svg = `<svg xmlns="http://www.w3.org/2000/svg" width="${W}" height="${H + 8}">`;
  nodes.forEach((n, i) => {
    for (const c of n.children) {
      const x1 = x(i) + bw / 2;
      const y1 = y(i) + bh;
      const x2 = x(c) + bw / 2;
      const y2 = y(c);
      svg += `<line x1="${x1}" y1="${y1}" x2="${x2}" y2="${y2}" stroke="#888"/>`;
      svg += `<text x="${(x1 + x2) / 2 + 3}" y="${(y1 + y2) / 2 + 3}">W ${esc(fmt(nodes[c].weight))}</text>`;
    }
  });
  nodes.forEach((n, i) => {
    const lines = [
      `${n.kind} ray, depth ${n.depth}${n.inside ? ', inside' : ''}${n.final ? ', final' : ''}`,
      `hits ${n.hit}`,
      `W ${fmt(n.weight)}`,
      `importance ${fmt(n.importance)}`,
      `colour ${fmt(n.colour)}`,
    ];
    svg += `<g class="ray-node" data-kind="${esc(n.kind)}"><rect x="${x(i)}" y="${y(i)}" width="${bw}" height="${bh}" rx="6" ` +
        `fill="${kKindColour[n.kind] || '#fff'}" stroke="#666"/>`;
    lines.forEach((t, k) => {
      svg += `<text x="${x(i) + 6}" y="${y(i) + 15 + 14 * k}">${esc(t)}</text>`;
    });
    svg += '</g>';
  });
  return `${svg}</svg>`;
}

async function inspect(event) {
  const canvas = $('image');
  const rect = canvas.getBoundingClientRect();
  const px = Math.floor(((event.clientX - rect.left) / rect.width) * view.width);
  const py = Math.floor(((event.clientY - rect.top) / rect.height) * view.height);
  if (!(px >= 0 && py >= 0 && px < view.width && py < view.height)) return;
  const res = await fetch(`/api/tree?x=${px}&y=${py}`);
  const tree = await res.json();
  if (!res.ok) return message(tree.error);
  const shown = tree.nodes.length < tree.total ? ` (the first ${tree.nodes.length} of ${tree.total} nodes)` : '';
  $('tree-title').textContent =
      `pixel (${px}, ${py}): radiance ${fmt(tree.radiance)}, ${tree.total} ray nodes${shown}; ` +
      'C_R = L_local + sum W_i C_i';
  $('tree-view').innerHTML = treeSvg(tree);
}

// ---- start -----------------------------------------------------------------------

function setExposure(value) {
  view.exposure = value;
  $('exposure').value = Math.log2(value).toFixed(1);
  $('exposure-value').textContent = value.toPrecision(3);
  updateUrl();
  draw();
}

async function start() {
  const url = new URLSearchParams(location.search);
  const first = await (await fetch('/api/settings', { cache: 'no-store' })).json();
  view.settings = first;
  const exposure = Number(url.get('exposure'));
  view.exposure = exposure > 0 ? exposure : first.exposure;
  url.delete('exposure');
  if ([...url.keys()].length > 0) {
    if (!(await send(url))) showSettings(first);  // opened in the URL's state, or told why not
  } else {
    showSettings(first);
  }
  setExposure(view.exposure);
  if (first.reference) {
    $('compare').hidden = false;
    $('chart').hidden = false;
    view.reference = decodeRgbe(await (await fetch('/api/reference')).arrayBuffer());
    $('error-scale').textContent = 'false colour: relative error 1e-4 (blue) to 1 (red)';
  }
  for (const el of form.querySelectorAll('select, input[name]')) {
    if (!el.name.startsWith('tunable:')) {
      el.addEventListener('change', () => { enableForMode(); apply(); });
    }
  }
  form.addEventListener('submit', (e) => e.preventDefault());
  $('exposure').addEventListener('input', (e) => setExposure(Math.pow(2, Number(e.target.value))));
  for (const radio of document.querySelectorAll('input[name=show]')) {
    radio.addEventListener('change', () => { view.show = radio.value; draw(); });
  }
  const flip = () => {
    view.show = view.show === 'reference' ? 'render' : 'reference';
    document.querySelector(`input[name=show][value=${view.show}]`).checked = true;
    draw();
  };
  $('flip').addEventListener('click', flip);
  document.addEventListener('keydown', (e) => {
    if ((e.key === 'f' || e.key === 'F') && view.reference && e.target.tagName !== 'INPUT') flip();
  });
  $('image').addEventListener('click', inspect);
  setInterval(poll, 200);  // up to 5 frames a second: passes last about 0.25 s
  poll();
}

start().catch((e) => message(`glint view: ${e.message}`));
