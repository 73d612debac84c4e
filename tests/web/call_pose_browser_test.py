#!/usr/bin/env python3
"""A member whose head rolls is drawn rolled at the other members (SPEC F20), natively and in a
real headless browser: a native inkwire-client member ("Nat") publishes a camera that shows
libdlib's example photo upright until the page has drawn it upright, then turned 20 degrees in
the picture (as a head tilted towards its right shoulder); a Chromium member ("Ada", no camera: a listener) and
Nat's own recording (its tile shows what the others are sent) draw Nat's face. Checks: the pose
the page's element and the native frame log say Nat's face is drawn with (roll 20 +- 3), and the
pose the server's own reading finds in each drawn picture (inkwire-eval head-pose against the
photo: 20 +- 3 degrees), and in a picture from before the tilt (0 +- 3).
  call_pose_browser_test.py BIN_DIR OUT_DIR
Skips with a message without chromium, chromedriver, selenium, libdlib's photos and model, or
inkwire-eval (built with the bench)."""
import json
import os
import shutil
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(__file__))
from browser_support import Checks, Server, chromium, skip  # skips without the browser

BIN, OUT = sys.argv[1], os.path.abspath(sys.argv[2])
PHOTO = "/usr/share/doc/libdlib19.1/examples/faces/Tom_Cruise_avp_2014_4.jpg"
MODEL = "/usr/share/dlib/shape_predictor_68_face_landmarks.dat"
for needed in (PHOTO, MODEL, os.path.join(BIN, "inkwire-eval")):
    if not os.path.exists(needed):
        skip(f"{needed} is missing (libdlib-dev, libdlib-data; inkwire-eval is built with INKWIRE_BUILD_BENCH)")
shutil.rmtree(OUT, ignore_errors=True)
os.makedirs(OUT)
checks = Checks()
ROLL = 20

# The camera: the photo at 320 x 452 (a webcam's face size), then turned 20 degrees clockwise on
# screen (ffmpeg's rotate turns clockwise for a positive angle), its corners filled with grey.
upright, tilted = os.path.join(OUT, "upright.png"), os.path.join(OUT, "tilted.png")
subprocess.run(["ffmpeg", "-v", "error", "-y", "-i", PHOTO, "-vf", "scale=320:-2", upright], check=True)
subprocess.run(["ffmpeg", "-v", "error", "-y", "-i", upright, "-vf", f"rotate={ROLL}*PI/180:fillcolor=gray", tilted], check=True)
# The client reads each picture when it is due, so the tilt comes when the links are turned to the
# tilted picture: once the page has drawn the face upright, whenever that is on a loaded machine.
camera = os.path.join(OUT, "camera")
os.makedirs(camera)
FRAMES = 15 * 90
for frame in range(FRAMES):
    os.symlink(upright, os.path.join(camera, f"{frame:04d}.png"))


def tilt_camera():
    for frame in range(FRAMES):
        link = os.path.join(camera, f"{frame:04d}.png")
        os.symlink(tilted, link + ".new")
        os.replace(link + ".new", link)


def pose_in(picture):
    """The pose the server's reading finds in `picture`, against the upright photo."""
    out = os.path.join(OUT, os.path.basename(picture) + ".json")
    run = subprocess.run([os.path.join(BIN, "inkwire-eval"), "head-pose", "--neutral", upright, "--image", picture, "--json", out],
                         capture_output=True, text=True)
    return json.load(open(out)) if run.returncode == 0 else None


server = Server(BIN, OUT, os.path.join(OUT, "data"), {"http": "127.0.0.1:0", "sessions": [{"name": "call", "kind": "conference"}]})
element = "document.querySelector('inkwire-call')"
driver = native = None
try:
    driver = chromium(OUT, 640, 520)
    driver.get(f"http://127.0.0.1:{server.http}/call/call")
    driver.execute_script(f"const e = {element}; e.nameInput.value = 'Ada'; e.join();")
    native = subprocess.Popen([f"{BIN}/inkwire-client", "--connect", f"127.0.0.1:{server.tcp}", "--session", "call", "--name", "Nat",
                               "--camera", camera, "--headless", "--frames", str(FRAMES), "--fps", "15", "--size", "480x360",
                               "--out", os.path.join(OUT, "nat-%04d.png"), "--frame-log", os.path.join(OUT, "nat.jsonl"),
                               "--cache", os.path.join(OUT, "cache-nat")], stderr=open(os.path.join(OUT, "nat.log"), "w"))
    nat = lambda: [m for m in driver.execute_script(f"return {element}.members") if m["name"] == "Nat"]
    # Before the tilt: Nat's face drawn upright (once its photo is in and a face came).
    face = lambda: nat()[0].get("face") if nat() else None
    end = time.time() + 60
    while time.time() < end and not (face() and abs(face()["pose"][2]) <= 3):
        time.sleep(0.2)
    checks.check(bool(face()) and abs(face()["pose"][2]) <= 3, f"the page draws Nat's face upright before the tilt (its element says {face()})")
    driver.save_screenshot(os.path.join(OUT, "ada-upright.png"))
    tilt_camera()
    # The tilt: the page's element says the face is drawn rolled (the server read it), then the
    # picture shows it, 0.5 s on (the tween takes 0.1 s).
    end = time.time() + 20
    rolled = lambda: face() and abs(face()["pose"][2] - ROLL) <= 3
    while time.time() < end and not rolled():
        time.sleep(0.2)
    checks.check(bool(rolled()), f"the page draws Nat's face rolled {ROLL} +- 3 degrees (its element says {face()})")
    time.sleep(0.5)
    driver.save_screenshot(os.path.join(OUT, "ada-tilted.png"))
finally:
    if driver:
        driver.quit()
    if native:
        native.terminate()  # it would show the camera for 90 s: its frame log holds every frame drawn so far
        native.wait(timeout=120)
    server.stop()

for name, want in (("ada-upright.png", 0), ("ada-tilted.png", ROLL)):
    pose = pose_in(os.path.join(OUT, name))
    checks.check(pose is not None and abs(pose["roll"] - want) <= 3,
                 f"in the browser's picture ({name}) Nat's face is read rolled {want} +- 3 degrees: {pose}")
# The native member's own tile, from its frame log: the last frame before the tilt reached it and
# a frame 0.5 s after its face was drawn rolled.
log = [json.loads(line) for line in open(os.path.join(OUT, "nat.jsonl"))]
face_of = lambda line: next((m.get("face") for m in line.get("members", []) if m["name"] == "Nat"), None)
upright_frames = [line["frame"] for line in log if face_of(line) and abs(face_of(line)["pose"][2]) <= 1]
rolled_frames = [line["frame"] for line in log if face_of(line) and abs(face_of(line)["pose"][2] - ROLL) <= 3]
checks.check(bool(upright_frames) and bool(rolled_frames),
             f"the native frame log draws Nat's face upright ({len(upright_frames)} frames), then rolled {ROLL} +- 3 ({len(rolled_frames)} frames)")
for frames, want in ((upright_frames, 0), (rolled_frames, ROLL)):
    if not frames:
        continue
    frame = frames[-1] if want == 0 else min(frames[0] + 8, frames[-1])
    picture = os.path.join(OUT, f"nat-{frame:04d}.png")
    pose = pose_in(picture) if os.path.exists(picture) else None
    checks.check(pose is not None and abs(pose["roll"] - want) <= 3,
                 f"in the native client's picture (frame {frame}) Nat's face is read rolled {want} +- 3 degrees: {pose}")
checks.finish()
