#!/usr/bin/env python3
"""<inkwire-turntable> in a real headless browser (SPEC W2, W4): Debian's chromium driven by
Debian's chromium-driver and python3-selenium, against a real inkwire-server on 127.0.0.1.

The element loads a product and draws its first view after one photo; at azimuths 0, 7.5, 37.5
and 180 degrees its canvas matches the C++ headless client's frame of the same view (PSNR >= 35
dB: the browser's software GL and llvmpipe differ in rounding, the browser's JPEG decoder in the
last bit); a drag turns the view and sends nothing; on a product photographed in three rows a
drag down turns it up (as far as the top row, matching the C++ client's view there) and the arrow
keys step one row; in presenter mode a following element and a
following C++ client show the presenting element's view. Run by ctest with the build's bin folder:
  turntable_browser_test.py BIN_DIR OUT_DIR
Skips (exit 0 with a message) when chromium, chromedriver or selenium is missing."""
import base64
import json
import os
import shutil
import subprocess
import sys
import urllib.request

sys.path.insert(0, os.path.dirname(__file__))
from browser_support import Checks, Server, chromium, psnr, read_image, skip, steady, wait_until  # skips without the browser
from selenium.webdriver.common.action_chains import ActionChains

BIN, OUT = sys.argv[1], sys.argv[2]
DUCK = "/usr/share/assimp/models/Collada/duck.dae"
if not os.path.exists(DUCK):
    skip(f"{DUCK} is missing (assimp-testmodels)")
SIZE = 256
checks = Checks()
check = checks.check

os.makedirs(OUT, exist_ok=True)
data = os.path.join(OUT, "data")
shutil.rmtree(data, ignore_errors=True)
subprocess.run([f"{BIN}/inkwire-server", "add-product", "duck", "--mesh", DUCK, "--size", str(SIZE), "--data", data, "--editor-token", "sh0p-0wner"],
               check=True, stdout=subprocess.DEVNULL)
# A studio's three rows of photos (SPEC T17): 12 photos at 0, 25 and 50 degrees up.
for row, elevation in enumerate((0, 25, 50), start=1):
    folder = os.path.join(OUT, "rows", f"row{row}")
    os.makedirs(folder, exist_ok=True)
    subprocess.run([f"{BIN}/inkwire-render", "--mesh", DUCK, "--view", f"0,{elevation},1.4", "--frames", "12", "--size", f"{SIZE}x{SIZE}",
                    "--backdrop", "#ffffff", "--out", os.path.join(folder, "IMG_%04d.png")], check=True, stdout=subprocess.DEVNULL)
subprocess.run([f"{BIN}/inkwire-server", "add-product", "rows", "--photos", os.path.join(OUT, "rows"), "--step", "-30",
                "--elevations", "0,25,50", "--data", data], check=True, stdout=subprocess.DEVNULL)
# A studio's photos at 1024 pixels (SPEC T18): shown first at 512, with a zoom level at 1024.
zoom_photos = os.path.join(OUT, "zoom-photos")
os.makedirs(zoom_photos, exist_ok=True)
subprocess.run([f"{BIN}/inkwire-render", "--mesh", DUCK, "--view", "0,0,1.4", "--frames", "12", "--size", "1024x1024",
                "--backdrop", "#ffffff", "--out", os.path.join(zoom_photos, "IMG_%04d.png")], check=True, stdout=subprocess.DEVNULL)
subprocess.run([f"{BIN}/inkwire-server", "add-product", "zoom", "--photos", zoom_photos, "--step", "-30", "--data", data],
               check=True, stdout=subprocess.DEVNULL)
server = Server(BIN, OUT, data, {"sessions": [], "http": "127.0.0.1:0"})
tcp, http = server.tcp, server.http
driver = None


def loaded_element(id_, session):
    """A new element for `session` at the top of the page, once loaded; its JS expression."""
    driver.execute_script(f"""const e = document.createElement('inkwire-turntable');
      e.setAttribute('session', '{session}'); e.setAttribute('auto-rotate', 'off'); e.id = '{id_}';
      e.style.cssText = 'width:{SIZE}px;height:{SIZE}px'; document.body.prepend(e);""")
    element = f"document.getElementById('{id_}')"
    wait_until(lambda: driver.execute_script(f"return {element}.hasAttribute('loaded')"), 120)
    return element


def against_client(element, session, name, view, setup=""):
    """PSNR of the element's picture (after the JS `setup` on it, `e`) against the C++ client's at `view`."""
    png = driver.execute_script(f"const e = {element}; {setup} e.draw(); return e.canvas.toDataURL('image/png');")
    browser_png = os.path.join(OUT, f"browser-{name}.png")
    with open(browser_png, "wb") as f:
        f.write(base64.b64decode(png.split(",", 1)[1]))
    client_png = os.path.join(OUT, f"client-{name}.png")
    subprocess.run([f"{BIN}/inkwire-client", "--connect", f"127.0.0.1:{tcp}", "--session", session, "--headless", "--frames", "1",
                    "--view", view, "--size", f"{SIZE}x{SIZE}", "--wait-for-product", "--out", client_png,
                    "--cache", os.path.join(OUT, f"cache-{session}")], check=True, stderr=subprocess.DEVNULL)
    return psnr(read_image(browser_png, OUT), read_image(client_png, OUT))


try:
    driver = chromium(OUT, 400, 400)
    driver.get(f"http://127.0.0.1:{http}/")
    driver.execute_script(f"""performance.setResourceTimingBufferSize(100000);
      document.body.innerHTML = '<inkwire-turntable session="duck" token="sh0p-0wner" auto-rotate="off" style="width:{SIZE}px;height:{SIZE}px"></inkwire-turntable>';
      import('/inkwire.js');""")
    wait_until(lambda: driver.execute_script("return document.querySelector('inkwire-turntable').hasAttribute('loaded')"), 120)
    element = "document.querySelector('inkwire-turntable')"
    check(driver.execute_script(f"return {element}.hasAttribute('loaded')"), "the element loads the product")
    check(driver.execute_script(f"return {element}.firstViewPhotos") == 1, "the first view is drawn after one photo")
    renderer = driver.execute_script("""const gl = document.createElement('canvas').getContext('webgl2');
      const i = gl.getExtension('WEBGL_debug_renderer_info'); return i ? gl.getParameter(i.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER);""")
    print("browser GL renderer:", renderer)

    for azimuth in (0, 7.5, 37.5, 180):
        db = against_client(element, "duck", str(azimuth), str(azimuth), f"e.azimuth = {azimuth};")
        check(db >= 35.0, f"azimuth {azimuth}: the browser's view matches the C++ client's at {db:.2f} dB (>= 35)")

    # A visitor's element reads the product as static files from the server (/products/duck/):
    # no WebSocket; and a drag turns the view and fetches nothing.
    check((driver.execute_script(f"return {element}.websocketsOpened") or 0) == 0, "a visitor's element opens no WebSocket")
    traffic = f"return [{element}.product.bytesReceived, performance.getEntriesByType('resource').length];"
    fetched = driver.execute_script(traffic)
    before = driver.execute_script(f"return {element}.azimuth")
    canvas = driver.execute_script(f"return {element}.canvas")
    ActionChains(driver).move_to_element(canvas).click_and_hold().move_by_offset(60, 0).move_by_offset(40, 0).release().perform()
    after = steady(lambda: driver.execute_script(f"return {element}.azimuth"))  # once its fling has ended
    check(abs(after - before) >= 30, f"a drag of 100 pixels turns the view ({before:.1f} -> {after:.1f} degrees, with inertia)")
    check(driver.execute_script(traffic) == fetched, "the drag fetched nothing")

    # One ring of photos: up and down there is nothing to turn to.
    ActionChains(driver).move_to_element(canvas).click_and_hold().move_by_offset(0, 50).release().perform()
    check(driver.execute_script(f"return {element}.elevation") == 0, "a drag down on one ring of photos keeps the view level")

    # Rows: a drag down turns the view up, as far as the top row; the arrow keys step one row.
    rows = loaded_element("rows", "rows")
    check(driver.execute_script(f"return {rows}.hasAttribute('loaded')"), "the element loads a product in three rows")
    rows_canvas = driver.execute_script(f"return {rows}.canvas")
    ActionChains(driver).move_to_element(rows_canvas).click_and_hold().move_by_offset(0, 25).move_by_offset(0, 25).perform()
    held = driver.execute_script(f"return [{rows}.azimuth, {rows}.elevation]")
    ActionChains(driver).release().perform()
    check(abs(held[0]) < 0.01 and abs(held[1] - 20) < 0.01, f"a drag of 50 pixels down turns the view 20 degrees up ({held[1]:.2f}), not round")
    db = against_client(rows, "rows", "rows", "-15,20", "e.azimuth = -15;")
    check(db >= 35.0, f"between rows (azimuth -15, 20 up) the browser's view matches the C++ client's at {db:.2f} dB (>= 35)")
    ActionChains(driver).move_to_element(rows_canvas).click_and_hold().move_by_offset(0, 60).move_by_offset(0, 60).release().perform()
    check(abs(driver.execute_script(f"return {rows}.elevation") - 50) < 0.01, "dragged further, the view stops at the top row (50 degrees)")
    driver.execute_script(f"{rows}.focus()")
    ActionChains(driver).send_keys("\ue015").perform()  # arrow down
    stepped = driver.execute_script(f"return {rows}.elevation")
    check(abs(stepped - 25) < 0.01, f"the down arrow steps one row down ({stepped:.2f} degrees)")
    driver.execute_script(f"{rows}.remove()")

    # Zoom (SPEC T18): not zoomed in, no finer photo is fetched; zoomed in four times, the finer
    # level of the photos the view is drawn from is, then of those nearest it up to six, and the
    # view matches the C++ client's.
    zoomed = loaded_element("zoom", "zoom")
    check(driver.execute_script(f"return {zoomed}.hasAttribute('loaded')"), "the element loads a product with a zoom level")
    fetched_zoom = f"""const e = {zoomed}, hex = (h) => Array.from(h, (b) => b.toString(16).padStart(2, '0')).join('');
      return e.snapshot.assets.filter((a) => a.kind === 7 && e.product.receivedBy.has(hex(a.hash))).length;"""
    # (Whatever the element fetches after loading has ended once its byte count holds still.)
    steady(lambda: driver.execute_script(f"return {zoomed}.product.bytesReceived"))
    check(driver.execute_script(fetched_zoom) == 0, "not zoomed in, no finer photo is fetched")
    driver.execute_script(f"{zoomed}.setZoom(4)")
    wait_until(lambda: driver.execute_script(f"{zoomed}.redraw(); return {zoomed}.view.finerInView >= 2"), 60)
    in_view = driver.execute_script(f"return {zoomed}.view.finerInView")
    check(in_view >= 2, f"zoomed in four times, the finer photos the view is drawn from are fetched ({in_view} drawn from)")
    # Then the photos a turn comes to next, till six (kFinerKept) hold the finer level, and no more.
    wait_until(lambda: driver.execute_script(fetched_zoom) >= 6, 60)
    steady(lambda: driver.execute_script(f"return {zoomed}.product.bytesReceived"))  # and no more once the fetches have ended
    fetched = driver.execute_script(fetched_zoom)
    check(fetched == 6, f"zoomed in and still, the six photos nearest the view take the finer level and no more ({fetched} of 12)")
    db = against_client(zoomed, "zoom", "zoom", "0,0,4")
    check(db >= 35.0, f"zoomed in four times the browser's view matches the C++ client's at {db:.2f} dB (>= 35)")
    driver.execute_script(f"{zoomed}.remove()")

    # Lifecycle (what connectedCallback adds, disconnectedCallback removes): moved in the page, the element's handlers are there once, so the same
    # drag turns it as far as before (twice as far when a re-connection added them again). The
    # turn is read while the button is still held: the fling after it depends on how fast a
    # loaded machine delivers the moves, the turn under the pointer does not.
    def turned_by_drag():
        start_az = steady(lambda: driver.execute_script(f"return {element}.azimuth"))  # the last fling has died down
        ActionChains(driver).move_to_element(driver.execute_script(f"return {element}.canvas")).click_and_hold() \
            .move_by_offset(30, 0).move_by_offset(30, 0).perform()
        turned = driver.execute_script(f"return {element}.azimuth") - start_az
        ActionChains(driver).release().perform()
        return turned
    first_turn = turned_by_drag()
    driver.execute_script(f"const e = {element}; const box = document.createElement('div'); document.body.prepend(box); box.append(e);")
    moved_turn = turned_by_drag()
    check(first_turn != 0 and 0.7 < moved_turn / first_turn < 1.4,
          f"moved in the page, a drag turns it once as far ({first_turn:.1f} then {moved_turn:.1f} degrees)")
    # One animation loop however often its attributes restart it: an element restarted five times
    # auto-spins as fast as one never restarted, side by side in the same frames (a loop per
    # restart would make it six times as fast, whatever the machine's load).
    driver.execute_script(f"""for (const id of ['spinner', 'reference']) {{
        const e = document.createElement('inkwire-turntable');
        e.setAttribute('session', 'duck'); e.style.cssText = 'width:{SIZE}px;height:{SIZE}px'; e.id = id;
        document.body.append(e);
      }}
      for (const t of ['a', 'b', 'c', 'd', '']) document.getElementById('spinner').setAttribute('token', t);""")
    loaded = "return ['spinner', 'reference'].every((id) => document.getElementById(id).hasAttribute('loaded'))"
    wait_until(lambda: driver.execute_script(loaded), 120)
    azimuths = "return ['spinner', 'reference'].map((id) => document.getElementById(id).azimuth)"
    s0, r0 = driver.execute_script(azimuths)
    # Until the one never restarted has spun 20 degrees, however long a loaded machine takes.
    wait_until(lambda: driver.execute_script(azimuths)[1] - r0 >= 20, 120)
    s1, r1 = driver.execute_script(azimuths)
    check(r1 - r0 > 0 and 0.5 < (s1 - s0) / (r1 - r0) < 1.8,
          f"after five restarts it auto-spins as fast as an element never restarted ({s1 - s0:.1f} against {r1 - r0:.1f} degrees)")
    driver.execute_script("for (const id of ['spinner', 'reference']) document.getElementById(id).remove()")
    # A visitor without the editor token who tries to present is refused, and the element says so.
    driver.execute_script(f"""const e = document.createElement('inkwire-turntable');
      e.setAttribute('session', 'duck'); e.setAttribute('present', ''); e.setAttribute('auto-rotate', 'off'); e.id = 'stranger';
      e.style.cssText = 'width:{SIZE}px;height:{SIZE}px'; document.body.append(e);""")
    message = wait_until(lambda: driver.execute_script("""const e = document.getElementById('stranger'); e.azimuth = e.azimuth + 5;
      const m = e.shadowRoot.querySelector('.message').textContent; return m.includes('Refused') ? m : '';"""), 60, poll=0.2) or \
        driver.execute_script("return document.getElementById('stranger').shadowRoot.querySelector('.message').textContent")
    check("only the product's editor may" in message, f"a visitor who presents is told why it is refused: '{message}'")
    driver.execute_script("document.getElementById('stranger').remove()")

    # Presenter mode: a second element that follows shows this one's view once it presents, a
    # drag included; a C++ client that follows later joins at the presented view.
    follower = "document.querySelectorAll('inkwire-turntable')[1]"
    driver.execute_script(f"""
      const follower = document.createElement('inkwire-turntable');
      follower.setAttribute('session', 'duck');
      follower.setAttribute('follow', '');
      follower.style.cssText = 'width:{SIZE}px;height:{SIZE}px';
      document.body.appendChild(follower);""")
    def wait_for(script, seconds=60):
        return wait_until(lambda: driver.execute_script(script), seconds)
    check(wait_for(f"return {follower}.hasAttribute('loaded')"), "a following element loads the product")
    driver.execute_script(f"{element}.setAttribute('present', ''); {element}.azimuth = 123.5;")
    check(wait_for(f"return Math.abs({follower}.azimuth - 123.5) < 0.01"),
          f"the follower turns to the presenter's 123.5 degrees ({driver.execute_script(f'return {follower}.azimuth'):.2f})")
    ActionChains(driver).move_to_element(canvas).click_and_hold().move_by_offset(-50, 0).move_by_offset(-30, 0).release().perform()
    presenter_az = steady(lambda: driver.execute_script(f"return {element}.azimuth"))  # the presenter's fling has died down
    on_the_circle = lambda degrees: (degrees + 180) % 360 - 180
    wait_until(lambda: abs(on_the_circle(driver.execute_script(f"return {follower}.azimuth") - presenter_az)) < 0.01, 60)
    follower_az = driver.execute_script(f"return {follower}.azimuth")
    check(abs(on_the_circle(presenter_az - 123.5)) >= 20 and abs(on_the_circle(follower_az - presenter_az)) < 0.01,
          f"after the presenter's drag the follower shows its view ({presenter_az:.2f} -> {follower_az:.2f} degrees)")
    # A presenter shares the product page's address with ?follow; nothing else of the query reaches the page.
    for query, tag in (("?follow", '<inkwire-turntable session="duck" follow>'), ("?present", '<inkwire-turntable session="duck" present>'),
                       ("?follow=<b>x</b>", '<inkwire-turntable session="duck">')):
        page = urllib.request.urlopen(f"http://127.0.0.1:{http}/turntable/duck{query}").read().decode()
        check(tag in page, f"the page /turntable/duck{query} holds {tag}")
    late_log = os.path.join(OUT, "late-follower.jsonl")
    subprocess.run([f"{BIN}/inkwire-client", "--connect", f"127.0.0.1:{tcp}", "--session", "duck", "--headless", "--frames", "1",
                    "--follow", "--size", f"{SIZE}x{SIZE}", "--out", os.path.join(OUT, "late-follower.png"), "--frame-log", late_log,
                    "--cache", os.path.join(OUT, "cache")], check=True, stderr=subprocess.DEVNULL)
    with open(late_log) as f:
        late_az = json.loads(f.readline())["product"]["azimuth"]
    check(abs(on_the_circle(late_az - presenter_az)) < 0.01,
          f"a C++ client that follows later joins at the browser presenter's view ({late_az:.2f} degrees)")
finally:
    if driver:
        driver.quit()
    server.stop()
checks.finish()
