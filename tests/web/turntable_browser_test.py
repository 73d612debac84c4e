#!/usr/bin/env python3
"""<inkwire-turntable> in a real headless browser (SPEC W2, W4): Debian's chromium driven by
Debian's chromium-driver and python3-selenium, against a real inkwire-server on 127.0.0.1.

The element loads a product and draws its first view after one photo; at azimuths 0, 7.5, 37.5
and 180 degrees its canvas matches the C++ headless client's frame of the same view (PSNR >= 35
dB: the browser's software GL and llvmpipe differ in rounding, the browser's JPEG decoder in the
last bit); a drag turns the view and sends nothing. Run by ctest with the build's bin folder:
  turntable_browser_test.py BIN_DIR OUT_DIR
Skips (exit 0 with a message) when chromium, chromedriver or selenium is missing."""
import base64
import json
import math
import os
import shutil
import subprocess
import sys
import time

def skip(reason):
    print(f"SKIPPED: {reason}")
    sys.exit(0)

try:
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service
    from selenium.webdriver.common.action_chains import ActionChains
except ImportError:
    skip("python3-selenium is not installed (scripts/setup.sh installs it)")
for tool in ("/usr/bin/chromium", "/usr/bin/chromedriver"):
    if not os.path.exists(tool):
        skip(f"{tool} is missing (packages chromium and chromium-driver)")

BIN, OUT = sys.argv[1], sys.argv[2]
DUCK = "/usr/share/assimp/models/Collada/duck.dae"
if not os.path.exists(DUCK):
    skip(f"{DUCK} is missing (assimp-testmodels)")
SIZE = 256
failures, checks = [], []

def check(ok, what):
    print(("ok: " if ok else "FAILED: ") + what)
    checks.append(what)
    if not ok:
        failures.append(what)

def read_png(data):
    path = os.path.join(OUT, "tmp.png")
    with open(path, "wb") as f:
        f.write(data)
    return read_file(path)

def read_file(path):
    """(width, height, RGB bytes top row first) of an image, through OpenImageIO's oiiotool
    (Debian's openimageio-tools) writing an uncompressed TGA that a few lines can read."""
    tga_path = os.path.join(OUT, "tmp.tga")
    subprocess.run(["oiiotool", path, "--ch", "R,G,B", "-d", "uint8", "-o", tga_path], check=True)
    with open(tga_path, "rb") as f:
        tga = f.read()
    width, height = tga[12] | tga[13] << 8, tga[14] | tga[15] << 8
    pixels = tga[18 + tga[0]:18 + tga[0] + width * height * 3]
    rows = [pixels[y * width * 3:(y + 1) * width * 3] for y in range(height)]
    if not tga[17] & 0x20:  # stored bottom-up
        rows.reverse()
    rgb = bytearray()
    for row in rows:  # BGR -> RGB
        for x in range(width):
            rgb += bytes((row[3 * x + 2], row[3 * x + 1], row[3 * x]))
    return width, height, bytes(rgb)

def psnr(a, b):
    if a[0] != b[0] or a[1] != b[1]:
        return 0.0
    se = sum((x - y) ** 2 for x, y in zip(a[2], b[2]))
    return 99.0 if se == 0 else 10 * math.log10(255 * 255 / (se / len(a[2])))

os.makedirs(OUT, exist_ok=True)
data = os.path.join(OUT, "data")
shutil.rmtree(data, ignore_errors=True)
subprocess.run([f"{BIN}/inkwire-server", "add-product", "duck", "--mesh", DUCK, "--size", str(SIZE), "--data", data],
               check=True, stdout=subprocess.DEVNULL)
with open(os.path.join(OUT, "server.json"), "w") as f:
    json.dump({"sessions": [], "http": "127.0.0.1:0"}, f)
log = open(os.path.join(OUT, "server.log"), "w+")
server = subprocess.Popen([f"{BIN}/inkwire-server", "--listen", "127.0.0.1:0", "--data", data, "--config", os.path.join(OUT, "server.json")],
                          stderr=log)
driver = None
try:
    tcp = http = 0
    for _ in range(100):
        log.seek(0)
        for line in log:
            event = json.loads(line) if line.startswith("{") else {}
            tcp = event.get("port", tcp) if event.get("event") == "listening" else tcp
            http = event.get("port", http) if event.get("event") == "http-listening" else http
        if tcp and http:
            break
        time.sleep(0.1)
    if not (tcp and http):
        raise SystemExit("the server did not start")

    options = webdriver.ChromeOptions()
    for a in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run", "--disable-background-networking",
              "--disable-component-update", "--disable-sync", "--force-device-scale-factor=1", "--window-size=400,400",
              f"--user-data-dir={os.path.join(OUT, 'profile')}", "--use-angle=swiftshader", "--enable-unsafe-swiftshader"):
        options.add_argument(a)
    options.binary_location = "/usr/bin/chromium"
    driver = webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=options)
    driver.get(f"http://127.0.0.1:{http}/")
    driver.execute_script(f"""
      document.body.innerHTML = '<inkwire-turntable session="duck" auto-rotate="off" style="width:{SIZE}px;height:{SIZE}px"></inkwire-turntable>';
      import('/inkwire.js');""")
    start = time.time()
    while time.time() - start < 60 and not driver.execute_script("return document.querySelector('inkwire-turntable').hasAttribute('loaded')"):
        time.sleep(0.1)
    element = "document.querySelector('inkwire-turntable')"
    check(driver.execute_script(f"return {element}.hasAttribute('loaded')"), "the element loads the product")
    check(driver.execute_script(f"return {element}.firstViewPhotos") == 1, "the first view is drawn after one photo")
    renderer = driver.execute_script("""const gl = document.createElement('canvas').getContext('webgl2');
      const i = gl.getExtension('WEBGL_debug_renderer_info'); return i ? gl.getParameter(i.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER);""")
    print("browser GL renderer:", renderer)

    for azimuth in (0, 7.5, 37.5, 180):
        png = driver.execute_script(f"const e = {element}; e.azimuth = {azimuth}; e.draw(); return e.canvas.toDataURL('image/png');")
        web = read_png(base64.b64decode(png.split(",", 1)[1]))
        out = os.path.join(OUT, f"client-{azimuth}.png")
        subprocess.run([f"{BIN}/inkwire-client", "--connect", f"127.0.0.1:{tcp}", "--session", "duck", "--headless", "--frames", "1",
                        "--view", str(azimuth), "--size", f"{SIZE}x{SIZE}", "--wait-for-product", "--out", out,
                        "--cache", os.path.join(OUT, "cache")], check=True, stderr=subprocess.DEVNULL)
        with open(os.path.join(OUT, f"browser-{azimuth}.png"), "wb") as f:
            f.write(base64.b64decode(png.split(",", 1)[1]))
        db = psnr(web, read_file(out))
        check(db >= 35.0, f"azimuth {azimuth}: the browser's view matches the C++ client's at {db:.2f} dB (>= 35)")

    # A drag turns the view and sends nothing.
    sent, received = driver.execute_script(f"const s = {element}.session; return [s.bytesSent, s.bytesReceived];")
    before = driver.execute_script(f"return {element}.azimuth")
    canvas = driver.execute_script(f"return {element}.canvas")
    ActionChains(driver).move_to_element(canvas).click_and_hold().move_by_offset(60, 0).move_by_offset(40, 0).release().perform()
    time.sleep(0.3)
    after = driver.execute_script(f"return {element}.azimuth")
    check(abs(after - before) >= 30, f"a drag of 100 pixels turns the view ({before:.1f} -> {after:.1f} degrees, with inertia)")
    check(driver.execute_script(f"const s = {element}.session; return [s.bytesSent, s.bytesReceived];") == [sent, received],
          "the drag sent and received nothing")
finally:
    if driver:
        driver.quit()
    server.terminate()
    server.wait(timeout=10)

print(f"{len(checks) - len(failures)} passed, {len(failures)} failed")
sys.exit(1 if failures else 0)
