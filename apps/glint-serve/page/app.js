// The page of glint-serve: the render streamed as server-sent events, the camera moved with the
// mouse, wheel and touch, and a clicked pixel's ray tree drawn over the image and listed beside
// it. Plain JavaScript, nothing fetched from anywhere but this server.

const token = new URLSearchParams(location.search).get("token");
const $ = (id) => document.getElementById(id);
const image = $("image"), overlay = $("overlay");

let session = null;   // this page's render, named by the server
let camera = null;    // the view, as the server last described it
let size = { width: 0, height: 0 };  // of the full image
let view = "image";  // shown: the image, or an output variable's picture with its legend

function url(path, params = {}) {
  const query = new URLSearchParams(params);
  if (session) query.set("session", session);
  if (token) query.set("token", token);
  return `${path}?${query}`;
}

// A change asked for: until its answer names the view it makes, no frame is that view's last.
let waiting = 0;
async function post(path, params = {}, body = undefined) {
  ++waiting;
  markDone();
  try {
    const response = await fetch(url(path, params), { method: "POST", body });
    const answer = await response.json();
    if (!response.ok) throw new Error(answer.error);
    if (answer.version !== undefined) awaitedVersion = Math.max(awaitedVersion, answer.version);
    return answer;
  } finally {
    --waiting;
    markDone();
  }
}

// --- The render, frame by frame ---

function showError(text) {
  $("error").hidden = !text;
  $("error").textContent = text || "";
}

function seconds(s) {
  return s < 60 ? `${s.toFixed(1)} s` : `${Math.floor(s / 60)} min ${Math.round(s % 60)} s`;
}

let explainedVersion = -1;  // of the view whose ray tree is drawn
let awaitedVersion = 0;     // of the newest view asked for: older views' frames are not its

// For whoever drives the page (the browser tests): whether the image shown is the last of the
// newest view asked for.
let lastFrame = null;
function markDone() {
  const f = lastFrame;
  document.body.dataset.done = !!f && !f.preview && f.passes_done === f.passes_total &&
    f.version >= awaitedVersion && waiting === 0 && !sending;
}

// The picture of the view chosen, when the frame's render records it; else the image.
function viewOf(frame) {
  return view !== "image" && frame.views.includes(view) ? view : "image";
}

function showFrame(frame) {
  // A frame of an error alone keeps the last image; while the scene's files stay broken, the
  // frames of its last good version carry their error too.
  showError(frame.error);
  if (frame.error && frame.passes_total === 0) return;
  // A new view (the scene edited, say): the drawn tree was another view's.
  if (explainedVersion >= 0 && frame.version > explainedVersion) clearTree();
  const what = frame.preview ? "preview" :
    `${frame.samples_done} of ${frame.samples_total} samples a pixel`;
  const left = frame.preview || frame.passes_done === frame.passes_total ?
    "" : `, about ${seconds(frame.seconds_left)} left`;
  $("status").textContent = `${what}, ${seconds(frame.seconds)}${left}`;
  // An edited scene may have another size; a preview is shown at the full one.
  if (!frame.preview && (frame.width !== size.width || frame.height !== size.height))
    setSize(frame.width, frame.height);
  if (frame.image) image.src = url("/image.png", { frame: frame.sequence, view: viewOf(frame) });
  document.body.dataset.sequence = frame.sequence;
  lastFrame = frame;
  markDone();
}

// Which frame's image has loaded, for whoever drives the page: the one shown.
image.addEventListener("load", () => {
  const params = new URL(image.currentSrc).searchParams;
  document.body.dataset.shown = params.get("frame");
  document.body.dataset.shownView = params.get("view");
  // Read at once: while the next frame's image loads, the element's own size may be 0.
  document.body.dataset.shownHeight = image.naturalHeight;
});

// The image's size; an output variable's picture is as wide, with its legend below.
function setSize(width, height) {
  size = { width, height };
  image.style.width = `${width}px`;
  overlay.setAttribute("width", width);
  overlay.setAttribute("height", height);
  overlay.setAttribute("viewBox", `0 0 ${width} ${height}`);
  $("error").style.maxWidth = `${width}px`;
}

function fillSettings(settings, integrators, accels) {
  const form = $("settings");
  if (integrators) form.integrator.replaceChildren(...integrators.map((n) => new Option(n, n)));
  if (accels) form.accel.replaceChildren(...accels.map((n) => new Option(n, n)));
  form.integrator.value = settings.integrator;
  form.accel.value = settings.accel;
  form.spp.value = settings.spp;
  form.max_depth.value = settings.max_depth;
}

const events = new EventSource(url("/events"));
events.addEventListener("hello", (e) => {
  const hello = JSON.parse(e.data);
  session = hello.session;
  camera = hello.camera;
  $("scene").textContent = hello.scene;
  document.title = `${hello.scene} · glint`;
  setSize(hello.width, hello.height);
  fillSettings(hello.settings, hello.integrators, hello.accels);
  $("view-choice").append(...hello.views.map((n) => new Option(n, n)));
  $("explain-integrator").append(...hello.integrators.map((n) => new Option(n, n)));
  document.body.dataset.session = session;
  setSaveLinks();
});
events.addEventListener("frame", (e) => showFrame(JSON.parse(e.data)));
events.onerror = () => { $("status").textContent = "the server is not answering"; };

// PNG saves the view shown; EXR the image with every output variable recorded, as layers.
function setSaveLinks() {
  $("save-png").href = url("/save", { format: "png", view });
  $("save-exr").href = url("/save", { format: "exr" });
}

// A view of an output variable asks the render to record them all, once; then the page
// switches between them and the image without rendering again.
$("view-choice").addEventListener("change", async (e) => {
  view = e.target.value;
  setSaveLinks();
  try {
    if (view !== "image" && lastFrame && !lastFrame.views.includes(view))
      fillSettings((await post("/settings", { aovs: "all" })).settings);
    else if (lastFrame && lastFrame.image)
      image.src = url("/image.png", { frame: lastFrame.sequence, view: viewOf(lastFrame) });
    showError("");
  } catch (error) {
    showError(error.message);
  }
});

$("settings").addEventListener("change", async (e) => {
  try {
    const answer = await post("/settings", { [e.target.name]: e.target.value });
    fillSettings(answer.settings);
    showError("");
  } catch (error) {
    showError(error.message);
  }
});

// --- The camera ---

const sub = (a, b) => a.map((x, i) => x - b[i]);
const add = (a, b) => a.map((x, i) => x + b[i]);
const scale = (a, s) => a.map((x) => x * s);
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
  a[0] * b[1] - a[1] * b[0]];
const unit = (a) => scale(a, 1 / Math.hypot(...a));

// v turned by angle about the unit axis k (Rodrigues' formula).
function rotate(v, k, angle) {
  const c = Math.cos(angle), s = Math.sin(angle);
  return add(add(scale(v, c), scale(cross(k, v), s)), scale(k, dot(k, v) * (1 - c)));
}

// The camera as the scene file's camera map: the keys of its projection only.
function cameraText(c) {
  const map = { type: c.type, from: c.from, at: c.at, up: c.up };
  if (["perspective", "fisheye", "ultra_wide_angle", "cylindrical", "spherical"].includes(c.type))
    map.fov = c.fov;
  if (["orthographic", "cylindrical"].includes(c.type)) map.height = c.height;
  if (c.type === "spherical") map.vertical_fov = c.vertical_fov;
  if (c.type === "cylindrical") Object.assign(map, { axis: c.axis, parallel: c.parallel });
  return JSON.stringify(map);
}

let sending = false, pending = null;
// One move in flight at a time; the newest waiting one goes next, the others are dropped.
async function sendCamera(next) {
  camera = next;
  if (sending) { pending = next; return; }
  sending = true;
  try {
    clearTree();
    const answer = await post("/camera", {}, cameraText(next));
    showError("");
    if (!pending) camera = answer.camera;
  } catch (error) {
    showError(error.message);
  }
  sending = false;
  markDone();
  if (pending) { const p = pending; pending = null; sendCamera(p); }
}

function orbit(c, dx, dy) {
  const up = unit(c.up);
  let offset = sub(c.from, c.at);
  offset = rotate(offset, up, -dx * 0.01);
  const right = unit(cross(offset, up));
  const turned = rotate(offset, right, dy * 0.01);
  // Not over the pole: the view would flip about up.
  if (Math.abs(dot(unit(turned), up)) < 0.99) offset = turned;
  return { ...c, from: add(c.at, offset) };
}

function pan(c, dx, dy) {
  const view = sub(c.at, c.from);
  const distance = Math.hypot(...view);
  const right = unit(cross(view, c.up)), up = unit(cross(right, view));
  // A pixel at the point looked at, for perspective; the view's height for orthographic.
  const pixel = c.type === "orthographic" ? c.height / size.height :
    2 * distance * Math.tan((c.fov * Math.PI) / 360) / size.height;
  const move = add(scale(right, dx * pixel), scale(up, dy * pixel));
  return { ...c, from: add(c.from, move), at: add(c.at, move) };
}

function zoom(c, factor) {
  if (c.type === "orthographic") return { ...c, height: c.height * factor };
  return { ...c, from: add(c.at, scale(sub(c.from, c.at), factor)) };
}

let drag = null;
image.addEventListener("contextmenu", (e) => e.preventDefault());
image.addEventListener("pointerdown", (e) => {
  image.setPointerCapture(e.pointerId);
  drag = { x: e.clientX, y: e.clientY, moved: false, pan: e.shiftKey || e.button === 2,
    start: camera, pointers: (drag?.pointers || 0) + 1 };
});
image.addEventListener("pointermove", (e) => {
  if (!drag || !camera) return;
  const dx = e.clientX - drag.x, dy = e.clientY - drag.y;
  if (!drag.moved && Math.hypot(dx, dy) < 3) return;
  drag.moved = true;
  sendCamera(drag.pan ? pan(drag.start, -dx, dy) : orbit(drag.start, dx, dy));
});
image.addEventListener("pointerup", (e) => {
  if (drag && !drag.moved) explainAt(e);
  drag = null;
});
image.addEventListener("wheel", (e) => {
  e.preventDefault();
  if (camera) sendCamera(zoom(camera, Math.exp(e.deltaY * 0.001)));
}, { passive: false });
// Two fingers pinch to zoom.
let pinch = null;
image.addEventListener("touchmove", (e) => {
  if (e.touches.length !== 2 || !camera) return;
  const d = Math.hypot(e.touches[0].clientX - e.touches[1].clientX,
    e.touches[0].clientY - e.touches[1].clientY);
  if (pinch) sendCamera(zoom(pinch.camera, pinch.distance / d));
  else pinch = { distance: d, camera };
  drag = null;
}, { passive: true });
image.addEventListener("touchend", () => { pinch = null; });

$("copy-camera").addEventListener("click", async () => {
  const text = await (await fetch(url("/camera.yaml"))).text();
  try {
    await navigator.clipboard.writeText(text);
    $("status").textContent = "camera copied: paste it into the scene file";
  } catch {
    window.prompt("The camera, to paste into the scene file:", text);
  }
});
$("reset-camera").addEventListener("click", async () => {
  camera = (await post("/camera/reset")).camera;
  clearTree();
});

// --- The ray tree of a clicked pixel ---

function clearTree() {
  explainedVersion = -1;
  overlay.replaceChildren();
  $("tree").replaceChildren();
  $("explain-status").textContent = "Click a pixel.";
}

const svg = (name, attributes) => {
  const element = document.createElementNS("http://www.w3.org/2000/svg", name);
  for (const [key, value] of Object.entries(attributes)) element.setAttribute(key, value);
  return element;
};

const format = (v) => Array.isArray(v) ? `(${v.map((x) => +x.toPrecision(6)).join(", ")})` :
  typeof v === "number" ? `${+v.toPrecision(6)}` : `${v}`;

function terms(list) {
  const div = document.createElement("div");
  div.className = "terms";
  div.textContent = list.filter(([, v]) => v !== null && v !== undefined)
    .map(([k, v]) => `${k} = ${format(v)}`).join("\n");
  div.style.whiteSpace = "pre";
  return div;
}

// The node's numbers as the notes' formula has them: I = local + kr I(reflected) + kt I(refracted).
function nodeDetails(ray, children) {
  const details = document.createElement("details");
  details.open = ray.depth <= 2;
  details.dataset.node = ray.id;
  const summary = document.createElement("summary");
  summary.className = `kind-${ray.kind === "eye" ? "primary" : ray.kind}`;
  const what = ray.hit ? `${ray.hit.shape} (${ray.hit.material}) at t = ${format(ray.hit.t)}` :
    "missed: the background";
  summary.textContent = `${ray.kind} ray ${ray.id}: ${what} → ${format(ray.value)}`;
  details.append(summary);
  const list = [["origin", ray.origin], ["direction", ray.direction], ["weight", ray.weight],
    ["stop", ray.stop]];
  if (ray.hit) list.push(["point", ray.hit.point], ["N", ray.hit.shading_normal],
    ["emission", ray.emission], ["ambient ka Ia", ray.ambient], ["direct", ray.direct],
    ["contribution", ray.contribution]);
  if (ray.snell) list.push(["n1", ray.snell.n1], ["n2", ray.snell.n2],
    ["cos θi", ray.snell.cos_incident], ["cos θt", ray.snell.cos_refracted],
    ["total internal reflection", ray.snell.total_internal_reflection]);
  if (ray.wavelength !== null && ray.wavelength !== undefined)
    list.push(["wavelength nm", ray.wavelength]);
  details.append(terms(list));
  for (const light of ray.lights || []) {
    const inner = document.createElement("details");
    inner.innerHTML = "<summary></summary>";
    inner.firstChild.textContent = `${light.name} → ${format(light.value)}`;
    for (const s of light.samples)
      inner.append(terms([["L", s.to_light], ["N·L", s.n_dot_l], ["IL", s.intensity],
        ["shadow", s.shadow], ["diffuse", s.diffuse], ["highlight", s.highlight],
        ["term", s.term]]));
    details.append(inner);
  }
  for (const branch of ray.branches || []) {
    details.append(terms([[`${branch.kind} k`, branch.k], ["factor", branch.factor],
      ["stop", branch.stop]]));
    if (branch.child !== null && children[branch.child]) details.append(children[branch.child]);
  }
  summary.addEventListener("mouseenter", () => highlight(ray.id, true, summary));
  summary.addEventListener("mouseleave", () => highlight(ray.id, false, summary));
  return details;
}

function highlight(node, on, summary) {
  summary.classList.toggle("hover", on);
  for (const line of overlay.querySelectorAll(`[data-node="${node}"]`))
    line.classList.toggle("highlight", on);
}

function drawTree(answer, x, y) {
  overlay.replaceChildren(svg("circle", { cx: x + 0.5, cy: y + 0.5, r: 3 }));
  for (const s of answer.overlay) {
    const kind = s.kind === "primary" ? "primary" : s.kind;
    overlay.append(svg("line", { x1: s.from[0], y1: s.from[1], x2: s.to[0], y2: s.to[1],
      class: `${kind}${s.blocked ? " blocked" : ""}`, "data-node": s.node }));
  }
  const rays = answer.tree.rays;
  const built = [];
  for (let i = rays.length - 1; i >= 0; --i) built[i] = nodeDetails(rays[i], built);
  const tree = answer.tree;
  const draws = tree.draws.map((d) => [`${d.purpose} u`, d.u]);
  // Where the eye ray leaves the lens, and when: the eye ray's origin and time.
  if (tree.draws.some((d) => d.purpose === "lens")) draws.push(["lens point", rays[0].origin]);
  if (tree.draws.some((d) => d.purpose === "time")) draws.push(["time", rays[0].time]);
  const head = terms([["pixel", tree.pixel], ["sample", tree.sample],
    ["integrator", tree.integrator], ["film", tree.film], ...draws,
    ["sample value", tree.sample_value]]);
  $("tree").replaceChildren(head, built[0]);
  $("explain-status").textContent = `Pixel ${x}, ${y}, sample ${tree.sample}` +
    (answer.overlay.length ? "" : " (this camera's rays cannot be drawn as straight lines)");
}

async function explainAt(e) {
  // The overlay covers the image's pixels; a view's legend lies below it.
  const box = overlay.getBoundingClientRect();
  const x = Math.floor(((e.clientX - box.left) / box.width) * size.width);
  const y = Math.floor(((e.clientY - box.top) / box.height) * size.height);
  if (x < 0 || y < 0 || x >= size.width || y >= size.height) return;
  const params = { x, y, sample: $("sample").value };
  if ($("explain-integrator").value) params.integrator = $("explain-integrator").value;
  try {
    const answer = await post("/explain", params);
    drawTree(answer, x, y);
    explainedVersion = answer.version;
  } catch (error) {
    $("explain-status").textContent = error.message;
  }
}
