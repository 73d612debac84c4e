#!/usr/bin/env python3
"""The web benchmark (`inkwire-bench --suite web` runs it; SPEC W2): in headless Chromium on
loopback, a product (the packaged truck rendered into 24 photos at 512x512, as add-product makes
it) in <inkwire-turntable>, against a plain 72-photo spin page made from the same truck (the
nearest photo per angle, as a shop's spin viewer shows it): bytes and milliseconds to the first
view and to the whole product, frames per second while dragging at 512x512 and 1024x1024, and
mean PSNR over 36 true views (10 degrees apart, between both viewers' photos, rendered by
inkwire-render). The 1024x1024 row is a second visit: its photos come from the browser's cache.
The `zoomed-turn` rows: the truck photographed at 1024 pixels, zoomed in and turned: how many
frames show a photo before its finer level is there, fetching ahead of the turn and not. The
`static` row: the same truck exported as static files (export-product) and served by nginx with
deploy/nginx/, the page on another origin: first view, whole product, a repeat visit's bytes (as
resource timing counts them on the wire) and frames per second while dragging.
  web_bench.py BIN_DIR OUT_DIR JSON_OUT"""
import base64
import functools
import http.server
import json
import os
import shutil
import subprocess
import sys
import threading

sys.path.insert(0, os.path.dirname(__file__))
from browser_support import PROTOCOL_VERSION, Nginx, Server, chromium, psnr, read_image, skip, steady, wait_until  # skips without the browser

BIN, OUT, JSON_OUT = sys.argv[1], sys.argv[2], sys.argv[3]
TRUCK = "/usr/share/assimp/models/glTF/CesiumMilkTruck/CesiumMilkTruck.gltf"
if not os.path.exists(TRUCK):
    skip(f"{TRUCK} is missing (assimp-testmodels)")
os.makedirs(OUT, exist_ok=True)
data = os.path.join(OUT, "data")
shutil.rmtree(data, ignore_errors=True)
subprocess.run([f"{BIN}/inkwire-server", "add-product", "truck", "--mesh", TRUCK, "--samples", "24", "--size", "512", "--data", data],
               check=True, stdout=subprocess.DEVNULL)
# The truck photographed at 1024 pixels (24 photos), put on the server as a shop does: shown first
# at 512, with a zoom level at 1024 (SPEC T18).
zoom_photos = os.path.join(OUT, "zoom-photos")
shutil.rmtree(zoom_photos, ignore_errors=True)
os.makedirs(zoom_photos)
subprocess.run([f"{BIN}/inkwire-render", "--mesh", TRUCK, "--view", "0,0,1.4", "--frames", "24", "--size", "1024x1024", "--backdrop", "#ffffff",
                "--out", os.path.join(zoom_photos, "IMG_%04d.png")], check=True, stderr=subprocess.DEVNULL)
subprocess.run([f"{BIN}/inkwire-server", "add-product", "truck-zoom", "--photos", zoom_photos, "--step", "-15", "--data", data],
               check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)

# The spin page: 72 photos of the truck over white, JPEG quality 90 as the product's photos.
spin = os.path.join(OUT, "spin")
shutil.rmtree(spin, ignore_errors=True)
os.makedirs(spin)
subprocess.run([f"{BIN}/inkwire-render", "--mesh", TRUCK, "--style", "default", "--view", "0,0,1.4", "--frames", "72", "--size", "512x512",
                "--backdrop", "#ffffff", "--out", os.path.join(spin, "raw-%04d.png")], check=True, stderr=subprocess.DEVNULL)
for i in range(72):
    raw = os.path.join(spin, f"raw-{i:04d}.png")
    subprocess.run(["oiiotool", raw, "--ch", "R,G,B", "--attrib", "Compression", "jpeg:90", "-o", os.path.join(spin, f"{i:02d}.jpg")], check=True)
    os.remove(raw)
with open(os.path.join(spin, "index.html"), "w") as f:
    f.write("""<!doctype html><meta charset=utf-8><style>body{margin:0} img{width:512px;height:512px;display:block}</style>
<img id=view alt="the product" draggable=false>
<script>
// A plain spin viewer: 72 photos, the nearest one shown; each photo fetched when first needed,
// the first one at once (the object turns the other way round from the camera: photo i looks
// from -5 i degrees).
const img = document.getElementById('view'), started = performance.now();
let azimuth = 0;
window.firstViewMs = null;
img.addEventListener('load', () => { if (window.firstViewMs === null) window.firstViewMs = performance.now() - started; }, { once: true });
window.show = (degrees) => {
  azimuth = degrees;
  const i = ((Math.round(-degrees / 5) % 72) + 72) % 72;
  img.src = String(i).padStart(2, '0') + '.jpg';
};
show(0);
</script>""")


class Quiet(http.server.SimpleHTTPRequestHandler):
    def log_message(self, *args):
        pass


httpd = http.server.ThreadingHTTPServer(("127.0.0.1", 0), functools.partial(Quiet, directory=spin))
threading.Thread(target=httpd.serve_forever, daemon=True).start()

# The truth at 36 views 10 degrees apart, none of them where a photo of either viewer was taken
# (the product's every 15 degrees, the spin page's every 5): a customer's view falls anywhere.
truth = {}
for a in [10 * k + 3.5 for k in range(36)]:
    path = os.path.join(OUT, f"truth-{a}.png")
    subprocess.run([f"{BIN}/inkwire-render", "--mesh", TRUCK, "--view", f"{a},0,1.4", "--size", "512x512", "--backdrop", "#ffffff",
                    "--out", path], check=True, stderr=subprocess.DEVNULL)
    truth[a] = read_image(path, OUT)

server = Server(BIN, OUT, data, {"sessions": [], "http": "127.0.0.1:0"})
# The truck as static files on nginx (SPEC T20-T23).
www = os.path.join(OUT, "www")
shutil.rmtree(www, ignore_errors=True)
subprocess.run([f"{BIN}/inkwire-server", "export-product", "truck", os.path.join(www, "truck"), "--data", data], check=True, stdout=subprocess.DEVNULL)
nginx = Nginx(www, os.path.join(OUT, "nginx"))
driver = chromium(OUT, 1100, 1100)


def drag_fps(element):
    """While dragging: the azimuth changes every animation frame, as a pointer moves it, and the
    element redraws as it does for a pointer (once per frame at most); frames drawn per second,
    the median of five 2-second runs (this machine is shared and noisy)."""
    return sorted(driver.execute_async_script(f"""const done = arguments[0], e = {element};
      const draw = e.draw; let draws = 0; e.draw = function () {{ ++draws; return draw.call(this); }};
      const t0 = performance.now();
      const step = () => {{ e.azimuth = e.azimuth - 1.3;
        if (performance.now() - t0 < 2000) requestAnimationFrame(step);
        else {{ e.draw = draw; done(draws * 1000 / (performance.now() - t0)); }} }};
      requestAnimationFrame(step);""") for _ in range(5))[2]


def wait_loaded(element):
    wait_until(lambda: driver.execute_script(f"return {element}.hasAttribute('loaded')"), 60, poll=0.05)


def first_view_on_wire(product):
    """The bytes of the product's files at `product` (a URL prefix) on the wire (compressed where
    the host compresses) before the element's first view, and the files by name."""
    return driver.execute_script(f"""const e = document.querySelector('inkwire-turntable'), due = e.startedAt + e.firstViewMs;
      const files = performance.getEntriesByType('resource').filter((r) => r.name.startsWith('{product}')
        && (r.name.includes('/files/') || r.name.split('?')[0].endsWith('product.json')) && r.responseEnd <= due);
      return [files.reduce((s, r) => s + r.transferSize, 0), files.map((r) => r.name.split('/').pop() + ' ' + r.transferSize)];""")


rows, renderer = [], ""
try:
    driver.get(f"http://127.0.0.1:{server.http}/")
    renderer = driver.execute_script("""const gl = document.createElement('canvas').getContext('webgl2');
      const i = gl.getExtension('WEBGL_debug_renderer_info'); return i ? gl.getParameter(i.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER);""")
    element = "document.querySelector('inkwire-turntable')"
    psnr_mean = None
    for size in (512, 1024):
        driver.execute_script(f"""document.body.style.margin = '0'; performance.clearResourceTimings(); performance.setResourceTimingBufferSize(100000);
          document.body.innerHTML = '<inkwire-turntable session="truck" auto-rotate="off" style="width:{size}px;height:{size}px"></inkwire-turntable>';
          import('/inkwire.js');""")
        wait_until(lambda: driver.execute_script(f"return {element}.hasAttribute('loaded')"), 60, poll=0.05)
        first_bytes, first_ms, total = driver.execute_script(f"const e = {element}; return [e.firstViewBytes, e.firstViewMs, e.product.bytesReceived];")
        first_wire, first_files = first_view_on_wire(f"http://127.0.0.1:{server.http}/products/truck/")
        fps = drag_fps(element)
        if size == 512:  # quality: the element's views against the truth
            scores = []
            for a, t in truth.items():
                png = driver.execute_script(f"const e = {element}; e.azimuth = {a}; e.draw(); return e.canvas.toDataURL('image/png')")
                path = os.path.join(OUT, f"element-{a}.png")
                with open(path, "wb") as f:
                    f.write(base64.b64decode(png.split(",", 1)[1]))
                scores.append(psnr(read_image(path, OUT), t))
            psnr_mean = sum(scores) / len(scores)
        rows.append({"variant": f"element,size={size}", "counters": {"fps": fps, "bytes_first_view": first_bytes, "bytes_first_view_wire": first_wire,
                                                                     "ms_first_view": first_ms,
                                                                     "bytes_total": total, **({"psnr_mean": psnr_mean} if size == 512 else {})}})
        print(f"web: element {size}: {fps:.1f} fps while dragging, first view {first_bytes} bytes ({first_wire} on the wire: {first_files}) "
              f"in {first_ms:.0f} ms, {total} bytes in all",
              file=sys.stderr)

    # The static product, page on the server's origin, product on nginx's: a first visit, then a
    # second (the page again), whose bytes are what resource timing says went over the wire.
    static = f"http://127.0.0.1:{nginx.port}/truck"
    on_wire = f"""return performance.getEntriesByType('resource').filter((r) => r.name.startsWith('{static}'))
      .reduce((s, r) => s + r.transferSize, 0)"""
    visits = []
    for visit in (1, 2):
        driver.get(f"http://127.0.0.1:{server.http}/")
        if visit == 1:  # the element rows above left the same photos, by hash, in Cache Storage
            driver.execute_async_script("const done = arguments[0]; caches.keys().then((k) => Promise.all(k.map((n) => caches.delete(n)))).then(done);")
        driver.execute_script(f"""document.body.style.margin = '0'; performance.setResourceTimingBufferSize(100000);
          document.body.innerHTML = '<inkwire-turntable src="{static}/product.json" auto-rotate="off" style="width:512px;height:512px"></inkwire-turntable>';
          import('{static}/inkwire.js');""")
        wait_loaded(element)
        visits.append(driver.execute_script(f"const e = {element}; return [e.firstViewBytes, e.firstViewMs, e.product.bytesReceived, e.websocketsOpened ?? 0]")
                      + [driver.execute_script(on_wire)])
        if visit == 1:  # the product's files on the wire (compressed where nginx compresses) before the first view
            first_wire, first_files = first_view_on_wire(static)
    (first_bytes, first_ms, total, sockets, _), (_, repeat_ms, _, _, repeat_wire) = visits
    fps = drag_fps(element)
    rows.append({"variant": "static,size=512", "counters": {"fps": fps, "bytes_first_view": first_bytes, "bytes_first_view_wire": first_wire,
                                                             "ms_first_view": first_ms, "bytes_total": total,
                                                             "bytes_repeat_visit": repeat_wire, "ms_first_view_repeat": repeat_ms,
                                                             "websockets_opened": sockets}})
    print(f"web: static on nginx: {fps:.1f} fps while dragging, first view {first_bytes} bytes ({first_wire} on the wire: {first_files}) "
          f"in {first_ms:.0f} ms, {total} bytes in all, "
          f"a repeat visit {repeat_wire} bytes on the wire ({repeat_ms:.0f} ms to its first view), {sockets} WebSockets", file=sys.stderr)

    # Zoomed in and turning (SPEC T18): a 256-pixel element zoomed in four times shows the photos
    # at 1024 pixels, their finer level. Turned 75 degrees at 30 degrees a second once its fetching
    # has settled: how many frames are drawn from a first-level photo (a photo sharpening as its
    # finer level arrives), with the element as shipped (the finer level of the photos nearest the
    # view fetched ahead of a turn) and, in the same run, with fetching held to the photos the view
    # is drawn from, as it was before.
    for fetch in ("drawn-from", "ahead"):
        # Each from the network: the photos the other fetched are not in the page's cache.
        driver.execute_async_script("const done = arguments[0]; caches.keys().then((k) => Promise.all(k.map((n) => caches.delete(n)))).then(done);")
        driver.execute_script("""document.body.innerHTML =
          '<inkwire-turntable session="truck-zoom" auto-rotate="off" style="width:256px;height:256px"></inkwire-turntable>';""")
        wait_until(lambda: driver.execute_script(f"return {element}.hasAttribute('loaded')"), 60, poll=0.05)
        if fetch == "drawn-from":
            driver.execute_script(f"""const e = {element}, ahead = e.nextFetch;
              e.nextFetch = function () {{ const n = ahead.call(this);
                return n && n.level > 0 && !this.view.viewSamples(this.direction()).includes(n.sample) ? null : n; }};""")
        received = driver.execute_script(f"return {element}.product.bytesReceived")
        driver.execute_script(f"{element}.setZoom(4)")
        wait_until(lambda: driver.execute_script(f"return {element}.view.finerInView") >= 2, 30, poll=0.1)
        steady(lambda: driver.execute_script(f"return {element}.product.bytesReceived"), still=1.0)  # the photos ahead, where fetched
        finer_bytes = driver.execute_script(f"return {element}.product.bytesReceived") - received
        held = driver.execute_script(f"return {element}.view.finer.size")
        frames = driver.execute_async_script(f"""const done = arguments[0], e = {element}, out = [], t0 = performance.now();
          const step = () => {{ const t = (performance.now() - t0) / 1000; e.azimuth = -Math.min(75, 30 * t); e.draw();
            out.push(e.view.finerInView < e.view.viewSamples(e.direction()).length);
            if (t < 2.5) requestAnimationFrame(step); else done(out); }};
          requestAnimationFrame(step);""")
        coarse = sum(1 for c in frames if c)
        rows.append({"variant": f"zoomed-turn,fetch={fetch}", "counters": {"frames": len(frames), "frames_coarse": coarse,
                                                                          "coarse_fraction": coarse / len(frames),
                                                                          "finer_held_before_turn": held, "bytes_finer_before_turn": finer_bytes}})
        print(f"web: zoomed in 4 times, fetching {fetch}: {coarse} of {len(frames)} frames of a 75-degree turn drawn from a "
              f"first-level photo; {held} finer photos held before it, {finer_bytes} bytes", file=sys.stderr)

    # What drawing the turntable with the C++ warp compiled to WebAssembly (the scene module, which
    # holds it) would add before a first view: the module's bytes and the time to fetch, compile
    # and instantiate it, uncached, on this page (issue: one implementation of each algorithm).
    driver.execute_cdp_cmd("Network.enable", {})
    driver.execute_cdp_cmd("Network.setCacheDisabled", {"cacheDisabled": True})
    driver.get(f"http://127.0.0.1:{server.http}/")
    module_ms, module_bytes = driver.execute_async_script("""const done = arguments[0], t0 = performance.now();
      import('/module/inkwire-scene.js').then((m) => m.default()).then(() => done([performance.now() - t0,
        performance.getEntriesByType('resource').filter((r) => r.name.includes('/module/')).reduce((s, r) => s + r.transferSize, 0)]),
        (e) => done([null, String(e)]));""")
    driver.execute_cdp_cmd("Network.setCacheDisabled", {"cacheDisabled": False})
    if module_ms is not None:
        rows.append({"variant": "module,uncached", "counters": {"bytes_first_view": module_bytes, "ms_first_view": module_ms}})
        print(f"web: the WebAssembly module alone: {module_bytes} bytes, {module_ms:.0f} ms to instantiate", file=sys.stderr)
    else:
        print(f"web: the WebAssembly module did not load: {module_bytes}", file=sys.stderr)

    # The spin page: what the browser downloads, per its resource timing (encoded body sizes).
    driver.get(f"http://127.0.0.1:{httpd.server_address[1]}/index.html")
    wait_until(lambda: driver.execute_script("return window.firstViewMs") is not None, 30, poll=0.05)
    first_ms = driver.execute_script("return window.firstViewMs")
    first_bytes = driver.execute_script("return performance.getEntriesByType('resource').concat(performance.getEntriesByType('navigation')).reduce((s, r) => s + r.transferSize, 0)")
    fps = sorted(driver.execute_async_script("""const done = arguments[0]; let frames = 0, a = 0; const t0 = performance.now();
      const step = () => { a -= 1.3; show(a); ++frames;
        if (performance.now() - t0 < 2000) requestAnimationFrame(step); else done(frames * 1000 / (performance.now() - t0)); };
      requestAnimationFrame(step);""") for _ in range(5))[2]
    scores = []
    for a, t in truth.items():
        i = round(-a / 5) % 72  # the spin viewer's nearest photo: photo i looks from -5 i degrees
        scores.append(psnr(read_image(os.path.join(spin, f"{i:02d}.jpg"), OUT), t))
    total = sum(os.path.getsize(os.path.join(spin, f"{i:02d}.jpg")) for i in range(72)) + os.path.getsize(os.path.join(spin, "index.html"))
    rows.append({"variant": "spin,n=72", "counters": {"fps": fps, "bytes_first_view": first_bytes, "ms_first_view": first_ms, "bytes_total": total,
                                                      "psnr_mean": sum(scores) / len(scores)}})
    print(f"web: spin page: {fps:.1f} fps while dragging, first view {first_bytes} bytes in {first_ms:.0f} ms, {total} bytes in all", file=sys.stderr)

    # The load rows: 1000 first views at once-ish (32 at a time) from nginx, from the server's
    # /products/ and over the server's WebSocket as the element read products before
    # (first_view_load.py), the browser closed first so the serving processes have the CPU.
    driver.quit()
    driver = None
    from first_view_load import static_visit, visit_all, websocket_visit
    manifest = json.load(open(os.path.join(www, "truck", "product.json")))
    first = [manifest["photos"][0], manifest["mattes"][0]]
    nginx_pids = [nginx.process.pid] + [int(p) for p in open(f"/proc/{nginx.process.pid}/task/{nginx.process.pid}/children").read().split()]
    visits = {  # via: the row names docs/cli.md fixes; inkwire-server is the WebSocket path the ratio is against
        "nginx": (lambda: static_visit(nginx.port, "/truck", [f["file"] for f in first]), nginx_pids),
        "inkwire-server": (lambda: websocket_visit(server.http, "truck", [(f["sha256"], f["size"]) for f in first], PROTOCOL_VERSION),
                           [server.process.pid]),
        "inkwire-server-products": (lambda: static_visit(server.http, "/products/truck", [f["file"] for f in first]), [server.process.pid]),
    }
    for host, (visit, pids) in visits.items():
        load = visit_all(visit, 1000, 32, pids)
        rows.append({"variant": f"load,via={host}", "counters": {k: v for k, v in load.items() if isinstance(v, (int, float)) and v is not None}})
        print(f"web: 1000 first views via {host}: {load['visitors_per_second']:.0f} a second ({load['requests_per_second']:.0f} requests), "
              f"p50 {load['p50_ms']:.1f} ms, p99 {load['p99_ms']:.1f} ms, {load['cpu_ms_per_visitor']:.2f} CPU ms a visitor "
              f"({load['bytes_per_visitor']:.0f} bytes), {load['failed']} failed {load['first_failure']}", file=sys.stderr)
finally:
    if driver:
        driver.quit()
    server.stop()
    nginx.stop()
    httpd.shutdown()
with open(JSON_OUT, "w") as f:
    json.dump({"browser_gl_renderer": renderer, "rows": rows}, f, indent=1)
