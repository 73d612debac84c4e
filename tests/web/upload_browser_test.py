#!/usr/bin/env python3
"""A scene from the model a visitor brings (SPEC N8, W6-W7) in real browsers against a real
inkwire-server on 127.0.0.1: on the front page Chromium picks a glTF with its .bin and texture
("New scene"); the page uploads it with its progress and lands on the scene's page as its editor.
Firefox, WebKit and the native client join the scene and draw it alike (PSNR >= 35 dB against
the native client at the same view and style); the editor restyles it and replaces its model
(an OBJ with its MTL and texture) and every member follows; a member who is not the editor
cannot restyle it (refused with the reason) and sees no "Replace the model".

  upload_browser_test.py BIN_DIR OUT_DIR
An engine that cannot run here is skipped with a message."""
import base64
import os
import shutil
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(__file__))
from browser_support import wait_until as shared_wait_until, Checks, Server, chromium, engine, engine_missing, psnr, read_image, skip  # skips without Chromium's tooling
from selenium.webdriver.common.by import By

BIN, OUT = sys.argv[1], os.path.abspath(sys.argv[2])
BOX = "/usr/share/assimp/models/glTF2/BoxTextured-glTF"
SPIDER = "/usr/share/assimp/models/OBJ"
for needed in (os.path.join(BOX, "BoxTextured.gltf"), os.path.join(SPIDER, "spider.obj")):
    if not os.path.exists(needed):
        skip(f"{needed} is missing (assimp-testmodels)")
if not os.path.exists(os.path.join(BIN, "web", "inkwire-scene.wasm")):
    skip("the server was built without the browser's renderer")
shutil.rmtree(OUT, ignore_errors=True)
os.makedirs(OUT)
checks = Checks()
check = checks.check
W, H = 320, 240
element = "document.querySelector('inkwire-scene')"



def wait_until(condition, seconds):
    """browser_support's wait, a page's script errors taken as "not yet" (it is still loading)."""
    return shared_wait_until(condition, seconds, poll=0.2, ignore=(Exception,))


def canvas(driver, name):
    """The element's picture at W x H, as a PNG read back."""
    driver.execute_script(f"document.body.style.margin = '0'; const e = {element}; e.style.cssText = 'width:{W}px;height:{H}px;display:block';"
                          f"e.shadowRoot.querySelector('details').style.display = 'none';")
    wait_until(lambda: driver.execute_script(f"return {element}.canvas.width") == W, 10)
    png = driver.execute_script(f"const e = {element}; e.draw(); return e.canvas.toDataURL('image/png');")
    path = os.path.join(OUT, f"{name}.png")
    with open(path, "wb") as f:
        f.write(base64.b64decode(png.split(",", 1)[1]))
    return read_image(path, OUT)


def native(scene, name):
    pattern = os.path.join(OUT, f"native-{name}-%04d.png")
    subprocess.run([f"{BIN}/inkwire-client", "--connect", f"127.0.0.1:{server.tcp}", "--session", scene, "--headless", "--frames", "1",
                    "--size", f"{W}x{H}", "--out", pattern, "--cache", os.path.join(OUT, "cache")], check=True, stderr=subprocess.DEVNULL)
    return read_image(pattern.replace("%04d", "0000"), OUT)


server = Server(BIN, OUT, os.path.join(OUT, "data"), {"http": "127.0.0.1:0", "sessions": []})
base = f"http://127.0.0.1:{server.http}"
editor = None
visitors = {}
try:
    editor = chromium(os.path.join(OUT, "editor"), 700, 700)
    editor.get(base + "/")
    picker = editor.find_element(By.CSS_SELECTOR, "form.upload input[type=file]")
    picker.send_keys("\n".join(os.path.join(BOX, f) for f in ("BoxTextured.gltf", "BoxTextured0.bin", "CesiumLogoFlat.png")))
    check(wait_until(lambda: "/scene/" in editor.current_url, 60), f"the upload lands on the scene's page ({editor.current_url})")
    scene = editor.current_url.split("/scene/", 1)[-1].split("#")[0]
    check(wait_until(lambda: editor.execute_script(f"return {element}.hasAttribute('loaded')"), 120), f"the editor's page draws scene {scene}")
    check(editor.execute_script(f"return {element}.modelName") == "BoxTextured.glb", "... of the model uploaded, as one GLB")
    check(not editor.execute_script("return document.querySelector('form.replace').hidden"), "... and offers its editor to replace the model")
    editor.execute_script(f"{element}.styleName = 'comic-extended'")
    for name in ("firefox", "webkit"):
        why = engine_missing(name)
        if why:
            print(f"SKIPPED engine {name}: {why}")
            continue
        driver = engine(name, os.path.join(OUT, name), 700, 700)
        visitors[name] = driver
        driver.get(f"{base}/scene/{scene}")
        check(wait_until(lambda: driver.execute_script(f"return {element}.hasAttribute('loaded')"), 120), f"{name} draws the scene")
        check(wait_until(lambda: driver.execute_script(f"return {element}.styleName") == "comic-extended", 30), f"{name} shows the editor's style")
        check(driver.execute_script("return document.querySelector('form.replace').hidden"), f"{name}, no editor, is offered no replacement")
    # Every browser draws as the native client does, at the same view and style.
    reference = native(scene, "box")
    for name, driver in [("chromium", editor), *visitors.items()]:
        db = psnr(canvas(driver, f"{name}-box"), reference)
        check(db >= 35, f"{name} draws the uploaded scene as the native client at {db:.2f} dB (>= 35)")
    # A member who is not the editor cannot restyle it.
    for name, driver in visitors.items():
        driver.execute_script(f"window.refusals = []; {element}.addEventListener('refused', (e) => refusals.push(e.detail)); {element}.styleName = 'hatching';")
        check(wait_until(lambda: driver.execute_script("return window.refusals.length") > 0, 20),
              f"{name}'s restyle is refused: {driver.execute_script('return window.refusals')}")
        check(wait_until(lambda: driver.execute_script(f"return {element}.styleName") == "comic-extended", 20), f"... and {name} shows the session's style again")
    # The editor replaces the model in the running scene; every member gets it, style kept.
    replace = editor.find_element(By.CSS_SELECTOR, "form.replace input[type=file]")
    replace.send_keys("\n".join(os.path.join(SPIDER, f) for f in ("spider.obj", "spider.mtl", "SpiderTex.jpg", "drkwood2.jpg", "engineflare1.jpg", "wal67ar_small.jpg", "wal69ar_small.jpg")
                                if os.path.exists(os.path.join(SPIDER, f))))
    for name, driver in [("chromium", editor), *visitors.items()]:
        check(wait_until(lambda: driver.execute_script(f"return {element}.modelName") == "spider.glb", 90),
              f"{name} draws the replaced model ({driver.execute_script(f'return {element}.modelName')})")
        check(driver.execute_script(f"return {element}.styleName") == "comic-extended", f"... in the style it had ({name})")
    print(editor.execute_script("return document.querySelector('form.replace .status').textContent"))
    spider = native(scene, "spider")
    check(psnr(spider, reference) < 30, "the native client draws the new model too")
    db = psnr(canvas(editor, "chromium-spider"), spider)
    check(db >= 35, f"... as the editor's page does ({db:.2f} dB)")
finally:
    for d in [editor, *visitors.values()]:
        if d:
            d.quit()
    server.stop()
checks.finish()
