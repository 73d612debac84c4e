#!/usr/bin/env python3
"""The demo's web part: a customer's browser (Debian's headless chromium through selenium) on a
running server's pages. Writes OUT/index.png (the session index), OUT/product-page.png (a
product's page with its snippet opened), OUT/turntable-drag.mp4 (the element's canvas while a
pointer drags it round and lets go), OUT/conference-page.png and OUT/conference.mp4 (a
conference's page while its speaker talks: the face rebuilt from expression codes) and
OUT/web.json (the browser's GL renderer, bytes sent during the drag).
  web_demo.py HTTP_PORT SESSION CONFERENCE OUT"""
import base64
import json
import os
import shutil
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from headless_chromium import chromium  # noqa: E402
from selenium.webdriver.common.action_chains import ActionChains

port, session, conference, out = sys.argv[1:5]
os.makedirs(out, exist_ok=True)
driver = chromium(os.path.join(out, 'profile'), 720, 820)
try:
    driver.get(f"http://127.0.0.1:{port}/")
    driver.save_screenshot(os.path.join(out, "index.png"))
    driver.get(f"http://127.0.0.1:{port}/turntable/{session}")
    element = "document.querySelector('inkwire-turntable')"
    start = time.time()
    while time.time() - start < 60 and not driver.execute_script(f"return {element}.hasAttribute('loaded')"):
        time.sleep(0.1)
    driver.execute_script("document.querySelector('details').open = true")
    time.sleep(1.0)  # a second of the auto-spin
    driver.save_screenshot(os.path.join(out, "product-page.png"))
    frames = os.path.join(out, "frames")
    os.makedirs(frames, exist_ok=True)
    # What the page moved over the network: the product's files (a plain fetch, no session) and a
    # session's messages when it presents or follows one.
    traffic = (f"const e = {element}, s = e.session; "
               "return (e.product?.bytesReceived ?? 0) + (s ? s.bytesSent + s.bytesReceived : 0)")
    sent = driver.execute_script(traffic)
    canvas = driver.execute_script(f"return {element}.canvas")

    def capture(i):
        png = driver.execute_script(f"const e = {element}; e.draw(); return e.canvas.toDataURL('image/png')")
        with open(os.path.join(frames, f"{i:04d}.png"), "wb") as f:
            f.write(base64.b64decode(png.split(",", 1)[1]))

    # The pointer goes down, drags a third of a turn in 40 steps, lets go; then the inertia.
    ActionChains(driver).move_to_element(canvas).click_and_hold().perform()
    for i in range(40):
        ActionChains(driver).move_by_offset(-8, 0).perform()
        capture(i)
    ActionChains(driver).release().perform()
    for i in range(40, 70):
        capture(i)
        time.sleep(1 / 30)
    after = driver.execute_script(traffic)
    subprocess.run(["ffmpeg", "-loglevel", "error", "-y", "-framerate", "30", "-i", os.path.join(frames, "%04d.png"), "-pix_fmt", "yuv420p",
                    "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", os.path.join(out, "turntable-drag.mp4")], check=True)
    # The conference: its page while the speaker talks, two seconds of the face at 15 fps.
    driver.get(f"http://127.0.0.1:{port}/conference/{conference}")
    face = "document.querySelector('inkwire-conference')"
    start = time.time()
    while time.time() - start < 30 and not driver.execute_script(f"return {face}.hasAttribute('loaded')"):
        time.sleep(0.1)
    faces = os.path.join(out, "face-frames")
    os.makedirs(faces, exist_ok=True)
    for i in range(45):
        png = driver.execute_script(f"const e = {face}; e.draw(); return e.canvas.toDataURL('image/png')")
        with open(os.path.join(faces, f"{i:04d}.png"), "wb") as f:
            f.write(base64.b64decode(png.split(",", 1)[1]))
        time.sleep(1 / 15)
    driver.save_screenshot(os.path.join(out, "conference-page.png"))
    subprocess.run(["ffmpeg", "-loglevel", "error", "-y", "-framerate", "15", "-i", os.path.join(faces, "%04d.png"), "-pix_fmt", "yuv420p",
                    "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", os.path.join(out, "conference.mp4")], check=True)
    renderer = driver.execute_script("""const gl = document.createElement('canvas').getContext('webgl2');
      const i = gl.getExtension('WEBGL_debug_renderer_info'); return i ? gl.getParameter(i.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER);""")
    with open(os.path.join(out, "web.json"), "w") as f:
        json.dump({"browser_gl_renderer": renderer, "bytes_during_drag": after - sent}, f, indent=1)
finally:
    driver.quit()
    # Only the pictures, the videos and the figures stay.
    for scratch in ("profile", "frames", "face-frames"):
        shutil.rmtree(os.path.join(out, scratch), ignore_errors=True)
