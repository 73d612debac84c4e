#!/usr/bin/env python3
"""The demo's scene in a browser: /scene/NAME in Debian's headless chromium (selenium) while
native clients change the session's style in turn (comic-extended, sketch-pencil, hatching,
painterly) and the page's visitor drags the model round. Writes OUT/scene-page.png (the page with
its style panel open) and OUT/scene.mp4 (the element's canvas throughout).
  web_scene_demo.py HTTP_PORT TCP_PORT SCENE BIN_DIR OUT"""
import base64
import os
import shutil
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from headless_chromium import chromium  # noqa: E402

port, tcp, scene, bin_dir, out = sys.argv[1:6]
os.makedirs(out, exist_ok=True)
driver = chromium(os.path.join(out, 'scene-profile'), 720, 620)
element = "document.querySelector('inkwire-scene')"
frames = os.path.join(out, "scene-frames")
os.makedirs(frames, exist_ok=True)
count = 0


def capture(steps, turn=0.0):
    """`steps` frames at 24 a second, the visitor's drag turning the camera `turn` degrees a frame."""
    global count
    for _ in range(steps):
        png = driver.execute_script(f"""const e = {element};
          if ({turn}) e.camera = {{azimuth: e.camera.azimuth + {turn}}};
          e.draw(); return e.canvas.toDataURL('image/png')""")
        with open(os.path.join(frames, f"{count:04d}.png"), "wb") as f:
            f.write(base64.b64decode(png.split(",", 1)[1]))
        count += 1
        time.sleep(1 / 24)


try:
    driver.get(f"http://127.0.0.1:{port}/scene/{scene}")
    start = time.time()
    while time.time() - start < 90 and not driver.execute_script(f"return {element}?.hasAttribute('loaded')"):
        time.sleep(0.1)
    if not driver.execute_script(f"return {element}?.hasAttribute('loaded')"):
        raise SystemExit("the scene page did not load: " + str(driver.execute_script(f"return {element}?.shadowRoot.querySelector('.message').textContent")))
    driver.execute_script(f"{element}.style.cssText = 'width:640px;height:480px;flex:none'")
    driver.execute_script(f"{element}.shadowRoot.querySelector('details').open = true")
    time.sleep(0.5)
    driver.save_screenshot(os.path.join(out, "scene-page.png"))
    driver.execute_script(f"{element}.shadowRoot.querySelector('details').open = false")
    for style in ("comic-extended", "sketch-pencil", "hatching", "painterly"):
        # A native client in the session changes the style for everyone; the page follows.
        subprocess.run([f"{bin_dir}/inkwire-client", "--connect", f"127.0.0.1:{tcp}", "--session", scene, "--headless", "--frames", "1",
                        "--size", "64x48", "--style", style, "--out", os.path.join(out, "scene-native.png"),
                        "--cache", os.path.join(out, "scene-cache")], check=True, stderr=subprocess.DEVNULL)
        capture(24)
        capture(36, turn=2.0)
    subprocess.run(["ffmpeg", "-loglevel", "error", "-y", "-framerate", "24", "-i", os.path.join(frames, "%04d.png"), "-pix_fmt", "yuv420p",
                    "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", os.path.join(out, "scene.mp4")], check=True)
finally:
    driver.quit()
    for scratch in ("scene-profile", "scene-frames", "scene-cache", "scene-native.png"):
        path = os.path.join(out, scratch)
        shutil.rmtree(path, ignore_errors=True) if os.path.isdir(path) else (os.path.exists(path) and os.remove(path))
