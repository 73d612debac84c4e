#!/usr/bin/env python3
"""A product exported as static files and served by Debian's nginx with the project's own config
(deploy/nginx/inkwire-products.conf), turned by <inkwire-turntable src=".../product.json"> in
each browser engine the machine has that can run here (Chromium; Firefox and WebKit under a display)
(SPEC T20-T23), with the page on one loopback origin and the product on another:

- the element draws the product with no WebSocket opened, and its view at an angle between
  photos matches the same element reading the product from inkwire-server (PSNR >= 45 dB);
- zoomed in, the finer level's photos are fetched from nginx, and not before;
- a second visit fetches only the manifest from nginx (its access log says so);
- a manifest of another version, a photo changed on disk after the export and a missing photo
  each show their reason in the element, which keeps what it drew;
- a second export after one photo changed writes that photo's files, the cells next to it (any
  cell for a product made along its shape, which every photo shapes) and
  the manifest, and nothing else.

  static_product_browser_test.py BIN_DIR OUT_DIR [ENGINE ...]
Skips with a message when nginx or the browser tooling is missing."""
import base64
import gzip
import json
import os
import shutil
import subprocess
import sys
import urllib.error
import urllib.request

sys.path.insert(0, os.path.dirname(__file__))
from browser_support import ENGINES, Checks, Nginx, Server, engine, engine_missing, psnr, read_image, skip, wait_until

BIN, OUT = sys.argv[1], sys.argv[2]
wanted = [a for a in sys.argv[3:] if a in ENGINES] or list(ENGINES)
DUCK = "/usr/share/assimp/models/Collada/duck.dae"
if not (shutil.which("nginx") or os.path.exists("/usr/sbin/nginx")):
    skip("nginx is missing (scripts/packages.txt: nginx-light)")
if not os.path.exists(DUCK):
    skip(f"{DUCK} is missing (assimp-testmodels)")
runnable = [name for name in wanted if not engine_missing(name)]
for name in wanted:
    if name not in runnable:
        print(f"{name}: skipped ({engine_missing(name)})")
if not runnable:
    skip("no browser engine can run here")
SIZE = 256
checks = Checks()
check = checks.check
shutil.rmtree(OUT, ignore_errors=True)
os.makedirs(OUT)


def run(*args):
    return subprocess.run([f"{BIN}/{args[0]}", *args[1:]], check=True, capture_output=True, text=True).stdout


# Twelve studio photos at 1024 px (a zoom level above the first 512), then the product, exported.
photos = os.path.join(OUT, "photos")
os.makedirs(photos)
run("inkwire-render", "--mesh", DUCK, "--view", "0,0,1.4", "--frames", "12", "--size", "1024x1024", "--backdrop", "#ffffff",
    "--out", os.path.join(photos, "IMG_%04d.png"))
data, root = os.path.join(OUT, "data"), os.path.join(OUT, "www")
printed = run("inkwire-server", "add-product", "duck", "--photos", photos, "--step", "-30", "--data", data, "--export", os.path.join(root, "duck"))
print(printed.strip())
check('<inkwire-turntable src="PRODUCT-URL/product.json"' in printed and 'session="duck"' in printed,
      "add-product prints the snippet for a static host and for the server")
manifest = json.load(open(os.path.join(root, "duck", "product.json")))
check(manifest["version"] == 1 and len(manifest["photos"]) == 12 and len(manifest["zoom"]) == 1,
      f"the manifest lists 12 photos and one zoom level ({len(manifest['photos'])}, {len(manifest['zoom'])})")

# Broken copies: another version; photo 6 changed after the export; photo 6 missing.
for bad in ("version", "changed", "missing"):
    shutil.copytree(os.path.join(root, "duck"), os.path.join(root, f"duck-{bad}"))
bad_manifest = dict(manifest, version=2)
json.dump(bad_manifest, open(os.path.join(root, "duck-version", "product.json"), "w"))
os.remove(os.path.join(root, "duck-version", "product.json.gz"))  # or nginx sends the good one, gzipped ahead
victim = manifest["photos"][6]["file"]
with open(os.path.join(root, "duck-changed", victim), "r+b") as f:
    f.seek(2000)
    f.write(b"\x00" * 64)
os.remove(os.path.join(root, "duck-missing", victim))

# nginx with the project's config, on 127.0.0.1, as an unprivileged process.
nginx = Nginx(root, os.path.join(OUT, "nginx"))
port = nginx.port
server = Server(BIN, OUT, data, {"sessions": [], "http": "127.0.0.1:0"})
product = f"http://127.0.0.1:{port}/duck"
requests_since = nginx.requests_since

# The server serves each product as the export has it (/products/NAME/: one way to load either):
# the same manifest and files, the headers a static host sends, a repeat visit answered 304.
served_by_server = f"http://127.0.0.1:{server.http}/products/duck"
exported = open(os.path.join(root, "duck", "product.json"), "rb").read()
with urllib.request.urlopen(f"{served_by_server}/product.json") as reply:
    check(reply.read() == exported and reply.headers["Access-Control-Allow-Origin"] == "*" and reply.headers["Cache-Control"] == "no-cache",
          "the server's /products/duck/product.json is the exported manifest, readable from any origin, revalidated each visit")
    etag = reply.headers["ETag"]
gzipped = urllib.request.urlopen(urllib.request.Request(f"{served_by_server}/product.json", headers={"Accept-Encoding": "gzip"}))
check(gzipped.headers["Content-Encoding"] == "gzip" and gzip.decompress(gzipped.read()) == exported, "... gzipped for a browser that takes it")
try:
    urllib.request.urlopen(urllib.request.Request(f"{served_by_server}/product.json", headers={"If-None-Match": etag}))
    check(False, "a repeat visit's manifest request is answered 304")
except urllib.error.HTTPError as e:
    check(e.code == 304, f"a repeat visit's manifest request is answered 304 ({e.code})")
for f in (manifest["photos"][3], manifest["mattes"][3], manifest["zoom"][0][3], manifest["cells"][3]):
    with urllib.request.urlopen(f"{served_by_server}/{f['file']}") as reply:
        same = reply.read() == open(os.path.join(root, "duck", f["file"]), "rb").read()
        check(same and "immutable" in reply.headers["Cache-Control"], f"the server serves {f['file']} as exported, immutable")
for wrong, code in (("files/" + "0" * 64 + ".jpg", 404), ("../duck/product.json", 404)):
    try:
        urllib.request.urlopen(f"{served_by_server}/{wrong}")
        check(False, f"a file the manifest does not name ({wrong}) is refused")
    except urllib.error.HTTPError as e:
        check(e.code == code, f"a file the manifest does not name ({wrong}) is refused ({e.code})")

try:
    for name in runnable:
        out = os.path.join(OUT, name)
        os.makedirs(out)
        driver = engine(name, out, 500, 420)
        try:
            # The page on the server's origin; the product on nginx's.
            driver.get(f"http://127.0.0.1:{server.http}/")

            def element_for(attributes, id_):
                driver.execute_script(f"""const e = document.createElement('inkwire-turntable');
                  for (const [k, v] of Object.entries({json.dumps(attributes)})) e.setAttribute(k, v);
                  e.setAttribute('auto-rotate', 'off'); e.id = '{id_}'; e.style.cssText = 'width:{SIZE}px;height:{SIZE}px;display:block';
                  document.body.prepend(e);""")
                element = f"document.getElementById('{id_}')"
                wait_until(lambda: driver.execute_script(f"return {element}.hasAttribute('loaded') || !!{element}.message.textContent"), 120)
                return element

            def picture(element, azimuth, label):
                png = driver.execute_script(f"const e = {element}; e.azimuth = {azimuth}; e.draw(); return e.canvas.toDataURL('image/png');")
                path = os.path.join(out, f"{label}.png")
                open(path, "wb").write(base64.b64decode(png.split(",", 1)[1]))
                return read_image(path, out)

            log_start = nginx.log_size()
            driver.execute_script(f"return import('{product}/inkwire.js').then(() => customElements.whenDefined('inkwire-turntable')).then(() => true)")
            static = element_for({"src": f"{product}/product.json"}, "static")
            message = driver.execute_script(f"return {static}.message.textContent")
            check(driver.execute_script(f"return {static}.hasAttribute('loaded')"), f"{name}: the element loads the product from nginx ({message!r})")
            check(not driver.execute_script(f"return {static}.websocketsOpened ?? 0"), f"{name}: no WebSocket is opened")
            first_view = driver.execute_script(f"return [{static}.firstViewPhotos, {static}.firstViewBytes, {static}.firstViewMs]")
            print(f"{name}: first view after {first_view[0]} photo, {first_view[1]} bytes from nginx, {first_view[2]:.0f} ms")
            served = requests_since(log_start)
            zoom_files = {f["file"] for f in manifest["zoom"][0]}
            check(not any(p.endswith(tuple(zoom_files)) for p, _ in served), f"{name}: not zoomed in, no finer photo is fetched")
            live = element_for({"session": "duck"}, "live")
            for azimuth in (37.5, 200):
                db = psnr(picture(static, azimuth, f"static-{azimuth}"), picture(live, azimuth, f"server-{azimuth}"))
                check(db >= 45, f"{name}: at {azimuth} degrees the static product matches the one from inkwire-server ({db:.1f} dB >= 45)")
            driver.execute_script(f"const e = {static}; e.zoom = 4; e.draw();")
            wait_until(lambda: any(p.endswith(tuple(zoom_files)) for p, _ in requests_since(log_start)), 60, poll=0.2)
            finer = sum(1 for p, _ in requests_since(log_start) if p.endswith(tuple(zoom_files)))
            check(finer > 0, f"{name}: zoomed in four times, the finer photos come from nginx ({finer})")

            # A second visit: the same page again; only the manifest goes to nginx. The first
            # visit's zoomed photos still in flight land first (on a loaded machine one was
            # logged during the second visit).
            nginx.settled_log_size()
            driver.get(f"http://127.0.0.1:{server.http}/")
            log_start = nginx.log_size()
            driver.execute_script(f"return import('{product}/inkwire.js').then(() => customElements.whenDefined('inkwire-turntable')).then(() => true)")
            again = element_for({"src": f"{product}/product.json"}, "again")
            check(driver.execute_script(f"return {again}.hasAttribute('loaded')"), f"{name}: the second visit shows the product")
            served = requests_since(log_start)
            print(f"{name}: the second visit asked nginx for {len(served)} files: {served[:3]}...")
            # Whether this browser keeps anything between visits at all: the same immutable file
            # fetched twice from the page must reach nginx once.
            probe = f"{product}/{manifest['photos'][5]['file']}"
            log_start = nginx.log_size()
            driver.execute_script(f"return fetch('{probe}').then((r) => r.arrayBuffer()).then(() => fetch('{probe}')).then((r) => r.arrayBuffer()).then(() => true)")
            caching = len(requests_since(log_start)) <= 1
            if caching:
                check([p for p, _ in served] == ["/duck/product.json"], f"{name}: a second visit fetches only the manifest ({len(served)} requests)")
            else:
                print(f"{name}: under automation this engine keeps no HTTP cache (an immutable file fetched twice reached nginx twice): "
                      "the second visit's check does not apply")

            # Broken products: the reason in the element, what it drew kept. Cache Storage goes
            # first: it holds the good files under the same hashes and would serve them.
            driver.execute_script("return caches.delete('inkwire-assets-v1').then(() => true)")
            for bad, reason in (("version", "version 2, this element reads version 1"), ("changed", "does not match its hash"), ("missing", "answered 404")):
                e = element_for({"src": f"http://127.0.0.1:{port}/duck-{bad}/product.json"}, f"bad-{bad}")
                wait_until(lambda: driver.execute_script(f"return {e}.message.textContent"), 60)
                said = driver.execute_script(f"return {e}.message.textContent")
                check(reason in said, f"{name}: a product whose {bad} photo or manifest is wrong says so ({said!r})")
                if bad != "version":
                    drawn = picture(e, 0, f"bad-{bad}")
                    check(min(drawn[2]) < 128, f"{name}: ... and keeps what it drew ({bad})")
        finally:
            driver.quit()

    # A second export after one photo changed: that photo's files, the cells next to it, the manifest.
    before = set(os.listdir(os.path.join(root, "duck", "files")))
    run("inkwire-render", "--mesh", DUCK, "--view", "0,0,1.4", "--frames", "12", "--size", "1024x1024", "--backdrop", "#fff8f0",
        "--out", os.path.join(OUT, "recoloured_%04d.png"))
    shutil.copy(os.path.join(OUT, "recoloured_0004.png"), os.path.join(photos, "IMG_0004.png"))
    printed = run("inkwire-server", "add-product", "duck", "--photos", photos, "--step", "-30", "--data", data, "--export", os.path.join(root, "duck"))
    after = json.load(open(os.path.join(root, "duck", "product.json")))
    new_files = set(os.listdir(os.path.join(root, "duck", "files"))) - before
    changed = {k: [i for i, (a, b) in enumerate(zip(manifest[k], after[k])) if a != b] for k in ("photos", "mattes", "cells")}
    changed["zoom"] = [i for i, (a, b) in enumerate(zip(manifest["zoom"][0], after["zoom"][0])) if a != b]
    print(f"after photo 4 changed, the export added {len(new_files)} files; changed: {changed}")
    # A product made along its shape (add-product says so): the shape comes from every photo, so a
    # changed photo may move control points of any cell; with matched points alone, only its own.
    shaped = "shape from the mattes" in printed
    cells_allowed = set(range(len(manifest["cells"]))) if shaped else {3, 4}
    check(changed["photos"] == [4] and changed["zoom"] == [4] and set(changed["mattes"]) <= {4} and set(changed["cells"]) <= cells_allowed,
          f"a second export after photo 4 changed writes only its files and {'cells' if shaped else 'the cells next to it'} ({changed})")
    check(len(new_files) == sum(len(v) for v in changed.values()), f"... and adds no other file ({len(new_files)} new)")
finally:
    server.stop()
    nginx.stop()
checks.finish()
