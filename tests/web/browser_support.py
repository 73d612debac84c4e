"""What the browser tests share beyond tests/support: a skip with a message when Debian's
chromium, chromium-driver or python3-selenium is missing, and headless Chromium with the flags
this machine needs."""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from inkwire_test import PROTOCOL_VERSION, Checks, Server, psnr, read_image, skip  # noqa: E402,F401  (re-exported for the tests)

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


def chromium(out, width, height, extra=()):
    """Headless Chromium; `extra` flags add to this machine's (e.g. fake camera and microphone)."""
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
    options.binary_location = "/usr/bin/chromium"
    return webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=options)
