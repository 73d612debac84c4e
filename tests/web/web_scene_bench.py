#!/usr/bin/env python3
"""The scene benchmark's browser half (`inkwire-bench --suite web-scene` runs it; SPEC W5-W7): in
headless Chromium (SwiftShader) on loopback, /scene/bench at 620x500: bytes and milliseconds to
the first frame (module and model), the module's compressed size, then per style the frames per
second while the camera turns a degree a frame (a drag), the milliseconds a frame spends in the
page's own calls (script and module: the rest is the browser drawing), and the picture against the
native headless client's of the same session (PSNR). First, the platform's own figures: the
C++ suite's bare frames (BARE_JSON: their data and shaders, bare_frame.hpp), drawn by a page's
script with the same calls. The native speeds are measured by the C++ suite in the same run.
  web_scene_bench.py BIN_DIR OUT_DIR JSON_OUT BARE_JSON STYLE..."""
import base64
import json
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(__file__))
from browser_support import Server, chromium, psnr, read_image, skip, steady, wait_until  # skips without the browser

BIN, OUT, JSON_OUT, BARE_JSON, STYLES = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4], sys.argv[5:]
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


def timed_frames():
    """Script that times FRAMES calls of the page's `frame(i)` drawing into WebGL2 context `g`,
    three times after a warm-up, one pixel read after each run waiting for the browser to draw
    them all: `timed`, the median run's frames a second and milliseconds a frame spent in the
    page's own calls (script and module; the rest is the browser drawing)."""
    return f"""const pixel = new Uint8Array(4), runs = [];
      for (let i = 0; i < 5; ++i) frame(i);
      g.readPixels(0, 0, 1, 1, g.RGBA, g.UNSIGNED_BYTE, pixel);
      for (let run = 0; run < 3; ++run) {{
        let inCalls = 0; const start = performance.now();
        for (let i = 0; i < {FRAMES}; ++i) {{ const t = performance.now(); frame(i); inCalls += performance.now() - t; }}
        g.readPixels(0, 0, 1, 1, g.RGBA, g.UNSIGNED_BYTE, pixel);
        runs.push([{FRAMES} * 1000 / (performance.now() - start), inCalls / {FRAMES}]);
      }}
      const timed = runs.sort((a, b) => a[0] - b[0])[1];"""


driver = chromium(OUT, WIDTH + 40, HEIGHT + 200)
driver.set_script_timeout(600)  # painterly in SwiftShader takes a while for 3 x 60 frames
rows = []
try:
    driver.get(f"http://127.0.0.1:{server.http}/scene/bench")
    wait_until(lambda: driver.execute_script(f"return {element}?.hasAttribute('loaded')"), 90, poll=0.05)
    ms, first_bytes, module_bytes = driver.execute_script(f"const e = {element}; return [e.msFirstFrame, e.bytesFirstFrame, e.moduleBytes]")
    renderer = driver.execute_script("const g = document.createElement('canvas').getContext('webgl2');"
                                     "const x = g.getExtension('WEBGL_debug_renderer_info'); return x ? g.getParameter(x.UNMASKED_RENDERER_WEBGL) : '';")
    driver.execute_script(f"document.body.style.margin = '0'; {element}.style.cssText = 'width:{WIDTH}px;height:{HEIGHT}px;flex:none';"
                          f"{element}.shadowRoot.querySelector('details').style.display = 'none'")
    # The least GL a frame of each kind of work can be (bare_frame.hpp), in a canvas made as the
    # module makes its own: what the browser's WebGL2 costs before any of the module's work.
    with open(BARE_JSON) as f:
        bare_frames = json.load(f)
    for bare in bare_frames:
        fps, in_calls, covered = driver.execute_script(f"""const bare = arguments[0], c = document.createElement('canvas');
          c.width = {WIDTH}; c.height = {HEIGHT}; document.body.appendChild(c);
          const g = c.getContext('webgl2', {{alpha: false, depth: true, stencil: true, antialias: false, preserveDrawingBuffer: true}});
          const header = '#version 300 es\\nprecision highp float;\\n', program = g.createProgram();
          for (const [stage, source] of [[g.VERTEX_SHADER, bare.vertex], [g.FRAGMENT_SHADER, bare.fragment]]) {{
            const s = g.createShader(stage); g.shaderSource(s, header + source); g.compileShader(s); g.attachShader(program, s);
          }}
          g.linkProgram(program);
          const vertexArray = g.createVertexArray(), mesh = 'indices' in bare, at = (name) => g.getUniformLocation(program, name);
          g.bindVertexArray(vertexArray);
          g.bindBuffer(g.ARRAY_BUFFER, g.createBuffer());
          g.bufferData(g.ARRAY_BUFFER, new Float32Array(mesh ? bare.positions : bare.centres), g.STATIC_DRAW);
          g.enableVertexAttribArray(0);
          if (mesh) {{
            g.vertexAttribPointer(0, 3, g.FLOAT, false, 12, 0);
            g.bindBuffer(g.ELEMENT_ARRAY_BUFFER, g.createBuffer()); g.bufferData(g.ELEMENT_ARRAY_BUFFER, new Uint16Array(bare.indices), g.STATIC_DRAW);
          }} else {{
            g.vertexAttribPointer(0, 2, g.FLOAT, false, 8, 0); g.vertexAttribDivisor(0, 1);
          }}
          const frame = (i) => {{  // as bare_frame.cpp draws
            g.bindFramebuffer(g.FRAMEBUFFER, null); g.viewport(0, 0, {WIDTH}, {HEIGHT});
            g.clearColor(1, 1, 1, 1); g.clear(g.COLOR_BUFFER_BIT | g.DEPTH_BUFFER_BIT | g.STENCIL_BUFFER_BIT);
            g.useProgram(program); g.bindVertexArray(vertexArray);
            if (mesh) {{
              g.enable(g.DEPTH_TEST); g.enable(g.CULL_FACE); g.disable(g.BLEND);
              g.uniform2f(at('turn'), Math.cos(0.02 * i), Math.sin(0.02 * i));
              g.drawElements(g.TRIANGLES, bare.indices.length, g.UNSIGNED_SHORT, 0);
            }} else {{
              g.disable(g.DEPTH_TEST); g.disable(g.CULL_FACE); g.enable(g.BLEND); g.blendFunc(g.SRC_ALPHA, g.ONE_MINUS_SRC_ALPHA);
              g.uniform2f(at('viewport'), {WIDTH}, {HEIGHT}); g.uniform2f(at('shift'), i % 8, i % 8); g.uniform1f(at('half_size'), bare.half_size);
              g.drawArraysInstanced(g.TRIANGLE_STRIP, 0, 4, bare.centres.length / 2);
              g.disable(g.BLEND);
            }}
          }};
          {timed_frames()}
          const all = new Uint8Array({WIDTH} * {HEIGHT} * 4);
          g.readPixels(0, 0, {WIDTH}, {HEIGHT}, g.RGBA, g.UNSIGNED_BYTE, all);
          let covered = 0; for (let p = 0; p < all.length; p += 4) covered += all[p] !== 255;
          c.remove();
          return [...timed, covered / ({WIDTH} * {HEIGHT})];""", bare)
        rows.append({"style": bare["name"], "fps": fps, "ms_in_page_calls": in_calls, "covered_share": covered})
        print(f"{bare['name']}: {fps:.1f} fps in the browser ({in_calls:.2f} ms a frame in the page's calls), {covered:.3f} of the picture covered",
              flush=True)

    for style in STYLES:
        subprocess.run([f"{BIN}/inkwire-client", "--connect", f"127.0.0.1:{server.tcp}", "--session", "bench", "--headless", "--frames", "1",
                        "--size", f"{WIDTH}x{HEIGHT}", "--view", "30,20,1.4", "--style", style, "--out", os.path.join(OUT, "native.png"),
                        "--cache", os.path.join(OUT, "cache")], check=True, stderr=subprocess.DEVNULL)
        # The element follows the native client's style and camera.
        wait_until(lambda: driver.execute_script(f"return {element}.styleName === {json.dumps(style)}"), 60)
        steady(lambda: driver.execute_script(f"return JSON.stringify({element}.camera)"), still=0.3)
        png = driver.execute_script(f"const e = {element}; e.draw(0); return e.canvas.toDataURL('image/png')")
        with open(os.path.join(OUT, "browser.png"), "wb") as f:
            f.write(base64.b64decode(png.split(",", 1)[1]))
        db = psnr(read_image(os.path.join(OUT, "browser.png"), OUT), read_image(os.path.join(OUT, "native.png"), OUT))
        # A drag: the camera turns a degree a frame.
        fps, in_calls = driver.execute_script(f"""const e = {element}, g = e.canvas.getContext('webgl2');
          const frame = (i) => {{ e.camera = {{azimuth: 30 + i}}; e.draw(i / 60); }};
          {timed_frames()}
          return timed;""")
        rows.append({"style": style, "fps": fps, "ms_in_page_calls": in_calls, "psnr_vs_native": db})
        print(f"{style}: {fps:.1f} fps in the browser ({in_calls:.2f} ms a frame in the page's calls), {db:.2f} dB against the native client", flush=True)
finally:
    driver.quit()
    server.stop()
with open(JSON_OUT, "w") as f:
    json.dump({"browser_gl_renderer": renderer, "ms_first_frame": ms, "bytes_first_frame": first_bytes, "module_bytes_compressed": module_bytes,
               "rows": rows}, f)
