"""Debian's headless Chromium through selenium with the flags this machine needs (software WebGL2
through SwiftShader, no first-run noise), for the demo's browser scripts."""
import os

from selenium import webdriver
from selenium.webdriver.chrome.service import Service


def chromium(profile, width, height):
    options = webdriver.ChromeOptions()
    for a in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run", "--disable-background-networking",
              "--disable-component-update", "--disable-sync", "--force-device-scale-factor=1", f"--window-size={width},{height}",
              f"--user-data-dir={profile}", "--use-angle=swiftshader", "--enable-unsafe-swiftshader"):
        options.add_argument(a)
    options.binary_location = "/usr/bin/chromium"
    return webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=options)
