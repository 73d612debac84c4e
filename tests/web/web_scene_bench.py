#!/usr/bin/env python3
"""The scene benchmark's browser half (`inkwire-bench --suite web-scene` runs it; SPEC W5-W7): in
headless Chromium (SwiftShader) on loopback, /scene/bench at 620x500: bytes and milliseconds to
the first frame (module and model), the module's compressed size, then per style the frames per
second while the camera turns a degree a frame (a drag), and the picture against the native
headless client's of the same session (PSNR). The native renderers' speed is measured by the C++
suite in the same run.
  web_scene_bench.py BIN_DIR OUT_DIR JSON_OUT STYLE..."""
import base64
import json
import os
import shutil
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(__file__))
from browser_support import Server, chromium, psnr, read_image, skip  # skips without the browser

BIN, OUT, JSON_OUT, STYLES = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4:]
MESH = os.path.join(BIN, "..", "packaged-data", "data", "meshes", "cow.off")
if not os.path.exists(MESH):
    skip(f"{MESH} is missing (libcgal-demo)")
WIDTH, HEIGHT, FRAMES = 620, 500, 60
os.makedirs(OUT, exist_ok=True)
data = os.path.join(OUT, "data")
shutil.rmtree(data, ignore_errors=True)
server = Server(BIN, OUT, data, {"sessions": [{"name": "bench", "kind": "scene", "style": "default", "assets": [{"path": MESH}]}],
                                 "http": "127.0.0.1:0"})
element = "document.querySelector('inkwire-scene')"
driver = chromium(OUT, WIDTH + 40, HEIGHT + 200)
driver.set_script_timeout(600)  # painterly in SwiftShader takes a while for 60 frames
rows = []
try:
    driver.get(f"http://127.0.0.1:{server.http}/scene/bench")
    start = time.time()
    while time.time() - start < 90 and not driver.execute_script(f"return {element}?.hasAttribute('loaded')"):
        time.sleep(0.05)
    ms, first_bytes, module_bytes = driver.execute_script(f"const e = {element}; return [e.msFirstFrame, e.bytesFirstFrame, e.moduleBytes]")
    renderer = driver.execute_script("const g = document.createElement('canvas').getContext('webgl2');"
                                     "const x = g.getExtension('WEBGL_debug_renderer_info'); return x ? g.getParameter(x.UNMASKED_RENDERER_WEBGL) : '';")
    driver.execute_script(f"document.body.style.margin = '0'; {element}.style.cssText = 'width:{WIDTH}px;height:{HEIGHT}px;flex:none';"
                          f"{element}.shadowRoot.querySelector('details').style.display = 'none'")
    for style in STYLES:
        subprocess.run([f"{BIN}/inkwire-client", "--connect", f"127.0.0.1:{server.tcp}", "--session", "bench", "--headless", "--frames", "1",
                        "--size", f"{WIDTH}x{HEIGHT}", "--view", "30,20,1.4", "--style", style, "--out", os.path.join(OUT, "native.png"),
                        "--cache", os.path.join(OUT, "cache")], check=True, stderr=subprocess.DEVNULL)
        time.sleep(0.5)
        png = driver.execute_script(f"const e = {element}; e.draw(0); return e.canvas.toDataURL('image/png')")
        with open(os.path.join(OUT, "browser.png"), "wb") as f:
            f.write(base64.b64decode(png.split(",", 1)[1]))
        db = psnr(read_image(os.path.join(OUT, "browser.png"), OUT), read_image(os.path.join(OUT, "native.png"), OUT))
        # A drag: the camera turns a degree a frame; one pixel read at the end waits for the GPU.
        fps = driver.execute_script(f"""const e = {element}, g = e.canvas.getContext('webgl2'), pixel = new Uint8Array(4);
          for (let i = 0; i < 5; ++i) e.draw(i / 60);
          g.readPixels(0, 0, 1, 1, g.RGBA, g.UNSIGNED_BYTE, pixel);
          const start = performance.now();
          for (let i = 0; i < {FRAMES}; ++i) {{ e.camera = {{azimuth: 30 + i}}; e.draw(i / 60); }}
          g.readPixels(0, 0, 1, 1, g.RGBA, g.UNSIGNED_BYTE, pixel);
          return {FRAMES} * 1000 / (performance.now() - start);""")
        rows.append({"style": style, "fps": fps, "psnr_vs_native": db})
        print(f"{style}: {fps:.1f} fps in the browser, {db:.2f} dB against the native client", flush=True)
finally:
    driver.quit()
    server.stop()
with open(JSON_OUT, "w") as f:
    json.dump({"browser_gl_renderer": renderer, "ms_first_frame": ms, "bytes_first_frame": first_bytes, "module_bytes_compressed": module_bytes,
               "rows": rows}, f)
