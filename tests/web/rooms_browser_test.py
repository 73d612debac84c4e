#!/usr/bin/env python3
"""Call rooms people open themselves (SPEC N6-N7, N12) in real browsers against a real
inkwire-server on 127.0.0.1:

- the front page's "Start a call" (Chromium) gives a link whose name carries at least 64 random
  bits, and its opener is the room's host; a Firefox member and a native member join by the link
  and each sees and hears the others;
- a second room open at the same time hears nothing of the first, nor it of the second;
- the host locks the room: a newcomer is refused with the reason, which names the host to ask;
  a member who is not host cannot lock, restyle or remove (each refused with the reason); the
  host reloads its page and is host again (its key kept by its browser); it sets the call's style
  for everyone and removes the Firefox member, who is told and does not come back by itself;
- after the last member leaves and room_idle_seconds pass, joining the name again finds an
  empty new room with a new host.

  rooms_browser_test.py BIN_DIR OUT_DIR
Firefox's part is skipped with a message where it cannot run (no display, no puppeteer-core)."""
import json
import math
import os
import re
import shutil
import subprocess
import sys
import time
import wave
import array

sys.path.insert(0, os.path.dirname(__file__))
from browser_support import wait_until as shared_wait_until, Checks, Server, chromium, engine, engine_missing, face_clip, skip  # skips without Chromium's tooling
from selenium.webdriver.common.by import By

BIN, OUT = sys.argv[1], os.path.abspath(sys.argv[2])
DLIB = "/usr/share/doc/libdlib19.1/examples/faces"
if not shutil.which("espeak-ng"):
    skip("espeak-ng is missing (scripts/setup.sh installs it)")
if not os.path.exists(os.path.join(DLIB, "2008_001322.jpg")):
    skip(f"libdlib-dev's example photos are missing ({DLIB})")
shutil.rmtree(OUT, ignore_errors=True)
os.makedirs(OUT)
checks = Checks()
check = checks.check
IDLE = 4  # room_idle_seconds here



def wait_until(condition, seconds):
    """browser_support's wait, a page's script errors taken as "not yet" (it is still loading)."""
    return shared_wait_until(condition, seconds, poll=0.2, ignore=(Exception,))


def speech(name, text):
    path = os.path.join(OUT, f"{name}.wav")
    subprocess.run(["espeak-ng", "-v", "en", "-s", "160", "-w", path, " ".join([text] * 20)], check=True)
    return path


def loud_seconds(path):
    """Seconds of a WAV louder than -45 dBFS (in 100 ms steps): a member heard, not silence."""
    with wave.open(path) as w:
        rate, raw = w.getframerate(), w.readframes(w.getnframes())
    samples = array.array("h", raw)
    step = rate // 10
    loud = 0
    for i in range(0, len(samples) - step, step):
        rms = math.sqrt(sum(x * x for x in samples[i:i + step]) / step) / 32768
        loud += rms > 10 ** (-45 / 20)
    return loud / 10


def native(name, session, *extra, seconds=90):
    """A native member of `session` (its camera a photo, its voice a sentence), recording what it
    sees (a frame log) and hears."""
    out = os.path.join(OUT, name)
    os.makedirs(out, exist_ok=True)
    folder, _ = face_clip(out, "camera", os.path.join(DLIB, "2009_004587.jpg"), os.path.join(DLIB, "2009_004587.jpg"), (seconds, 1))
    log = open(os.path.join(out, "client.log"), "w")
    process = subprocess.Popen([f"{BIN}/inkwire-client", "--connect", f"127.0.0.1:{server.tcp}", "--session", session, "--name", name, *extra,
                                "--camera", folder, "--microphone", speech(name, f"This is {name} speaking in the call"), "--headless",
                                "--frames", str(10 * seconds), "--fps", "10", "--size", "320x240", "--out", os.path.join(out, "grid.mp4"),
                                "--audio-out", os.path.join(out, "heard.wav"), "--frame-log", os.path.join(out, "frames.jsonl"),
                                "--cache", os.path.join(out, "cache")], stderr=log, stdout=subprocess.DEVNULL)
    process.out, process.log_path = out, log.name
    return process


def members_seen(process):
    """Every member name the native member's frame log saw."""
    seen = set()
    try:
        for line in open(os.path.join(process.out, "frames.jsonl")):
            for m in json.loads(line).get("members", []):
                seen.add(m["name"])
    except (OSError, ValueError):
        pass
    return seen


server = Server(BIN, OUT, os.path.join(OUT, "data"), {"http": "127.0.0.1:0", "sessions": [], "making": {"room_idle_seconds": IDLE}})
base = f"http://127.0.0.1:{server.http}"
element = "document.querySelector('inkwire-call')"
photo = os.path.join(DLIB, "2008_001322.jpg")
_, ada_camera = face_clip(OUT, "ada-camera", photo, photo, (60, 1))
chrome_flags = ["--use-fake-ui-for-media-stream", "--use-fake-device-for-media-stream", f"--use-file-for-fake-video-capture={ada_camera}",
                f"--use-file-for-fake-audio-capture={speech('ada', 'Hello from Ada in the browser')}", "--autoplay-policy=no-user-gesture-required"]
members = lambda d: sorted(m["name"] for m in d.execute_script(f"return {element}.members"))
ada = firefox = None
natives = []


def join(driver, name):
    wait_until(lambda: driver.execute_script(f"const e = {element}; return !!e && !!e.link"), 60)
    driver.execute_script(f"const e = {element}; e.nameInput.value = '{name}'; e.join();")
    return wait_until(lambda: driver.execute_script(f"return {element}.hasAttribute('joined')"), 60)


try:
    ada = chromium(os.path.join(OUT, "ada"), 900, 700, chrome_flags)
    ada.get(base + "/")
    ada.find_element(By.CSS_SELECTOR, "form.start button").click()
    wait_until(lambda: "/call/" in ada.current_url, 20)
    room = ada.current_url.rsplit("/call/", 1)[-1]
    check(re.fullmatch(r"[A-Za-z0-9_-]{16,}", room) is not None, f"Start a call gives /call/{room}: {len(room) * 6} random bits (>= 64), URL-safe")
    invite = ada.execute_script("return document.querySelector('.invite a').href")
    check(invite.endswith(f"/call/{room}"), f"the page shows the link to copy ({invite})")
    check(join(ada, "Ada"), "Ada opens the room by joining it")
    check(wait_until(lambda: ada.execute_script(f"return {element}.isHost"), 20), "... and is its host")

    # A Firefox member and a native member join by the link.
    nat = native("Nat", room)
    natives.append(nat)
    why = engine_missing("firefox")
    if why:
        print(f"SKIPPED engine firefox: {why}")
    else:
        firefox = engine("firefox", os.path.join(OUT, "firefox"), 900, 700)
        firefox.get(invite)
        check(join(firefox, "Fox"), "a Firefox member joins by the link")
        check(not firefox.execute_script(f"return {element}.isHost"), "... and is no host")
    expected = sorted(["Ada", "Nat"] + (["Fox"] if firefox else []))
    browsers = [("Ada", ada)] + ([("Fox", firefox)] if firefox else [])
    for name, driver in browsers:
        check(wait_until(lambda: members(driver) == expected, 60), f"{name} sees every member ({members(driver)})")
        check(wait_until(lambda: driver.execute_script(f"return {element}.voiceStats.played") > 20, 60),
              f"{name} hears the others ({driver.execute_script(f'return {element}.voiceStats.played')} packets played)")
    check(wait_until(lambda: set(expected) <= members_seen(nat), 60), f"Nat sees every member ({sorted(members_seen(nat))})")

    # A second room at the same time: its members and theirs never meet.
    other = native("Otto", f"{room}-other", "--new")
    natives.append(other)
    check(wait_until(lambda: "Otto" in members_seen(other), 60), "a second room opens beside the first")
    check("Otto" not in members(ada) and not (members_seen(other) & {"Ada", "Nat", "Fox"}),
          f"the two rooms do not see each other ({members(ada)}; {sorted(members_seen(other))})")

    # The host's controls; others are refused them.
    if firefox:
        refusals = f"window.refusals = []; {element}.addEventListener('refused', (e) => refusals.push(e.detail));"
        firefox.execute_script(refusals)
        firefox.execute_script(f"{element}.lockRoom(true); {element}.setCallStyle('comic-extended'); "
                               f"{element}.removeMember({element}.roster.members.find((m) => m.name === 'Ada').member);")
        check(wait_until(lambda: len(firefox.execute_script("return window.refusals")) >= 3, 20),
              f"a member who is not host cannot lock, restyle or remove: {firefox.execute_script('return window.refusals')}")
        check(not ada.execute_script(f"return {element}.locked") and members(ada) == expected, "... and nothing changed")
    ada.execute_script(f"{element}.lockButton.click()")
    check(wait_until(lambda: ada.execute_script(f"return {element}.locked"), 20), "the host locks the room")
    newcomer = subprocess.run([f"{BIN}/inkwire-client", "--connect", f"127.0.0.1:{server.tcp}", "--session", room, "--name", "Late", "--no-rejoin",
                               "--headless", "--frames", "1", "--out", os.path.join(OUT, "late.png"), "--cache", os.path.join(OUT, "cache-late")],
                              capture_output=True, text=True, timeout=60)
    check(newcomer.returncode != 0 and "locked" in newcomer.stderr and "Ada" in newcomer.stderr,
          f"a newcomer is refused with the reason and whom to ask: {newcomer.stderr.strip().splitlines()[-1] if newcomer.stderr.strip() else ''}")

    # The host reloads its page: host again.
    ada.get(invite)
    check(join(ada, "Ada") and wait_until(lambda: ada.execute_script(f"return {element}.isHost"), 30),
          "after a reload the host's browser is host again (its key kept)")
    ada.execute_script(f"const s = {element}.styleSelect; s.value = 'comic-extended'; s.dispatchEvent(new Event('change'));")
    if firefox:
        check(wait_until(lambda: firefox.execute_script(f"return {element}.styleSelect.value") == "comic-extended", 20),
              "the host sets the call's style for everyone")
        firefox.execute_script(f"window.shutOut = ''; {element}.session.addEventListener('shut-out', (e) => shutOut = e.detail);")
        ada.execute_script(f"{element}.removeMember({element}.roster.members.find((m) => m.name === 'Fox').member)")
        check(wait_until(lambda: "removed you" in (firefox.execute_script(f"return {element}.reason") or ""), 20),
              f"the host removes the Firefox member, who is told: {firefox.execute_script(f'return {element}.reason')!r}")
        check(wait_until(lambda: members(ada) == ["Ada", "Nat"], 20), "... and is gone from the call")
        time.sleep(5)  # an absence cannot be waited for: longer than a rejoin would take (2 s)
        check(not firefox.execute_script(f"return {element}.hasAttribute('joined')") and members(ada) == ["Ada", "Nat"],
              "... and does not come back by itself")

    # Everyone leaves; after the idle time the name opens a new, empty room.
    ada.execute_script(f"{element}.hangUp()")
    for p in natives:
        p.terminate()
        p.wait(timeout=30)
    natives.clear()
    check(wait_until(lambda: any(e.get("event") == "room-gone" and e.get("session") == room for e in server.events()), IDLE + 30),
          f"the empty room is gone after {IDLE} s")
    again = native("Neo", room, "--new", seconds=20)
    natives.append(again)
    check(wait_until(lambda: "Neo" in members_seen(again), 60) and members_seen(again) == {"Neo"},
          f"joining the name again finds an empty new room ({sorted(members_seen(again))})")
    check(wait_until(lambda: "are its host" in open(again.log_path).read(), 10), "... with a new host")
    check(loud_seconds(os.path.join(nat.out, "heard.wav")) > 1, f"Nat heard the others ({loud_seconds(os.path.join(nat.out, 'heard.wav')):.1f} s of sound)")
    check(loud_seconds(os.path.join(other.out, "heard.wav")) < 0.5, "Otto, alone in his room, heard nothing of the first")
    ada.save_screenshot(os.path.join(OUT, "ada.png"))
finally:
    for p in natives:
        p.terminate()
    for d in (ada, firefox):
        if d:
            d.quit()
    server.stop()
checks.finish()
