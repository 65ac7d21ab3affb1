// The browser console: polls /preview.png, /status and /ranks about 5 times a second and sends the
// buttons' commands as POST /command, the same lines as the control port takes.
"use strict";

const $ = (id) => document.getElementById(id);
const POLL_MS = 200;
const STALE_MS = 3000; // no answer from the wall this long: say so

// The shared secret, if the wall asks for one: from the address's #token=... (never sent to the
// server in the URL) or typed in; kept for this tab only.
let token = sessionStorage.getItem("token") || "";
const fragment = new URLSearchParams(location.hash.slice(1));
if (fragment.get("token")) {
  token = fragment.get("token");
  sessionStorage.setItem("token", token);
  history.replaceState(null, "", location.pathname);
}

let lastAnswerAt = Date.now();
const stamp = () => new Date().toISOString().replace(/[-:]/g, "").replace(/\..*/, ""); // for file names
let paused = false;

function headers() {
  return token ? { Authorization: "Bearer " + token } : {};
}

// A request with the secret; a 401 for the secret in use shows the prompt (one answered late for a
// secret since replaced does not).
async function request(path, options = {}) {
  const used = token;
  const response = await fetch(path, { ...options, headers: headers(), cache: "no-store" });
  if (response.status === 401) {
    if (used === token) askForSecret();
    throw new Error("the wall asks for its secret");
  }
  return response;
}

function askForSecret() {
  $("login-note").textContent = token
    ? "The wall refused this secret: enter the right one (its --control-token-file)."
    : "The wall asks for its secret (its --control-token-file).";
  if ($("login").hidden) {
    $("login").hidden = false;
    $("token").focus();
  }
}

// Fetches a file the wall wrote (with the secret, hence not a plain link) and saves it as `name`.
async function download(path, name) {
  try {
    const response = await request(path);
    if (!response.ok) throw new Error((await response.text()).trim());
    const a = document.createElement("a");
    a.href = URL.createObjectURL(await response.blob());
    a.download = name;
    a.click();
    setTimeout(() => URL.revokeObjectURL(a.href), 10000);
    $("answer").textContent = "downloaded " + name;
  } catch (err) {
    $("answer").textContent = "download " + name + " → " + err.message;
  }
}

async function command(line) {
  try {
    const response = await request("/command", { method: "POST", body: line });
    const text = (await response.text()).trim();
    $("answer").textContent = line + " → " + text;
    return text;
  } catch (e) {
    $("answer").textContent = line + " → " + e.message;
    return "";
  }
}

function showStatus(s) {
  paused = s.paused;
  $("play").textContent = paused ? "play" : "pause";
  $("status").textContent =
    `frame ${s.frame}  t=${Number(s.time_s).toFixed(1)} s  ${s.fps.toPrecision(3)} fps  ` +
    `${paused ? "paused" : "playing"} ×${s.speed}  ` +
    `${s.lat_deg.toFixed(2)}° ${s.lon_deg.toFixed(2)}° ${s.alt_km.toFixed(1)} km`;
  if (document.activeElement !== $("time")) $("time").value = Number(s.time_s).toFixed(1);
  if (document.activeElement !== $("time-slider")) $("time-slider").value = s.time_s;
  if (document.activeElement !== $("speed")) $("speed").value = s.speed;
  // A movie frame that could not be written (a full disk): the movie writes no more frames.
  $("movie-error").hidden = !s.movie_error;
  if (s.movie_error) $("movie-error").textContent = "movie: " + s.movie_error + " (no more frames; stop the movie)";
}

async function pollStatus() {
  try {
    const response = await request("/status");
    if (!response.ok) throw new Error((await response.text()).trim());
    const s = await response.json();
    showStatus(s);
    camera = s;
    lastAnswerAt = Date.now();
  } catch (e) {
    // the alarm below says it once the silence lasts
  }
}

let previewUrl = null;
async function pollPreview() {
  try {
    const response = await request("/preview.png");
    if (!response.ok) return;
    const url = URL.createObjectURL(await response.blob());
    $("preview").src = url;
    if (previewUrl) URL.revokeObjectURL(previewUrl);
    previewUrl = url;
  } catch (e) {
    // as above
  }
}

// Each rank's render time in the last frame as a bar (longest: full width), red where the rank lags:
// it drew an older frame than the master's, took more than 1.5 times the median, or its last
// heartbeat reached the master more than two heartbeat periods ago (a beat missed).
function rankLags(r, last, median) {
  const heartbeatLate = r.heartbeat_age_s !== null && last.heartbeat_period_s !== null &&
    r.heartbeat_age_s > 2 * last.heartbeat_period_s;
  return r.frame < last.frame || r.render_ms > 1.5 * median || heartbeatLate;
}

async function pollRanks() {
  try {
    const response = await request("/ranks");
    if (!response.ok) return;
    const last = await response.json();
    if (!last.ranks) return;
    const times = last.ranks.map((r) => r.render_ms);
    const longest = Math.max(...times, 1e-9);
    const median = [...times].sort((a, b) => a - b)[Math.floor(times.length / 2)];
    $("ranks").replaceChildren(...last.ranks.map((r, i) => {
      const row = document.createElement("div");
      row.className = "rank" + (rankLags(r, last, median) ? " lagging" : "");
      const bar = document.createElement("span");
      bar.className = "bar";
      bar.style.width = `${(100 * r.render_ms / longest).toFixed(1)}%`;
      const label = document.createElement("span");
      label.className = "label";
      // the master (rank 0) is the one that hears the others
      const heard = i === 0 || r.heartbeat_age_s === null ? "" : `, heard ${r.heartbeat_age_s.toFixed(1)} s ago`;
      label.textContent = `rank ${i}: ${r.render_ms.toFixed(1)} ms, waited ${r.wait_ms.toFixed(1)} ms${heard}`;
      row.append(bar, label);
      return row;
    }));
  } catch (e) {
    // as for the status
  }
}

function checkAlive() {
  const silentS = (Date.now() - lastAnswerAt) / 1000;
  $("alarm").hidden = silentS * 1000 < STALE_MS || !$("login").hidden; // refused, not silent
  $("alarm").textContent = `The wall has not answered for ${silentS.toFixed(0)} s: ` +
    "it may have quit, crashed or be busy; the picture above is the last one.";
}

async function loadPresets() {
  try {
    const names = await (await request("/presets")).json();
    $("presets").replaceChildren(...names.map((name) => {
      const b = document.createElement("button");
      b.type = "button";
      b.textContent = name;
      b.onclick = () => command("preset " + name);
      return b;
    }));
  } catch (e) {
    $("presets").textContent = "no presets: " + e.message;
  }
}

$("play").onclick = () => command(paused ? "play" : "pause");
$("speed").onchange = () => command("speed " + $("speed").value);
$("time-set").onclick = () => command("time " + $("time").value);
$("time").onkeydown = (e) => { if (e.key === "Enter") command("time " + $("time").value); };
$("time-slider").onchange = () => command("time " + $("time-slider").value);
// The screenshot is written into the wall's output folder, then downloaded (GET /screenshots/NAME).
$("screenshot").onclick = async () => {
  const name = `console-${stamp()}.png`;
  if ((await command("screenshot " + name)).startsWith("ok screenshot "))
    await download("/screenshots/" + encodeURIComponent(name), name);
};
// Recording: `record start` / `record stop` of a camera path and `movie start` / `movie stop` into the
// wall's output folder, named by the time pressed. The stopped path can be downloaded (GET
// /recordings/NAME, with the secret, hence fetched: one scene with its base embedded) and replayed:
// `preset FILE` at its first time. The stopped movie can be downloaded as NAME.zip (GET /movies/NAME).
let recording = "";  // the path's name while `record start` runs
let movie = "";      // the movie's name while `movie start` runs
let recorded = null; // the last stopped path: { name, file, from }
let filmed = "";     // the last stopped movie's name

function showRecording() {
  $("record").textContent = recording ? "stop path" : "record path";
  $("record").classList.toggle("on", !!recording);
  $("movie").textContent = movie ? "stop movie" : "record movie";
  $("movie").classList.toggle("on", !!movie);
  $("download").hidden = $("replay").hidden = !recorded;
  if (recorded) $("download").textContent = "download " + recorded.name;
  $("download-movie").hidden = !filmed;
  if (filmed) $("download-movie").textContent = "download " + filmed + ".zip";
}

$("record").onclick = async () => {
  if (!recording) {
    const name = `path-${stamp()}.toml`;
    if ((await command("record start " + name)).startsWith("ok")) recording = name;
  } else {
    const answer = await command("record stop");
    const stopped = answer.match(/^ok record stop (.+) keys=\d+ from_s=(\S+) to_s=\S+$/);
    if (stopped) recorded = { name: recording, file: stopped[1], from: stopped[2] };
    if (answer.startsWith("ok") || answer.includes("no recording runs") || answer.includes("(the recording ended)"))
      recording = "";
  }
  showRecording();
};

$("movie").onclick = async () => {
  const name = movie || `movie-${stamp()}`;
  const answer = await command(movie ? "movie stop" : `movie start ${$("movie-exr").checked ? "exr " : ""}${name}`);
  if (answer.startsWith("ok movie start")) movie = name;
  else if (answer.startsWith("ok movie stop") || answer.startsWith("error movie stop")) {
    if (!answer.includes("no movie runs")) filmed = movie; // its frames up to a failure too
    movie = "";
    $("movie-error").hidden = true;
  }
  showRecording();
};

$("download-movie").onclick = (e) => {
  e.preventDefault();
  download("/movies/" + encodeURIComponent(filmed), filmed + ".zip");
};

$("download").onclick = (e) => {
  e.preventDefault();
  download("/recordings/" + encodeURIComponent(recorded.name), recorded.name);
};

$("replay").onclick = async () => {
  if ((await command("preset " + recorded.file)).startsWith("ok")) await command("time " + recorded.from);
};

// Steering: keys (W/S forward and back, A/D to the sides, R/F up and down, the arrows look), a drag
// on the preview (look; a finger too) and a gamepad (the browser's Gamepad API: the left stick moves,
// the right stick looks), each sent as the protocol's `goto` or `look` from the camera the wall last
// reported. A move covers a tenth of the altitude (at least 1 km) along the ground's great circle.
const PLANET_RADIUS_KM = 6371; // the moves' great circles; the wall keeps its own sphere for the altitude
const LOOK_STEP_DEG = 5;
const DRAG_DEG_PER_PX = 0.2;
let camera = null;   // the last /status (lat_deg, lon_deg, alt_km, heading_deg, pitch_deg)
let steering = false; // one steering command at a time: a held key or stick never floods the wall
let nextSteer = null;  // the latest asked for meanwhile (camera => line), sent when the one in flight ends

const radians = (deg) => deg * Math.PI / 180;
const degrees = (rad) => rad * 180 / Math.PI;
const wrapDeg = (deg) => ((deg % 360) + 540) % 360 - 180;

// `goto` forward and to the right by the given fractions of a move, the altitude times `upFactor`.
function moveLine(c, forward, right, upFactor) {
  const stepKm = Math.max(0.1 * c.alt_km, 1);
  const angle = Math.hypot(forward, right) * stepKm / PLANET_RADIUS_KM;
  const bearing = radians(c.heading_deg) + Math.atan2(right, forward);
  const lat1 = radians(c.lat_deg);
  const lat2 = Math.asin(Math.sin(lat1) * Math.cos(angle) + Math.cos(lat1) * Math.sin(angle) * Math.cos(bearing));
  const lon2 = radians(c.lon_deg) + Math.atan2(Math.sin(bearing) * Math.sin(angle) * Math.cos(lat1),
                                               Math.cos(angle) - Math.sin(lat1) * Math.sin(lat2));
  const altKm = Math.min(Math.max(c.alt_km * upFactor, 0.001), 1e6);
  return `goto ${degrees(lat2).toFixed(6)} ${wrapDeg(degrees(lon2)).toFixed(6)} ${altKm.toFixed(6)}`;
}

function lookLine(c, turnDeg, tiltDeg) {
  const pitch = Math.min(Math.max(c.pitch_deg + tiltDeg, -90), 90);
  return `look ${(((c.heading_deg + turnDeg) % 360) + 360) % 360} ${pitch}`;
}

// Sends the steering line `make(camera)` for the camera as the wall has it now: /status asked first,
// which also reports what a command has just set before a frame shows it, so a move right after a
// turn or a preset starts from them. While one is in flight, only the latest asked for waits (a
// press is never lost, a held key never piles up).
async function steer(make) {
  if (steering) {
    nextSteer = make;
    return;
  }
  steering = true;
  try {
    const response = await request("/status");
    if (response.ok) {
      camera = await response.json();
      await command(make(camera));
    }
  } catch (e) {
    // the alarm says so when the wall stops answering
  }
  steering = false;
  const next = nextSteer;
  nextSteer = null;
  if (next) steer(next);
}

const KEYS = {
  w: (c) => moveLine(c, 1, 0, 1), s: (c) => moveLine(c, -1, 0, 1),
  a: (c) => moveLine(c, 0, -1, 1), d: (c) => moveLine(c, 0, 1, 1),
  r: (c) => moveLine(c, 0, 0, 1.25), f: (c) => moveLine(c, 0, 0, 1 / 1.25),
  ArrowLeft: (c) => lookLine(c, -LOOK_STEP_DEG, 0), ArrowRight: (c) => lookLine(c, LOOK_STEP_DEG, 0),
  ArrowUp: (c) => lookLine(c, 0, LOOK_STEP_DEG), ArrowDown: (c) => lookLine(c, 0, -LOOK_STEP_DEG),
};
document.addEventListener("keydown", (e) => {
  const key = e.key.length === 1 ? e.key.toLowerCase() : e.key;
  if (!KEYS[key] || e.target.closest("input, textarea, select") || !camera) return;
  e.preventDefault();
  steer(KEYS[key]);
});

// A drag on the preview turns the camera: right turns right, up looks up.
let drag = null; // { x, y } of the last look sent
$("preview").addEventListener("pointerdown", (e) => {
  drag = { x: e.clientX, y: e.clientY };
  $("preview").setPointerCapture(e.pointerId);
});
$("preview").addEventListener("pointermove", (e) => {
  if (!drag || steering || !camera) return; // the pixels dragged meanwhile count in the next look
  const dx = e.clientX - drag.x, dy = e.clientY - drag.y;
  if (Math.abs(dx) + Math.abs(dy) < 2) return;
  drag = { x: e.clientX, y: e.clientY };
  steer((c) => lookLine(c, dx * DRAG_DEG_PER_PX, -dy * DRAG_DEG_PER_PX));
});
$("preview").addEventListener("pointerup", () => { drag = null; });
$("preview").addEventListener("pointercancel", () => { drag = null; });

// The first gamepad, read 10 times a second: sticks past a dead zone move and look.
const DEAD_ZONE = 0.15;
setInterval(() => {
  const pad = [...(navigator.getGamepads ? navigator.getGamepads() : [])].find((p) => p && p.connected);
  if (!pad || !camera || pad.axes.length < 4) return;
  const [lx, ly, rx, ry] = pad.axes.map((a) => (Math.abs(a) < DEAD_ZONE ? 0 : a));
  if (lx || ly) steer((c) => moveLine(c, -ly, lx, 1));
  else if (rx || ry) steer((c) => lookLine(c, rx * LOOK_STEP_DEG, -ry * LOOK_STEP_DEG));
}, 100);

// Orbit: the camera turns to the pivot (latitude, longitude, altitude; an empty latitude or longitude
// is the camera's own, so the default pivot is the sky 110 km above it, where the aurora glows) and
// circles it as the protocol's `orbit` does; W/S then move toward and away from it. Steering with
// goto or look ends it, as `orbit off` does.
$("orbit").onclick = () => {
  const pivot = (id, own) => ($(id).value === "" ? own : Number($(id).value));
  steer((c) => `orbit ${pivot("pivot-lat", c.lat_deg)} ${pivot("pivot-lon", c.lon_deg)} ${pivot("pivot-alt", 110)}`);
};
$("orbit-off").onclick = () => command("orbit off");

// The secret typed in is tried on /status: kept if the wall takes it, else the prompt says so.
async function useSecret() {
  token = $("token").value;
  try {
    const response = await request("/status");
    if (!response.ok) throw new Error((await response.text()).trim());
  } catch (e) {
    return; // refused: the prompt stays, saying why; or the wall did not answer: the alarm says so
  }
  sessionStorage.setItem("token", token);
  $("login").hidden = true;
  $("token").value = "";
  $("answer").textContent = "the wall accepted the secret";
  loadPresets();
}
$("token-set").onclick = useSecret;
$("token").onkeydown = (e) => { if (e.key === "Enter") useSecret(); };

// Polls `poll` again POLL_MS after each answer: one request at a time each, so a slow wall is not
// flooded; each on its own, so the ranks' heartbeats still show while the wall's frame loop waits
// for a silent rank and /status does not answer.
function keepPolling(poll) {
  (async function loop() {
    await poll();
    setTimeout(loop, POLL_MS);
  })();
}

loadPresets();
keepPolling(pollStatus);
keepPolling(pollPreview);
keepPolling(pollRanks);
setInterval(checkAlive, POLL_MS);
