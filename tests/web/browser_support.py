"""What the browser tests share beyond tests/support: a skip with a message when Debian's
chromium, chromium-driver or python3-selenium is missing, and headless Chromium with the flags
this machine needs; Firefox (Debian's firefox-esr through puppeteer-core, tests/web/package.json)
and WebKitGTK (webkit2gtk-driver's WebKitWebDriver and MiniBrowser) behind the same few calls
(get, execute_script, save_screenshot, quit), each with fake camera and microphone, for the
tests that run in every engine (SPEC F18). Those two need a display (xvfb-run): without one, or
without the engine, `engine()` says why and the test skips that engine."""
import json
import os
import shutil
import subprocess
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from inkwire_test import PROTOCOL_VERSION, Checks, Server, psnr, read_image, skip, steady, wait_until  # noqa: E402,F401  (re-exported for the tests)

try:
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service
except ImportError:
    skip("python3-selenium is not installed (scripts/setup.sh installs it)")
for _tool in ("/usr/bin/chromium", "/usr/bin/chromedriver"):
    if not os.path.exists(_tool):
        skip(f"{_tool} is missing (packages chromium and chromium-driver)")


# WebGL2 with no GPU: SwiftShader (Chromium's own, on Vulkan; what a visitor's browser without a
# GPU uses, and the tests' default) or, with INKWIRE_BROWSER_GL=llvmpipe, ANGLE over Mesa's
# llvmpipe through EGL, the rasteriser the native client draws with (the benches compare both).
GL_FLAGS = {"swiftshader": ("--disable-gpu", "--use-angle=swiftshader", "--enable-unsafe-swiftshader"),
            "llvmpipe": ("--use-angle=gl-egl", "--ignore-gpu-blocklist")}


def chromium(out, width, height, extra=(), mobile=False):
    """Headless Chromium; `extra` flags add to this machine's (e.g. fake camera and microphone).
    `mobile`: a phone's viewport of exactly `width` x `height` (Chromium's device emulation: a
    desktop window is never narrower than 500 pixels)."""
    gl = os.environ.get("INKWIRE_BROWSER_GL", "swiftshader")
    if gl not in GL_FLAGS:
        raise SystemExit(f"INKWIRE_BROWSER_GL={gl}: not one of {', '.join(GL_FLAGS)}")
    options = webdriver.ChromeOptions()
    for a in ("--headless=new", "--no-sandbox", "--disable-quic", "--no-first-run", "--disable-background-networking",
              "--disable-component-update", "--disable-sync", "--force-device-scale-factor=1", f"--window-size={width},{height}",
              f"--user-data-dir={os.path.join(out, 'profile')}", *GL_FLAGS[gl]):
        options.add_argument(a)
    for a in extra:
        options.add_argument(a)
    if mobile:
        options.add_experimental_option("mobileEmulation", {"deviceMetrics": {"width": width, "height": height, "pixelRatio": 1.0}})
    options.binary_location = "/usr/bin/chromium"
    driver = webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=options)
    # A script waits behind the page's own work, which on a machine whose cores are busy elsewhere
    # can take long: one generous timeout, not the driver's 30 s.
    driver.set_script_timeout(300)
    return driver


def face_frames(folder, neutral, smile, seconds):
    """A camera for a call member: a folder of frames at 15 fps, `neutral` for seconds[0] and then
    `smile` for seconds[1] (links to the two photos)."""
    os.makedirs(folder)
    frame = 0
    for photo, count in ((neutral, seconds[0] * 15), (smile, seconds[1] * 15)):
        for _ in range(count):
            os.symlink(photo, os.path.join(folder, f"{frame:04d}{os.path.splitext(photo)[1]}"))
            frame += 1
    return folder


def face_clip(out, name, neutral, smile, seconds=(3, 9)):
    """face_frames() in OUT/NAME and a y4m of them at 15 fps, 320 x 240 (Chromium's fake camera
    file): the native member's camera and a browser's, the same pictures."""
    folder = face_frames(os.path.join(out, name), neutral, smile, seconds)
    y4m = os.path.join(out, f"{name}.y4m")
    subprocess.run(["ffmpeg", "-v", "error", "-y", "-framerate", "15", "-i", os.path.join(folder, "%04d" + os.path.splitext(neutral)[1]),
                    "-vf", "scale=320:240:force_original_aspect_ratio=decrease,pad=320:240:(ow-iw)/2:(oh-ih)/2,format=yuv420p", y4m], check=True)
    return folder, y4m


ENGINES = ("chromium", "firefox", "webkit")
HERE = os.path.dirname(os.path.abspath(__file__))
MINIBROWSER = "/usr/lib/x86_64-linux-gnu/webkit2gtk-4.1/MiniBrowser"


def engine_missing(name):
    """Why `name` cannot run here, or None."""
    if name == "chromium":
        return None  # checked on import
    if not os.environ.get("DISPLAY"):
        return f"{name} needs a display here (run under xvfb-run: headless Firefox has no WebGL)"
    if name == "firefox":
        if not os.path.exists("/usr/bin/firefox-esr"):
            return "/usr/bin/firefox-esr is missing (package firefox-esr)"
        if not shutil.which("node") or not os.path.isdir(os.path.join(HERE, "node_modules", "puppeteer-core")):
            return "puppeteer-core is not installed (scripts/setup.sh runs npm ci --prefix tests/web)"
        if not shutil.which("pulseaudio"):
            return "pulseaudio is missing (Firefox plays no sound without a sound server)"
        return None
    if name == "webkit":
        if not os.path.exists("/usr/bin/WebKitWebDriver"):
            return "/usr/bin/WebKitWebDriver is missing (package webkit2gtk-driver)"
        if not os.path.exists(MINIBROWSER):
            return f"{MINIBROWSER} is missing (package libwebkit2gtk-4.1-0)"
        return None
    return f"no engine named {name}"


def null_sound_server(out):
    """A PulseAudio daemon of this test's own with a null sink (Firefox's audio needs a sound server
    to run at all; a machine without speakers has none): the environment that reaches it, and
    the daemon's process."""
    runtime = os.path.join(out, "pulse-runtime")
    os.makedirs(runtime, exist_ok=True)
    os.chmod(runtime, 0o700)
    env = dict(os.environ, XDG_RUNTIME_DIR=runtime, PULSE_RUNTIME_PATH=os.path.join(runtime, "pulse"))
    daemon = subprocess.Popen(["pulseaudio", "--daemonize=no", "--exit-idle-time=-1", "-n", "--load=module-null-sink sink_name=inkwire",
                               "--load=module-native-protocol-unix", f"--log-target=file:{os.path.join(out, 'pulseaudio.log')}"],
                              env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    # Up before Firefox starts: a Firefox that finds no sound server keeps its audio suspended
    # for good.
    if not wait_until(lambda: os.path.exists(os.path.join(runtime, "pulse", "native")), 60):
        raise RuntimeError(f"the test's sound server did not start (see {out}/pulseaudio.log)")
    return env, daemon


class FirefoxDriver:
    """Firefox ESR through tests/web/firefox_bridge.mjs, with selenium's calls the tests use."""

    def __init__(self, out, width, height, prefs=()):
        os.makedirs(out, exist_ok=True)
        profile = os.path.join(out, "firefox-profile")
        shutil.rmtree(profile, ignore_errors=True)
        os.makedirs(profile)
        self.log = open(os.path.join(out, "firefox.log"), "w")
        env, self.sound = null_sound_server(out)
        self.process = subprocess.Popen(["node", os.path.join(HERE, "firefox_bridge.mjs"), profile, str(width), str(height), *prefs],
                                        stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=self.log, text=True, cwd=HERE, env=env)

    def _ask(self, request):
        self.process.stdin.write(json.dumps(request) + "\n")
        self.process.stdin.flush()
        line = self.process.stdout.readline()
        if not line:
            raise RuntimeError(f"Firefox ended (see {self.log.name})")
        answer = json.loads(line)
        if "error" in answer:
            raise RuntimeError(f"in Firefox: {answer['error']}")
        return answer["ok"]

    def get(self, url):
        self._ask({"get": url})

    def execute_script(self, script):
        return self._ask({"script": script})

    def save_screenshot(self, path):
        self._ask({"screenshot": os.path.abspath(path)})

    def quit(self):
        try:
            self._ask({"quit": True})
            self.process.wait(timeout=20)
        except Exception:
            self.process.kill()
        self.sound.terminate()
        self.sound.wait(timeout=10)


def webkit(width, height):
    """WebKitGTK's MiniBrowser under WebKitWebDriver, with mock camera and microphone. Its
    JavaScriptCore leaves SharedArrayBuffer off even on a cross-origin isolated page, where
    Safari has it: it is turned on as Safari has it (JSC_useSharedArrayBuffer)."""
    os.environ["JSC_useSharedArrayBuffer"] = "1"
    o = webdriver.WebKitGTKOptions()
    o.binary_location = MINIBROWSER
    for a in ("--automation", "--enable-mock-capture-devices=true", "--enable-media-stream=true", "--media-playback-requires-user-gesture=false"):
        o.add_argument(a)
    driver = webdriver.WebKitGTK(executable_path="/usr/bin/WebKitWebDriver", options=o)
    driver.set_window_size(width, height)
    return driver


def engine(name, out, width, height, chromium_extra=()):
    """A browser of engine `name` with a fake camera and microphone (Chromium's from
    `chromium_extra`, the others' own: a test pattern and a tone)."""
    if name == "chromium":
        return chromium(out, width, height, ["--use-fake-ui-for-media-stream", "--use-fake-device-for-media-stream",
                                             "--autoplay-policy=no-user-gesture-required", *chromium_extra])
    if name == "firefox":
        return FirefoxDriver(out, width, height)
    return webkit(width, height)


class Nginx:
    """Debian's nginx serving `root` on a free 127.0.0.1 port with the project's own site config
    (deploy/nginx/inkwire-products.conf, its listen and root lines replaced), as an unprivileged
    foreground process with its logs in `prefix`. `requests_since(offset)` reads the access log
    from a byte offset (`log_size()` now): [(path, status)]."""
    CONF = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "deploy", "nginx", "inkwire-products.conf")

    def __init__(self, root, prefix):
        import re
        import socket
        binary = shutil.which("nginx") or "/usr/sbin/nginx"
        if not os.path.exists(binary):
            skip("nginx is missing (scripts/packages.txt: nginx-light)")
        with socket.socket() as s:
            s.bind(("127.0.0.1", 0))
            self.port = s.getsockname()[1]
        os.makedirs(os.path.join(prefix, "logs"), exist_ok=True)
        site = open(self.CONF).read()
        site = re.sub(r"listen [^;]*;", f"listen 127.0.0.1:{self.port};", site)
        site = re.sub(r"root [^;]*;", f"root {root};", site)
        open(os.path.join(prefix, "site.conf"), "w").write(site)
        open(os.path.join(prefix, "nginx.conf"), "w").write(f"""daemon off; pid {prefix}/nginx.pid; error_log {prefix}/logs/error.log;
events {{ worker_connections 256; }}
http {{ access_log {prefix}/logs/access.log; client_body_temp_path {prefix}/tmp; proxy_temp_path {prefix}/tmp;
        include {prefix}/site.conf; }}
""")
        self.access_log = os.path.join(prefix, "logs", "access.log")
        self.process = subprocess.Popen([binary, "-p", prefix, "-c", os.path.join(prefix, "nginx.conf")],
                                        stderr=open(os.path.join(prefix, "stderr.log"), "w"))
        if wait_until(lambda: os.path.exists(self.access_log), 30, poll=0.05):
            return
        raise SystemExit(f"nginx did not start: {open(os.path.join(prefix, 'stderr.log')).read()}")

    def log_size(self):
        return os.path.getsize(self.access_log)

    def settled_log_size(self, quiet=1.0, longest=15.0):
        """log_size() once the log has not grown for `quiet` seconds (at most `longest`): nginx
        logs a request when it ends, so a page's fetches still in flight land before this."""
        end, size, since = time.time() + longest, self.log_size(), time.time()
        while time.time() < end and time.time() - since < quiet:
            time.sleep(0.1)
            if self.log_size() != size:
                size, since = self.log_size(), time.time()
        return size

    def requests_since(self, start):
        import re
        with open(self.access_log) as f:
            f.seek(start)
            return [(m.group(1), int(m.group(2))) for m in re.finditer(r'"GET ([^ ]*) HTTP/[0-9.]*" (\d+)', f.read())]

    def stop(self):
        self.process.terminate()
        self.process.wait(timeout=10)
