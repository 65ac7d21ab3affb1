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

async function request(path, options = {}) {
  const response = await fetch(path, { ...options, headers: headers(), cache: "no-store" });
  if (response.status === 401) {
    $("login").hidden = false;
    throw new Error("the wall asks for its secret");
  }
  return response;
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
}

async function pollStatus() {
  try {
    const response = await request("/status");
    if (!response.ok) throw new Error((await response.text()).trim());
    showStatus(await response.json());
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
  $("alarm").hidden = silentS * 1000 < STALE_MS;
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
$("screenshot").onclick = () => command(`screenshot console-${stamp()}.png`);
// Recording: `record start` / `record stop` of a camera path and `movie start` / `movie stop` into the
// wall's output folder, named by the time pressed. The stopped path can be downloaded (GET
// /recordings/NAME, with the secret, hence fetched) and replayed: `preset FILE` at its first time.
let recording = "";  // the path's name while `record start` runs
let movie = false;
let recorded = null; // the last stopped path: { name, file, from }

function showRecording() {
  $("record").textContent = recording ? "stop path" : "record path";
  $("record").classList.toggle("on", !!recording);
  $("movie").textContent = movie ? "stop movie" : "record movie";
  $("movie").classList.toggle("on", movie);
  $("download").hidden = $("replay").hidden = !recorded;
  if (recorded) $("download").textContent = "download " + recorded.name;
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
  const answer = await command(movie ? "movie stop" : `movie start movie-${stamp()}`);
  if (answer.startsWith("ok movie start")) movie = true;
  else if (answer.startsWith("ok movie stop") || answer.startsWith("error movie stop")) movie = false;
  showRecording();
};

$("download").onclick = async (e) => {
  e.preventDefault();
  try {
    const response = await request("/recordings/" + encodeURIComponent(recorded.name));
    if (!response.ok) throw new Error((await response.text()).trim());
    const a = document.createElement("a");
    a.href = URL.createObjectURL(await response.blob());
    a.download = recorded.name;
    a.click();
    setTimeout(() => URL.revokeObjectURL(a.href), 10000);
    $("answer").textContent = "downloaded " + recorded.name;
  } catch (err) {
    $("answer").textContent = "download " + recorded.name + " → " + err.message;
  }
};

$("replay").onclick = async () => {
  if ((await command("preset " + recorded.file)).startsWith("ok")) await command("time " + recorded.from);
};

$("token-set").onclick = () => {
  token = $("token").value;
  sessionStorage.setItem("token", token);
  $("login").hidden = true;
  loadPresets();
};

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
