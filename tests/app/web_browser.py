#!/usr/bin/env python3
"""Presses the browser console's buttons in headless Chromium and checks the wall obeys.

Usage: web_browser.py URL SECRET WORK_DIR PRESET RANK1_PID WALL_SIZE

URL is the console of a running wall (http://127.0.0.1:PORT) at the default --rank-timeout (10 s:
a heartbeat every second), SECRET its token, WORK_DIR its --out, PRESET a preset whose camera
differs from the wall's, RANK1_PID the process of its rank 1, WALL_SIZE its whole canvas (WxH).
Chromium is driven through the DevTools protocol over --remote-debugging-pipe (JSON messages ending
in a NUL byte: it reads fd 3, writes fd 4). First the secret's prompt: the page opened without
#token asks for it, a wrong one typed in is refused with a line saying so, the right one (Enter)
makes the console work (status, presets, pause and play); a wrong #token is refused too. Then the
page is opened with #token=SECRET and its real controls are used through Runtime.evaluate: the
pause/play button, the time slider (its value set, then the input and change events the page
listens to), a preset's button. After each, GET /status must show what was asked: paused with
the time standing still, the slider's time, playing with the time running, the camera the preset's
answer reports. The screenshot button: the browser downloads (Browser.setDownloadBehavior into
WORK_DIR/downloads) the PNG the wall wrote, WALL_SIZE. The recording buttons: a path recorded and
stopped, downloaded (one scene, its base embedded: the recorded camera keys) and the downloaded copy
replayed with `preset COPY`, a movie recorded and stopped with its EXR box ticked (its PNGs and EXRs in WORK_DIR)
and downloaded as a zip (the folder's files, byte for byte), the path
replayed. The preview on the page must change when the camera moves. While rank 1 is
stopped (SIGSTOP, for at most 6 s), GET /ranks and the page must show its heartbeat's age growing
past two periods and draw the rank red; once it runs again (SIGCONT), no longer. Writes
WORK_DIR/console.png (Page.captureScreenshot) and WORK_DIR/chromium.log. Standard library only.
Exit status 0 when all holds, 1 otherwise (with one line saying what did not).
"""
import base64
import fcntl
import io
import json
import math
import os
import select
import signal
import subprocess
import sys
import time
import tomllib
import urllib.request
import zipfile

DEADLINE_S = 30.0  # for each condition polled; frames take 50-300 ms on a loaded 2-core machine
POLL_S = 0.1


class Failure(Exception):
    pass


def poll(what, probe, deadline_s=DEADLINE_S):
    """probe() until it returns something true; Failure naming `what` after the deadline."""
    end = time.monotonic() + deadline_s
    last = None
    while time.monotonic() < end:
        last = probe()
        if last:
            return last
        time.sleep(POLL_S)
    raise Failure(f"{what} (waited {deadline_s:.0f} s; last seen: {last!r})")


class Chromium:
    """One headless Chromium, one page, over the DevTools pipe."""

    def __init__(self, work_dir):
        to_chrome_r, to_chrome_w = os.pipe()
        from_chrome_r, from_chrome_w = os.pipe()
        # The child's ends at 10 and above, so bash can put them at 3 and 4 without clobbering one another.
        child_r = fcntl.fcntl(to_chrome_r, fcntl.F_DUPFD, 10)
        child_w = fcntl.fcntl(from_chrome_w, fcntl.F_DUPFD, 10)
        for fd in (to_chrome_r, from_chrome_w):
            os.close(fd)
        self.log = open(os.path.join(work_dir, "chromium.log"), "wb")
        args = ["--headless", "--no-sandbox", "--disable-gpu", "--no-first-run", "--remote-debugging-pipe",
                "--user-data-dir=" + os.path.join(work_dir, "chromium-profile"), "--window-size=720,900",
                "about:blank"]
        self.process = subprocess.Popen(
            ["bash", "-c", f'exec 3<&{child_r} 4>&{child_w} {child_r}<&- {child_w}>&-; exec /usr/bin/chromium "$@"',
             "chromium"] + args,
            pass_fds=(child_r, child_w), stdin=subprocess.DEVNULL, stdout=self.log, stderr=self.log)
        os.close(child_r)
        os.close(child_w)
        self.out, self.inp = to_chrome_w, from_chrome_r
        self.buffer = b""
        self.next_id = 0
        self.events = []
        self.session = None

    def _send(self, message):
        data = json.dumps(message).encode() + b"\0"
        while data:
            data = data[os.write(self.out, data):]

    def _receive(self, deadline):
        """The next message, or None at the deadline; Failure if Chromium closed the pipe."""
        while b"\0" not in self.buffer:
            left = deadline - time.monotonic()
            if left <= 0 or not select.select([self.inp], [], [], left)[0]:
                return None
            chunk = os.read(self.inp, 1 << 20)
            if not chunk:
                raise Failure("Chromium closed the DevTools pipe (see chromium.log)")
            self.buffer += chunk
        message, self.buffer = self.buffer.split(b"\0", 1)
        return json.loads(message)

    def call(self, method, params=None, page=True, timeout_s=DEADLINE_S):
        """A DevTools command's result; events arriving meanwhile are kept in self.events."""
        self.next_id += 1
        message = {"id": self.next_id, "method": method, "params": params or {}}
        if page:
            message["sessionId"] = self.session
        self._send(message)
        deadline = time.monotonic() + timeout_s
        while True:
            answer = self._receive(deadline)
            if answer is None:
                raise Failure(f"no answer to {method} within {timeout_s:.0f} s")
            if answer.get("id") == self.next_id:
                if "error" in answer:
                    raise Failure(f"{method}: {answer['error']}")
                return answer["result"]
            if "method" in answer:
                self.events.append(answer)

    def open(self, url):
        target = self.call("Target.createTarget", {"url": "about:blank"}, page=False)["targetId"]
        self.target = target
        self.session = self.call("Target.attachToTarget", {"targetId": target, "flatten": True}, page=False)["sessionId"]
        self.call("Runtime.enable")
        self.call("Page.enable")
        self.call("Page.navigate", {"url": url})

    def close_page(self):
        """Closes the page opened last (its polling stops)."""
        self.call("Target.closeTarget", {"targetId": self.target}, page=False)
        self.session = None

    def allow_downloads(self, folder):
        """Downloads are saved into folder under their names, and reported as Browser.download* events."""
        self.call("Browser.setDownloadBehavior", {"behavior": "allow", "downloadPath": folder, "eventsEnabled": True},
                  page=False)

    def downloaded(self, folder, name):
        """The bytes of the download named `name`, once Chromium reports it completed (Failure if it
        was cancelled or never came)."""
        def probe():
            self.evaluate("true")  # events arrive with answers
            guids = [e["params"]["guid"] for e in self.events if e.get("method") == "Browser.downloadWillBegin"
                     and e["params"].get("suggestedFilename") == name]
            states = [e["params"]["state"] for e in self.events if e.get("method") == "Browser.downloadProgress"
                      and e["params"]["guid"] in guids and e["params"]["state"] != "inProgress"]
            if "canceled" in states:
                raise Failure(f"the download of {name} was cancelled")
            return "completed" in states and os.path.isfile(os.path.join(folder, name))
        poll(f"the browser's download of {name} into {folder}", probe)
        with open(os.path.join(folder, name), "rb") as f:
            return f.read()

    def evaluate(self, expression):
        """The value of a JavaScript expression in the page (promises awaited); Failure if it throws."""
        result = self.call("Runtime.evaluate", {"expression": expression, "returnByValue": True, "awaitPromise": True})
        if "exceptionDetails" in result:
            raise Failure(f"the page threw on {expression!r}: {result['exceptionDetails'].get('exception', {}).get('description', result['exceptionDetails'].get('text'))}")
        return result["result"].get("value")

    def page_errors(self):
        return [e["params"]["exceptionDetails"].get("exception", {}).get("description", "?")
                for e in self.events if e.get("method") == "Runtime.exceptionThrown"]

    def screenshot(self, path):
        data = self.call("Page.captureScreenshot", {"format": "png"})["data"]
        with open(path, "wb") as f:
            f.write(base64.b64decode(data))

    def close(self):
        try:
            self.call("Browser.close", page=False, timeout_s=5)
        except (Failure, OSError):
            pass
        try:
            self.process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.process.kill()
            self.process.wait()
        os.close(self.out)
        os.close(self.inp)
        self.log.close()


class Wall:
    """GET /status of the wall, beside the page."""

    def __init__(self, url, secret):
        self.url, self.secret = url, secret

    def status(self):
        request = urllib.request.Request(self.url + "/status", headers={"Authorization": "Bearer " + self.secret})
        with urllib.request.urlopen(request, timeout=15) as r:
            return json.load(r)

    def ranks(self):
        request = urllib.request.Request(self.url + "/ranks", headers={"Authorization": "Bearer " + self.secret})
        with urllib.request.urlopen(request, timeout=15) as r:
            return json.load(r)

    def command(self, line):
        request = urllib.request.Request(self.url + "/command", data=line.encode(), method="POST",
                                         headers={"Authorization": "Bearer " + self.secret})
        with urllib.request.urlopen(request, timeout=15) as r:
            return r.read().decode().strip()

    def frames_later(self, count):
        """The status once the wall has drawn `count` more frames."""
        first = self.status()["frame"]
        return poll(f"{count} frames after frame {first}", lambda: (lambda s: s if s["frame"] >= first + count else None)(self.status()))


# JavaScript helpers defined in the page once it has loaded.
PAGE_HELPERS = r"""
window.awTest = {
  click(id) { document.getElementById(id).click(); return true; },
  text(id) { return document.getElementById(id).textContent; },
  shown(id) { return getComputedStyle(document.getElementById(id)).display !== "none"; },
  // A number typed into field `id`: its value, then the change event the page listens to.
  type(id, value) {
    const f = document.getElementById(id);
    f.value = value;
    f.dispatchEvent(new Event("change", { bubbles: true }));
    return f.value;
  },
  // The time slider moved as a hand would: its value, then the events the page listens to.
  slide(value) {
    const s = document.getElementById("time-slider");
    s.value = value;
    s.dispatchEvent(new Event("input", { bubbles: true }));
    s.dispatchEvent(new Event("change", { bubbles: true }));
    return s.value;
  },
  // Rank i's row in the ranks' view: its label and whether it is drawn as lagging.
  rank(i) {
    const row = document.querySelectorAll("#ranks .rank")[i];
    return row ? { label: row.textContent, lagging: row.classList.contains("lagging") } : null;
  },
  clickPreset(name) {
    const b = [...document.querySelectorAll("#presets button")].find((b) => b.textContent === name);
    if (!b) return false;
    b.click();
    return true;
  },
  // The preview's pixels, decoded, as a short fingerprint (width, height, a sum over every byte).
  async preview() {
    const img = document.getElementById("preview");
    if (!img.src) return null;
    // The page swaps the picture 5 times a second: a decode that a newer picture overtook rejects,
    // and the caller polls again.
    try { await img.decode(); } catch (e) { return null; }
    const c = document.createElement("canvas");
    c.width = img.naturalWidth;
    c.height = img.naturalHeight;
    const g = c.getContext("2d");
    g.drawImage(img, 0, 0);
    const d = g.getImageData(0, 0, c.width, c.height).data;
    let h = 0;
    for (let i = 0; i < d.length; ++i) h = (h * 31 + d[i]) >>> 0;
    return `${c.width}x${c.height}:${h}`;
  },
};
true
"""


def answer_after(browser, prefix):
    """The page's answer line once it shows the answer to a command beginning with `prefix` (on a
    timeout, the Failure names the line it showed last)."""
    shown = [None]

    def probe():
        shown[0] = browser.evaluate("awTest.text('answer')")
        return shown[0] if shown[0].startswith(prefix) and " → " in shown[0] else None
    try:
        return poll(f"the page's answer to '{prefix}'", probe)
    except Failure as e:
        raise Failure(f"{e}; the page showed: {shown[0]!r}") from None


def check_pause_and_play(browser, wall):
    poll("the page showing the wall playing", lambda: browser.evaluate("awTest.text('play')") == "pause")
    browser.evaluate("awTest.click('play')")
    print("pause ->", answer_after(browser, "pause"))
    poll("/status paused", lambda: wall.status()["paused"])
    before = wall.status()
    after = wall.frames_later(3)
    if after["time_s"] != before["time_s"]:
        raise Failure(f"paused, yet the time ran from {before['time_s']} (frame {before['frame']}) to {after['time_s']} (frame {after['frame']})")
    print(f"paused: frames {before['frame']} to {after['frame']} all at time_s={after['time_s']}")

    # The time slider, while paused: the next frames show exactly its time.
    print("slider ->", browser.evaluate("awTest.slide(1234)"))
    print("time ->", answer_after(browser, "time 1234"))
    poll("/status time_s=1234 after the slider", lambda: wall.status()["time_s"] == 1234)
    print("slider: /status time_s=1234")

    poll("the page showing the wall paused", lambda: browser.evaluate("awTest.text('play')") == "play")
    browser.evaluate("awTest.click('play')")
    print("play ->", answer_after(browser, "play"))
    poll("/status playing", lambda: not wall.status()["paused"])
    before = wall.status()
    after = wall.frames_later(3)
    if not after["time_s"] > before["time_s"] >= 1234:
        raise Failure(f"playing, yet the time went from {before['time_s']} to {after['time_s']}")
    print(f"playing: time_s {before['time_s']} at frame {before['frame']} -> {after['time_s']} at frame {after['frame']}")
    # The speed field, typed into as a hand would: the wall's speed, then back to 1.
    for speed in (4, 1):
        browser.evaluate(f"awTest.type('speed', {speed})")
        answer = answer_after(browser, f"speed {speed}").split(" → ", 1)[1]
        poll(f"/status speed {speed}", lambda: wall.status()["speed"] == speed)
        print(f"speed {speed} -> {answer}")


def check_preset_and_preview(browser, wall, preset):
    first = poll("a preview on the page", lambda: browser.evaluate("awTest.preview()"))
    if not browser.evaluate(f"awTest.clickPreset({json.dumps(preset)})"):
        raise Failure(f"no button for the preset {preset}")
    answer = answer_after(browser, "preset " + preset).split(" → ", 1)[1]
    print(f"preset {preset} ->", answer)
    if not answer.startswith("ok preset " + preset):
        raise Failure(f"preset {preset} answered {answer}")
    asked = {k: float(v) for k, v in (w.split("=") for w in answer.split()[3:])}
    status = poll("/status at the preset's camera",
                  lambda: (lambda s: s if all(abs(s[k] - v) < 1e-6 for k, v in asked.items()) else None)(wall.status()))
    print("camera:", {k: status[k] for k in asked})
    second = poll("the preview on the page changing with the camera",
                  lambda: (lambda p: p if p and p != first else None)(browser.evaluate("awTest.preview()")))
    print(f"preview: {first} -> {second}")


def great_circle_km(a, b):
    """The ground distance between two /status cameras on a 6371 km sphere (the page's moves)."""
    la1, lo1, la2, lo2 = (math.radians(v) for v in (a["lat_deg"], a["lon_deg"], b["lat_deg"], b["lon_deg"]))
    h = math.sin((la2 - la1) / 2) ** 2 + math.cos(la1) * math.cos(la2) * math.sin((lo2 - lo1) / 2) ** 2
    return 2 * 6371 * math.asin(math.sqrt(h))


def initial_bearing_deg(a, b):
    """The great circle's bearing from camera a to camera b at a, clockwise from north."""
    la1, lo1, la2, lo2 = (math.radians(v) for v in (a["lat_deg"], a["lon_deg"], b["lat_deg"], b["lon_deg"]))
    y = math.sin(lo2 - lo1) * math.cos(la2)
    x = math.cos(la1) * math.sin(la2) - math.sin(la1) * math.cos(la2) * math.cos(lo2 - lo1)
    return math.degrees(math.atan2(y, x)) % 360


def check_steering(browser, wall):
    """An arrow key turns the camera 5 degrees, W moves it a tenth of its altitude (at least 1 km)
    forward at the same altitude, a drag of 50 px across the preview turns it 10 degrees."""
    def key(name, code, vk):
        for kind in ("keyDown", "keyUp"):
            event = {"type": kind, "key": name, "code": code, "windowsVirtualKeyCode": vk}
            if kind == "keyDown" and len(name) == 1:
                event["text"] = name  # a character key: its keydown carries the character
            browser.call("Input.dispatchKeyEvent", event)

    def turned_by(before, degrees):
        want = (before["heading_deg"] + degrees) % 360
        return lambda: (lambda s: s if abs((s["heading_deg"] - want + 180) % 360 - 180) < 1e-4 else None)(wall.status())

    before = wall.status()
    key("ArrowRight", "ArrowRight", 39)
    after = poll("/status turned 5 degrees right by the arrow key", turned_by(before, 5))
    answer_after(browser, "look ")  # the page has its answer: the next press starts from it
    print(f"ArrowRight: heading {before['heading_deg']:.6f} -> {after['heading_deg']:.6f}")
    before = after
    key("w", "KeyW", 87)
    step_km = max(0.1 * before["alt_km"], 1)
    answer = answer_after(browser, "goto ").split(" → ", 1)[1]
    if not answer.startswith("ok goto"):
        raise Failure(f"W: the page's goto answered {answer}")
    after = poll("/status moved forward by W", lambda: (lambda s: s if great_circle_km(before, s) > 0.5 * step_km else None)(wall.status()))
    moved = great_circle_km(before, after)
    bearing = initial_bearing_deg(before, after)
    print(f"W: moved {moved:.6f} km toward {bearing:.4f} deg (a move: {step_km:.6f} km toward the heading "
          f"{before['heading_deg']:.4f}), altitude {before['alt_km']:.6f} -> {after['alt_km']:.6f} km")
    if abs(moved - step_km) > 1e-3 * step_km or abs(after["alt_km"] - before["alt_km"]) > 1e-5:
        raise Failure(f"W moved {moved} km at altitude {after['alt_km']}, expected {step_km} km at {before['alt_km']}")
    # The goto's 6 decimals of a degree (0.1 m) leave the bearing of a 1 km move within 0.01 degree.
    if abs((bearing - before["heading_deg"] + 180) % 360 - 180) > 0.05:
        raise Failure(f"W moved toward {bearing} deg, not along the heading {before['heading_deg']}")
    before = after
    box = browser.evaluate("(() => { const r = document.getElementById('preview').getBoundingClientRect(); "
                           "return [r.left + r.width / 2, r.top + r.height / 2]; })()")
    x, y = box
    browser.call("Input.dispatchMouseEvent", {"type": "mousePressed", "x": x, "y": y, "button": "left", "buttons": 1, "clickCount": 1})
    browser.call("Input.dispatchMouseEvent", {"type": "mouseMoved", "x": x + 50, "y": y, "button": "left", "buttons": 1})
    browser.call("Input.dispatchMouseEvent", {"type": "mouseReleased", "x": x + 50, "y": y, "button": "left", "buttons": 0, "clickCount": 1})
    after = poll("/status turned 10 degrees right by a 50 px drag", turned_by(before, 10))
    answer_after(browser, f"look {after['heading_deg']:.0f}")  # the drag's look answered: none in flight
    print(f"drag: heading {before['heading_deg']:.6f} -> {after['heading_deg']:.6f}")


def check_narrow_screen(browser, work_dir):
    """On a phone's screen (375 CSS px wide, touch) the page fits its width: nothing scrolls sideways
    and every control lies within the screen."""
    browser.call("Emulation.setDeviceMetricsOverride", {"width": 375, "height": 812, "deviceScaleFactor": 2, "mobile": True})
    browser.call("Emulation.setTouchEmulationEnabled", {"enabled": True, "maxTouchPoints": 5})
    fits = poll("the page fitting 375 px", lambda: browser.evaluate(
        "(() => { const w = document.documentElement.clientWidth;"
        " const out = [...document.querySelectorAll('button, input, img')].filter((e) => e.offsetParent &&"
        " e.getBoundingClientRect().right > w + 0.5).map((e) => e.id || e.textContent);"
        " return w === 375 && document.documentElement.scrollWidth <= w && out.length === 0 ? w :"
        " null; })()"))
    browser.screenshot(os.path.join(work_dir, "console-phone.png"))
    print(f"phone: the page fits {fits} px, every control within it")


def check_gamepad(browser, wall):
    """The page's gamepad polling, fed by a stand-in for navigator.getGamepads (a headless browser has
    no pad, and DevTools cannot plug one in): the left stick pushed forward moves the camera forward,
    released it stops."""
    before = wall.status()
    browser.evaluate("(() => { window.awPad = { connected: true, axes: [0, -1, 0, 0] };"
                     " navigator.getGamepads = () => [window.awPad]; return true; })()")
    moved = poll("/status moved by the gamepad's left stick",
                 lambda: (lambda s: s if great_circle_km(before, s) > 0.5 else None)(wall.status()))
    browser.evaluate("(() => { window.awPad.axes = [0, 0, 0, 0]; return true; })()")
    bearing = initial_bearing_deg(before, moved)
    print(f"gamepad: moved {great_circle_km(before, moved):.3f} km toward {bearing:.3f} deg (heading {before['heading_deg']:.3f})")
    if abs((bearing - before["heading_deg"] + 180) % 360 - 180) > 0.05:
        raise Failure(f"the stick moved the camera toward {bearing} deg, not along the heading {before['heading_deg']}")
    answer_after(browser, "goto ")  # its last move answered: none in flight


def check_orbit(browser, wall):
    """The orbit button with the pivot's latitude and longitude left empty: the sky 110 km above the
    camera, so the camera turns to look straight up at it; orbit off ends it."""
    browser.evaluate("awTest.click('orbit')")
    answer = answer_after(browser, "orbit ").split(" → ", 1)[1]
    if not answer.startswith("ok orbit ") or "alt_km=110 " not in answer:
        raise Failure(f"orbit answered {answer}")
    status = poll("/status looking up at the pivot", lambda: (lambda s: s if s["pitch_deg"] > 89.9 else None)(wall.status()))
    print(f"orbit -> {answer}; pitch {status['pitch_deg']:.4f}")
    browser.evaluate("awTest.click('orbit-off')")
    if answer_after(browser, "orbit off").split(" → ", 1)[1] != "ok orbit off":
        raise Failure("orbit off was not answered ok")


def load_page(browser, url):
    browser.open(url)
    poll("the page's script loaded", lambda: browser.evaluate("typeof command === 'function' && document.readyState === 'complete'"))
    browser.evaluate(PAGE_HELPERS)


def check_secret_prompt(browser, wall, url, secret):
    """Opened without the secret, the page asks for it; a wrong one typed in is refused with a line
    saying so, the right one (typed, then Enter) makes the console work; a wrong one in the address
    is refused the same way."""
    def type_secret(text):
        browser.evaluate("(() => { const f = document.getElementById('token'); f.value = ''; f.focus(); return true; })()")
        browser.call("Input.insertText", {"text": text})

    def note(words):
        return lambda: (lambda n: n if awshown() and words in n else None)(browser.evaluate("awTest.text('login-note')"))
    awshown = lambda: browser.evaluate("awTest.shown('login')")

    load_page(browser, f"{url}/")
    print("no secret:", poll("the page asking for the secret", note("asks for its secret")))
    type_secret("wrong-" + secret)
    browser.evaluate("awTest.click('token-set')")
    print("a wrong secret:", poll("the page refusing a wrong secret", note("refused")))
    if browser.evaluate("awTest.text('status')").startswith("frame "):
        raise Failure("the page showed the wall's status without the secret")
    type_secret(secret)
    for kind in ("keyDown", "keyUp"):
        browser.call("Input.dispatchKeyEvent", {"type": kind, "key": "Enter", "code": "Enter", "windowsVirtualKeyCode": 13})
    poll("the prompt gone after the right secret", lambda: not awshown())
    poll("the page accepting the secret", lambda: browser.evaluate("awTest.text('answer')") == "the wall accepted the secret")
    poll("the status line filled after the secret", lambda: browser.evaluate("awTest.text('status')").startswith("frame "))
    poll("the preset buttons after the secret", lambda: browser.evaluate("document.querySelectorAll('#presets button').length"))
    # A command from the page: pause, then play again.
    for press, paused in (("pause", True), ("play", False)):
        poll(f"the page's {press} button", lambda: browser.evaluate("awTest.text('play')") == press)
        browser.evaluate("awTest.click('play')")
        answer_after(browser, press)
        poll(f"/status paused={paused} after the page's {press}", lambda: wall.status()["paused"] == paused)
    if awshown():
        raise Failure("the page asks for the secret again after accepting it")
    print("the right secret: accepted, status, presets, pause and play from the page")
    browser.close_page()
    load_page(browser, f"{url}/#token=wrong-{secret}")
    print("a wrong secret in the address:", poll("the page refusing the address's secret", note("refused")))
    browser.close_page()


def png_size(data):
    """(width, height) of PNG bytes, from the IHDR chunk; Failure if they are not a PNG."""
    if data[:8] != b"\x89PNG\r\n\x1a\n" or data[12:16] != b"IHDR":
        raise Failure(f"not a PNG: {data[:16]!r}")
    return int.from_bytes(data[16:20], "big"), int.from_bytes(data[20:24], "big")


def check_screenshot(browser, work_dir, downloads, wall_size):
    """The screenshot button: the wall writes the file into its output folder and the browser
    downloads the same bytes, a PNG of the whole wall."""
    browser.evaluate("awTest.click('screenshot')")
    # The command's answer, then (at once) the download's: "downloaded NAME" only if both went well.
    def done():
        line = browser.evaluate("awTest.text('answer')")
        if line.startswith("screenshot ") and " → error" in line or line.startswith("download "):
            raise Failure(f"screenshot: {line}")
        return line if line.startswith("downloaded console-") else None
    answer = poll("the page's screenshot downloaded", done)
    name = answer.split()[1]
    data = browser.downloaded(downloads, name)
    with open(os.path.join(work_dir, name), "rb") as f:
        if f.read() != data:
            raise Failure(f"the downloaded {name} differs from the wall's file")
    size = "%dx%d" % png_size(data)
    if size != wall_size:
        raise Failure(f"the downloaded screenshot is {size}, the wall {wall_size}")
    print(f"screenshot: the page: {answer}; {len(data)} bytes, a {size} PNG, the file the wall wrote")


def check_downloaded_recording(text, recorded, name):
    """The downloaded path is one self-contained scene: no base, the recorded [scene] times and
    camera keys as recorded, the base scene's tables embedded. Returns its table names."""
    got, had = tomllib.loads(text), tomllib.loads(recorded)
    if "base" in got["scene"] or "base" not in had["scene"]:
        raise Failure(f"the downloaded {name} still names a base scene (or the recorded one none)")
    for key in ("start_time_s", "time_step_s"):
        if got["scene"][key] != had["scene"][key]:
            raise Failure(f"the downloaded {name}: [scene] {key} {got['scene'][key]} != {had['scene'][key]}")
    if got["camera"] != had["camera"]:
        raise Failure(f"the downloaded {name}: its camera keys differ from the recorded ones")
    if not set(got["scene"]["components"]) <= set(got):
        raise Failure(f"the downloaded {name} lacks tables of its components {got['scene']['components']}")
    return sorted(got)


def check_recording(browser, wall, work_dir, downloads):
    """Record path, stop, download (the file's bytes), record movie, stop (its PNGs), replay path."""
    browser.evaluate("awTest.click('record')")
    started = answer_after(browser, "record start")
    if "→ ok record start" not in started or browser.evaluate("awTest.text('record')") != "stop path":
        raise Failure(f"record path: {started}")
    wall.frames_later(5)
    browser.evaluate("awTest.click('record')")
    stopped = answer_after(browser, "record stop")
    if "→ ok record stop" not in stopped or not browser.evaluate("awTest.shown('download')"):
        raise Failure(f"stop path: {stopped}")
    name = browser.evaluate("recorded.name")
    status, kind, text = browser.evaluate(
        "(async () => { const r = await request('/recordings/' + encodeURIComponent(recorded.name));"
        " return [r.status, r.headers.get('content-type'), await r.text()]; })()")
    if (status, kind) != (200, "application/toml"):
        raise Failure(f"GET /recordings/{name}: {status} {kind}")
    with open(os.path.join(work_dir, name)) as f:
        tables = check_downloaded_recording(text, f.read(), name)
    browser.evaluate("awTest.click('download')")
    copy = os.path.join(downloads, name)
    if browser.downloaded(downloads, name).decode() != text:
        raise Failure(f"the browser's download of {name} differs from GET /recordings/{name}")
    poll("the page's download", lambda: browser.evaluate("awTest.text('answer')") == "downloaded " + name)
    replayed = wall.command("preset " + copy)  # the downloaded copy, outside the output folder
    if not replayed.startswith("ok preset " + copy):
        raise Failure(f"preset {copy} (the downloaded path) answered {replayed}")
    print(f"downloaded {copy} (self-contained: {', '.join(tables)}); preset it -> {replayed}")
    browser.evaluate("awTest.click('movie-exr')")  # the "EXR too" box: PNG and OpenEXR frames
    browser.evaluate("awTest.click('movie')")
    if "→ ok movie start" not in answer_after(browser, "movie start"):
        raise Failure("record movie: " + browser.evaluate("awTest.text('answer')"))
    wall.frames_later(3)
    browser.evaluate("awTest.click('movie')")
    movie = answer_after(browser, "movie stop")
    folder, frames = movie.split("ok movie stop ")[1].rsplit(" frames=", 1)
    pngs = [f for f in os.listdir(folder) if f.endswith(".png")]
    exrs = [f for f in os.listdir(folder) if f.endswith(".exr")]
    if len(pngs) != int(frames) or len(exrs) != int(frames) or int(frames) < 3:
        raise Failure(f"stop movie: {movie}, {len(pngs)} PNGs and {len(exrs)} EXRs in {folder}")
    if not browser.evaluate("awTest.shown('download-movie')"):
        raise Failure("stop movie: no download link for the movie")
    browser.evaluate("awTest.click('download-movie')")
    zip_name = os.path.basename(folder) + ".zip"
    with zipfile.ZipFile(io.BytesIO(browser.downloaded(downloads, zip_name))) as z:
        members = sorted(z.namelist())
        want = sorted(os.path.basename(folder) + "/" + f for f in os.listdir(folder))
        if members != want:
            raise Failure(f"the downloaded {zip_name} holds {members}, the folder {want}")
        for member in members:
            with open(os.path.join(folder, os.path.basename(member)), "rb") as f:
                if z.read(member) != f.read():
                    raise Failure(f"{member} in the downloaded {zip_name} differs from the wall's file")
    poll("the page's movie download", lambda: browser.evaluate("awTest.text('answer')") == "downloaded " + zip_name)
    browser.evaluate("awTest.click('replay')")
    replayed = answer_after(browser, "time ")
    if "→ ok time_s=" not in replayed:
        raise Failure(f"replay path: {replayed}")
    print(f"recorded {name} ({stopped.split('keys=')[1]}), downloaded; movie of {frames} frames, downloaded as "
          f"{zip_name}; {replayed}")


def check_silent_rank(browser, wall, pid):
    poll("rank 1 drawn as keeping up", lambda: (lambda r: r and not r["lagging"])(browser.evaluate("awTest.rank(1)")))
    period = wall.ranks()["heartbeat_period_s"]
    os.kill(pid, signal.SIGSTOP)  # its heartbeat thread stops too; the frame loop waits for it
    try:
        stopped = time.monotonic()

        def late():
            row = browser.evaluate("awTest.rank(1)")
            age = wall.ranks()["ranks"][1]["heartbeat_age_s"]
            return (row, age) if row and row["lagging"] and "heard" in row["label"] and age > 2 * period else None
        row, age = poll("rank 1 red with its heartbeat more than two periods old", late, deadline_s=6.0)
        print(f"rank 1 stopped {time.monotonic() - stopped:.1f} s: /ranks heartbeat_age_s={age}, page: {row}")
    finally:
        os.kill(pid, signal.SIGCONT)
    row = poll("rank 1 drawn as keeping up again", lambda: (lambda r: r if r and not r["lagging"] else None)(browser.evaluate("awTest.rank(1)")))
    after = wall.frames_later(3)
    print(f"rank 1 running again: page: {row}; the wall at frame {after['frame']}")


def main():
    url, secret, work_dir, preset, rank1_pid, wall_size = sys.argv[1:7]
    wall = Wall(url, secret)
    downloads = os.path.join(work_dir, "downloads")  # one folder deeper: a relative base would miss from there
    os.makedirs(downloads, exist_ok=True)
    browser = Chromium(work_dir)
    try:
        browser.call("Browser.getVersion", page=False)
        browser.allow_downloads(downloads)
        check_secret_prompt(browser, wall, url, secret)
        load_page(browser, f"{url}/#token={secret}")
        poll("the status line filled", lambda: browser.evaluate("awTest.text('status')").startswith("frame "))
        poll("the preset buttons", lambda: browser.evaluate("document.querySelectorAll('#presets button').length"))
        if browser.evaluate("awTest.shown('login')"):
            raise Failure("the page asks for the secret though its address gave it")
        check_pause_and_play(browser, wall)
        check_preset_and_preview(browser, wall, preset)
        check_steering(browser, wall)
        check_gamepad(browser, wall)
        check_orbit(browser, wall)
        check_screenshot(browser, work_dir, downloads, wall_size)
        check_recording(browser, wall, work_dir, downloads)
        check_silent_rank(browser, wall, int(rank1_pid))
        shot = os.path.join(work_dir, "console.png")
        browser.screenshot(shot)
        with open(shot, "rb") as f:
            if f.read(8) != b"\x89PNG\r\n\x1a\n":
                raise Failure("the screenshot is not a PNG")
        print(f"screenshot: {shot}, {os.path.getsize(shot)} bytes")
        check_narrow_screen(browser, work_dir)
        if browser.page_errors():
            raise Failure(f"the page threw: {browser.page_errors()}")
    except Failure as e:
        print(f"FAIL: {e}", file=sys.stderr)
        return 1
    finally:
        browser.close()
    return 0


if __name__ == "__main__":
    sys.exit(main())
