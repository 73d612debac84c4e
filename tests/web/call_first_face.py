#!/usr/bin/env python3
"""A person joining a call from a link in Chromium (SPEC F16): how long after pressing Join the
first face is drawn, and what the page fetched, for the `join` rows of `inkwire-bench --suite
call`. A native member (Yale subject 07, else one of libdlib's photos) is already publishing;
the browser member opens /call/call with a fake camera, waits `prejoin` seconds in the pre-join
(0: joins as soon as the preview shows, 2: reads the page for a moment) and joins. The element's
`joinedAt` and `firstFaceAt` (performance.now() of joining and of the first tile drawn with a
face) give the time; the page's Resource Timing gives its bytes on the wire (the WebSocket's
are not a page fetch). Then its connection is cut under it (as a lost network would) and the
time until the server has it in the call again is `rejoin_ms` (tests/web/call_browser_test.py
checks that it comes back, in one tile). Five runs per wait, the median reported.

  call_first_face.py BIN_DIR OUT_DIR --bench ROWS.json
Skips with a message without chromium, chromedriver, selenium or ffmpeg."""
import json
import os
import shutil
import statistics
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(__file__))
from browser_support import Server, chromium, face_clip, skip, wait_until  # skips without the browser

BIN, OUT = sys.argv[1], sys.argv[2]
BENCH = sys.argv[sys.argv.index("--bench") + 1] if "--bench" in sys.argv else None
RUNS, WAITS = 5, (0, 2)
YALE = os.path.join(os.path.dirname(__file__), "..", "..", "..", "shared", "data", "yalefaces")
DLIB = "/usr/share/doc/libdlib19.1/examples/faces"
if not shutil.which("ffmpeg"):
    skip("ffmpeg is missing (scripts/setup.sh installs it)")
shutil.rmtree(OUT, ignore_errors=True)
os.makedirs(OUT)


def photos(subject, dlib_photo):
    if os.path.exists(os.path.join(YALE, f"subject{subject}_normal.png")):
        return [os.path.abspath(os.path.join(YALE, f"subject{subject}_{label}.png")) for label in ("normal", "happy")]
    if os.path.exists(os.path.join(DLIB, dlib_photo)):
        return [os.path.join(DLIB, dlib_photo)] * 2
    skip(f"neither ../shared/data/yalefaces nor libdlib-dev's example photos ({DLIB}) are here")


def join_once(out, wait, browser_camera, native_camera):
    """One join: (ms from the page's start to joining, ms from joining to the first face, page bytes,
    page files, ms from a cut to the server's second join of the member)."""
    os.makedirs(out)
    server = Server(BIN, out, os.path.join(out, "data"), {"http": "127.0.0.1:0", "sessions": [{"name": "call", "kind": "conference"}]})
    native = subprocess.Popen([f"{BIN}/inkwire-client", "--connect", f"127.0.0.1:{server.tcp}", "--session", "call", "--name", "Nat",
                               "--camera", native_camera, "--headless", "--frames", "600", "--fps", "15", "--size", "320x240",
                               "--out", os.path.join(out, "nat.mp4"), "--cache", os.path.join(out, "cache")],
                              stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    driver = None
    element = "document.querySelector('inkwire-call')"
    try:
        # Nat is in the call, publishing, before the browser member comes.
        joins = lambda name: [e for e in server.events() if e.get("event") == "join" and e.get("name") == name]
        wait_until(lambda: joins("Nat"), 60)
        driver = chromium(out, 640, 520, ["--use-fake-ui-for-media-stream", "--use-fake-device-for-media-stream",
                                          f"--use-file-for-fake-video-capture={browser_camera}", "--autoplay-policy=no-user-gesture-required"])
        driver.get(f"http://127.0.0.1:{server.http}/call/call")
        wait_until(lambda: driver.execute_script(f"return {element}.preview.videoWidth > 0"), 60, poll=0.05)
        time.sleep(wait)  # the bench's own variable: a person reading the pre-join page for a moment
        driver.execute_script(f"const e = {element}; e.nameInput.value = 'Ada'; e.join();")
        wait_until(lambda: driver.execute_script(f"return {element}.firstFaceAt"), 30, poll=0.02)
        joined, first = driver.execute_script(f"const e = {element}; return [e.joinedAt, e.firstFaceAt]")
        fetched = driver.execute_script("return performance.getEntriesByType('navigation').concat(performance.getEntriesByType('resource'))"
                                        ".filter(e => !e.name.startsWith('ws')).map(e => e.transferSize)")
        if not first:
            raise SystemExit(f"no face was drawn within 30 s of joining (waited {wait} s in the pre-join)")
        driver.execute_script(f"{element}.link.worker.postMessage({{ op: 'cut' }})")
        cut = time.time()
        if not wait_until(lambda: len(joins("Ada")) >= 2, 60, poll=0.02):
            raise SystemExit("the cut member did not join again within 60 s")
        return joined, first - joined, sum(fetched), len(fetched), 1000 * (time.time() - cut)
    finally:
        if driver:
            driver.quit()
        native.terminate()
        native.wait()
        server.stop()


browser_camera = face_clip(OUT, "ada", *photos("02", "2008_001322.jpg"))[1]
native_camera = face_clip(OUT, "nat", *photos("07", "2009_004587.jpg"))[0]
rows = []
for wait in WAITS:
    runs = [join_once(os.path.join(OUT, f"wait{wait}-run{k}"), wait, browser_camera, native_camera) for k in range(RUNS)]
    after = [r[1] for r in runs]
    print(f"chromium, {wait} s in the pre-join: joined {statistics.median(r[0] for r in runs):.0f} ms after the page began; the first face "
          f"{', '.join(f'{a:.0f}' for a in after)} ms after joining; the page fetched {runs[0][2]} bytes in {runs[0][3]} files; "
          f"cut, it was back in {', '.join(f'{r[4]:.0f}' for r in runs)} ms")
    rows.append({"variant": f"join,engine=chromium,prejoin={wait}",
                 "counters": {"first_face_after_join_ms": statistics.median(after), "first_face_after_join_ms_max": max(after),
                              "joined_after_page_ms": statistics.median(r[0] for r in runs), "page_bytes": runs[0][2], "page_files": runs[0][3],
                              "rejoin_ms": statistics.median(r[4] for r in runs), "rejoin_ms_max": max(r[4] for r in runs)}})
if BENCH:
    with open(BENCH, "w") as f:
        json.dump({"rows": rows}, f)
