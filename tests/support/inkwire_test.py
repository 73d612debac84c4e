"""What the Python end-to-end tests share (browser, window): a skip with a message, checks that
print one line each and a closing 'N passed, N failed', a real inkwire-server on 127.0.0.1 (its
TCP and HTTP ports read from its log), images read through oiiotool, and PSNR."""
import json
import math
import os
import subprocess
import sys
import time


# The wire protocol's version, as the C++ codec writes it in the golden frames the JS codec checks.
PROTOCOL_VERSION = json.load(open(os.path.join(os.path.dirname(__file__), "..", "golden", "protocol-frames.json")))["version"]


def wait_until(condition, timeout, poll=0.1, ignore=()):
    """Polls `condition` until it answers something true, and returns that answer; on timeout
    returns its last answer (false), for the check after it to say what was seen. The one way the
    tests wait: for a state, an event, a log line or a file, each with one generous timeout that
    a loaded machine does not reach, never for a fixed time. Exceptions of the `ignore` types
    count as "not yet" (a page still loading answers a script with an error)."""
    end = time.time() + timeout
    while True:
        try:
            value = condition()
        except ignore:
            value = None
        if value or time.time() >= end:
            return value
        time.sleep(poll)


def steady(read, still=0.5, timeout=60, poll=0.05):
    """`read()` once its answer has stopped changing (the same for `still` seconds: a fling or a
    stream of fetches has ended), within `timeout`: that answer."""
    end, value = time.time() + timeout, read()
    since = time.time()
    while time.time() < end and time.time() - since < still:
        time.sleep(poll)
        now = read()
        if now != value:
            value, since = now, time.time()
    return value


def skip(reason):
    print(f"SKIPPED: {reason}")
    sys.exit(0)


class Checks:
    def __init__(self):
        self.failures, self.count = [], 0

    def check(self, ok, what):
        print(("ok: " if ok else "FAILED: ") + what)
        self.count += 1
        if not ok:
            self.failures.append(what)

    def finish(self):
        print(f"{self.count - len(self.failures)} passed, {len(self.failures)} failed")
        sys.exit(1 if self.failures else 0)


class Server:
    """inkwire-server on free ports with `config` (JSON) and its data in `data`."""

    def __init__(self, bin_dir, out, data, config, name="server"):
        path = os.path.join(out, f"{name}.json")
        with open(path, "w") as f:
            json.dump(config, f)
        self.log = open(os.path.join(out, f"{name}.log"), "w+")
        self.process = subprocess.Popen([f"{bin_dir}/inkwire-server", "--listen", "127.0.0.1:0", "--data", data, "--config", path],
                                        stderr=self.log)
        self.tcp = self.http = 0

        def listening():
            for event in self.events():
                if event.get("event") == "listening":
                    self.tcp = event["port"]
                if event.get("event") == "http-listening":
                    self.http = event["port"]
            return self.tcp and (self.http or "http" not in config) or self.process.poll() is not None
        if not wait_until(listening, 60) or self.process.poll() is not None:
            raise SystemExit(f"the server did not start: {self.text()}")

    def events(self):
        self.log.seek(0)
        return [json.loads(line) for line in self.log if line.startswith("{")]

    def text(self):
        self.log.seek(0)
        return self.log.read()

    def stop(self):
        """Ends the server as an operator would (SIGTERM); one still draining its members after
        30 s (a browser's long-lived fetch holds its socket up to the idle deadline) is killed,
        so a test's end never hangs or leaves it running."""
        self.process.terminate()
        try:
            self.process.wait(timeout=30)
        except subprocess.TimeoutExpired:
            print(f"the server took over 30 s to stop: killed ({self.text().splitlines()[-1:]})")
            self.process.kill()
            self.process.wait(timeout=10)


def read_image(path, scratch):
    """(width, height, RGB bytes top row first) of an image, through OpenImageIO's oiiotool
    (Debian's openimageio-tools) writing an uncompressed TGA that a few lines can read."""
    tga_path = os.path.join(scratch, "tmp.tga")
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
