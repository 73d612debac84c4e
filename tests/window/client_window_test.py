"""The windowed client as a person meets it, under a display (xvfb-run in CI): a real server, a
real GLFW window on llvmpipe, real key presses (xdotool, through the X server's XTEST) and the
screen grabbed by ffmpeg's x11grab. Checks that Tab and Shift-Tab switch the style on screen,
that an arrow key turns the view, that the docked panel covers at most 35% of a 640x480 window
by default, and that an idle window of a still style draws nothing (what it costs a core is the
bench's: `inkwire-bench --suite window` runs this script with --bench ROWS.json). On a
product: P presents the window's view (a client that follows shows it), F follows a presenter;
on a product in three rows the Up and Down arrows step a row and a drag down turns the view up,
no further than the top row. In a scene whose editor is someone else, the window knows from
joining that it may not steer: Tab, the arrows and a drag change nothing, and the panel says why.

Each step waits until the window has taken in the input it was given (a resize queued behind it
shows in its frame log), not for a fixed time.

Usage: client_window_test.py BIN_DIR OUT_DIR [--bench ROWS.json]   (skips with a message without
a display, xdotool or ffmpeg)."""
import json
import os
import shutil
import subprocess
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from inkwire_test import Checks, Server, psnr, read_image, skip, steady, wait_until  # noqa: E402

BIN, OUT = sys.argv[1], sys.argv[2]
BENCH = sys.argv[sys.argv.index("--bench") + 1] if "--bench" in sys.argv else None
if not os.environ.get("DISPLAY"):
    skip("no DISPLAY: run under xvfb-run (scripts/test.sh does)")
for tool in ("xdotool", "ffmpeg", "oiiotool"):
    if not shutil.which(tool):
        skip(f"{tool} is missing (scripts/setup.sh installs it)")
shutil.rmtree(OUT, ignore_errors=True)
os.makedirs(OUT)
MESH = os.path.join(BIN, "..", "packaged-data", "data", "meshes", "cow.off")
WIDTH, HEIGHT = 640, 480


def log_lines(path):
    with open(path) as f:
        return [json.loads(line) for line in f if line.strip()]


def wait_for(predicate, seconds, what):
    end = time.time() + seconds
    while time.time() < end:
        value = predicate()
        if value:
            return value
        time.sleep(0.2)
    raise SystemExit(f"timed out waiting for {what}")


def taken_in(log, what):
    """Waits until the window has taken in every input sent so far, and returns its frame log's
    last line then: the window is made a pixel taller and back (X requests queued behind the
    input, so the window meets them after it), and the frame log shows each size in turn."""
    for height in (HEIGHT + 1, HEIGHT):
        window = subprocess.run(["xdotool", "search", "--sync", "--onlyvisible", "--pid", str(client.pid)], check=True, capture_output=True,
                                text=True).stdout.split()[0]
        subprocess.run(["xdotool", "windowsize", window, str(WIDTH), str(height)], check=True)
        line = wait_for(lambda: (lambda lines: lines and lines[-1]["window"] == [WIDTH, height] and lines[-1])(log_lines(log)), 60, what)
    return line


def cpu_seconds(pid):
    with open(f"/proc/{pid}/stat") as f:
        fields = f.read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def grab(name):
    """The window's picture as the screen shows it (the window sits at the screen's corner)."""
    path = os.path.join(OUT, name)
    subprocess.run(["ffmpeg", "-loglevel", "error", "-y", "-f", "x11grab", "-video_size", f"{WIDTH}x{HEIGHT}",
                    "-i", os.environ["DISPLAY"] + "+0,0", "-frames:v", "1", path], check=True)
    return read_image(path, OUT)


def grab_until(name, shows, what):
    """grab() until the picture `shows` what is wanted (the screen catches up with the window's
    last frame), within a generous timeout: the last grab."""
    image = None
    def grabbed():
        nonlocal image
        image = grab(name)
        return shows(image)
    wait_until(grabbed, 30, poll=0.2)
    return image


def key(*keys):
    subprocess.run(["xdotool", "key", "--delay", "50", *keys], check=True)


checks = Checks()
config = {"sessions": [{"name": "look", "kind": "scene", "style": "comic",
                        "assets": [{"path": os.path.abspath(MESH), "kind": "mesh"}]},
                       {"name": "lecture", "kind": "scene", "style": "comic", "editor_token": "t3acher",
                        "assets": [{"path": os.path.abspath(MESH), "kind": "mesh"}]}]}
DUCK = "/usr/share/assimp/models/Collada/duck.dae"
EDITOR = "sh0p-0wner"  # the product's editor token: only its editors present
if os.path.exists(DUCK):  # a product for presenter mode, made as a shop owner would
    subprocess.run([f"{BIN}/inkwire-server", "add-product", "duck", "--mesh", DUCK, "--samples", "12", "--size", "128",
                    "--data", os.path.join(OUT, "data"), "--editor-token", EDITOR], check=True, stdout=subprocess.DEVNULL)
    # Three rows of six photos, at 0, 25 and 50 degrees up (SPEC T17).
    for row, elevation in enumerate((0, 25, 50), start=1):
        folder = os.path.join(OUT, "rows", f"row{row}")
        os.makedirs(folder)
        subprocess.run([f"{BIN}/inkwire-render", "--mesh", DUCK, "--view", f"0,{elevation},1.4", "--frames", "6", "--size", "128x128",
                        "--backdrop", "#ffffff", "--out", os.path.join(folder, "IMG_%04d.png")], check=True, stdout=subprocess.DEVNULL)
    subprocess.run([f"{BIN}/inkwire-server", "add-product", "rows", "--photos", os.path.join(OUT, "rows"), "--step", "-60",
                    "--elevations", "0,25,50", "--data", os.path.join(OUT, "data")], check=True, stdout=subprocess.DEVNULL)
server = Server(BIN, OUT, os.path.join(OUT, "data"), config)
env = dict(os.environ, XDG_CONFIG_HOME=os.path.join(OUT, "config"))  # the panel's first-run state
client_log = open(os.path.join(OUT, "client.log"), "w")
client = None


def open_window(session, log, *flags):
    """A window on `session` in place of the one before (if any); its frame log's path."""
    global client
    if client:
        client.terminate()
        client.wait(timeout=10)
    path = os.path.join(OUT, log)
    client = subprocess.Popen([f"{BIN}/inkwire-client", "--connect", f"127.0.0.1:{server.tcp}", "--session", session, *flags,
                               "--size", f"{WIDTH}x{HEIGHT}", "--cache", os.path.join(OUT, "cache"), "--frame-log", path],
                              stderr=client_log, env=env)
    return path


frame_log = open_window("look", "frames.jsonl")
try:
    wait_for(lambda: os.path.exists(frame_log) and any(line["style"] == "comic" for line in log_lines(frame_log)), 60, "the first frame")
    subprocess.run(["xdotool", "mousemove", "5", "5"], check=True)  # over the picture, not the panel
    first = taken_in(frame_log, "the window to take the pointer in")
    panel, window = first["panel"], first["window"]
    share = panel["width"] * panel["height"] / (window[0] * window[1])
    checks.check(window == [WIDTH, HEIGHT], f"the window is {WIDTH}x{HEIGHT} ({window})")
    checks.check(0 < share <= 0.35 and not panel["folded"], f"the panel covers {share:.1%} of the window by default (<= 35%)")
    checks.check(panel["x"] + panel["width"] >= WIDTH - 1, f"the panel is docked to the right edge (x {panel['x']}, width {panel['width']})")
    comic = grab("1-comic.png")

    # Idle: a still style, nothing moving, nobody typing: the window draws nothing (it waits for
    # events). Five seconds of looking; what a core it costs meanwhile is the bench's figure.
    steady(lambda: len(log_lines(frame_log)))  # the frames it draws after the last input are drawn
    frames_before, cpu_before, idle_start = len(log_lines(frame_log)), cpu_seconds(client.pid), time.time()
    time.sleep(5.0)
    idle_cpu = (cpu_seconds(client.pid) - cpu_before) / (time.time() - idle_start)
    idle_frames = len(log_lines(frame_log)) - frames_before
    print(f"an idle window used {idle_cpu:.1%} of a core over {time.time() - idle_start:.1f} s")
    checks.check(idle_frames == 0, f"an idle window of a still style draws nothing ({idle_frames} frames in 5 s)")
    if BENCH:
        with open(BENCH, "w") as f:
            json.dump({"rows": [{"variant": "idle,style=comic", "counters": {"idle_cpu_fraction": idle_cpu, "idle_frames": idle_frames,
                                                                             "seconds": time.time() - idle_start}}]}, f)

    key("Tab")
    after_tab = wait_for(lambda: [line for line in log_lines(frame_log) if line["style"] != "comic"], 10, "a style change after Tab")[-1]
    checks.check(after_tab["style"] == "comic-extended", f"Tab switches to the next style (comic -> {after_tab['style']})")
    # The session's answer comes after the key: the window has drawn the new style once a frame
    # of it is logged (each line is written after its frame is shown).
    extended = grab_until("2-after-tab.png", lambda image: psnr(comic, image) < 40, "the new style on screen")
    checks.check(psnr(comic, extended) < 40, f"the picture on screen changes after Tab (PSNR {psnr(comic, extended):.1f} dB against before, < 40)")

    key("shift+Tab")
    back = wait_for(lambda: [line for line in log_lines(frame_log)[-3:] if line["style"] == "comic"], 10, "a style change after Shift-Tab")[-1]
    checks.check(back["style"] == "comic", "Shift-Tab switches back to the previous style")
    again = grab_until("3-after-shift-tab.png", lambda image: psnr(comic, image) > 30, "the first style on screen again")
    checks.check(psnr(comic, again) > 30, f"back in the first style the picture is the first one again (PSNR {psnr(comic, again):.1f} dB, > 30)")

    key("Right", "Right")
    taken_in(frame_log, "the window to take the arrows in")
    turned = grab_until("4-after-right.png", lambda image: psnr(again, image) < 30, "the turned view on screen")
    checks.check(psnr(again, turned) < 30, f"two Right arrows turn the view (PSNR {psnr(again, turned):.1f} dB against before, < 30)")

    # A scene whose editor is someone else: the server says on joining what this member may not
    # change; the window's Tab and drag do nothing and its panel says why.
    lecture_log = open_window("lecture", "lecture.jsonl")
    wait_for(lambda: os.path.exists(lecture_log) and any(line.get("may_not") for line in log_lines(lecture_log)), 60, "the lecture's permissions")
    subprocess.run(["xdotool", "mousemove", "5", "5"], check=True)
    may_not = taken_in(lecture_log, "the window to take the pointer in")["may_not"]
    checks.check({"style-change", "camera-pose"} <= set(may_not), f"the window knows from joining what it may not change: {', '.join(may_not)}")
    still = grab("5-lecture.png")
    key("Tab", "Right", "Right")
    subprocess.run(["xdotool", "mousemove", "--sync", "200", "200", "sleep", "0.3", "mousedown", "1", "mousemove", "--sync", "100", "200",
                    "mouseup", "1"], check=True)
    subprocess.run(["xdotool", "mousemove", "5", "5"], check=True)  # the pointer where it was for the first picture
    last = taken_in(lecture_log, "the window to take the keys and the drag in")
    after = grab("6-lecture-after-keys.png")
    checks.check(last["style"] == "comic" and "refused" not in last, f"Tab changes nothing and nothing is refused ({last['style']})")
    # The picture left of the panel (whose title shows focus), before and after.
    def picture(image, right=int(last["panel"]["x"])):
        width, height, rgb = image
        return (right, height, b"".join(rgb[y * width * 3:(y * width + right) * 3] for y in range(height)))
    moved = psnr(picture(still), picture(after))
    checks.check(moved > 40, f"neither the arrows nor a drag move a follower's view (PSNR {moved:.1f} dB, > 40)")

    if not os.path.exists(DUCK):
        print(f"skipped presenter mode: {DUCK} is missing (assimp-testmodels)")
    else:
        product_log = open_window("duck", "product.jsonl", "--token", EDITOR)
        wait_for(lambda: os.path.exists(product_log) and any(line["product"]["samples_loaded"] == 12 for line in log_lines(product_log)),
                 60, "the product in the window")

        def headless(name, *flags):
            log = os.path.join(OUT, f"{name}.jsonl")
            subprocess.run([f"{BIN}/inkwire-client", "--connect", f"127.0.0.1:{server.tcp}", "--session", "duck", "--headless",
                            "--size", "128x128", "--wait-for-product", "--out", os.path.join(OUT, f"{name}-%04d.png"),
                            "--frame-log", log, "--cache", os.path.join(OUT, "cache"), *flags], check=True, stderr=client_log)
            return log_lines(log)[-1]["product"]["azimuth"]

        def window_azimuth():
            return log_lines(product_log)[-1]["product"]["azimuth"]

        on_the_circle = lambda degrees: (degrees + 180) % 360 - 180
        key("p", "Right")  # present, then step one photo (30 degrees)
        taken_in(product_log, "the window to take P and Right in")
        followed = headless("follower", "--frames", "1", "--follow")
        checks.check(abs(on_the_circle(window_azimuth() - 30)) < 0.01 and abs(on_the_circle(followed - window_azimuth())) < 0.01,
                     f"P presents the window's view: a client that follows shows {followed:.1f} degrees, the window {window_azimuth():.1f}")
        key("p", "f")  # stop presenting, follow
        taken_in(product_log, "the window to take P and F in")
        presented = headless("presenter", "--frames", "5", "--fps", "10", "--view", "200", "--present", "--token", EDITOR)
        wait_until(lambda: abs(on_the_circle(window_azimuth() - presented)) < 0.01, 30)
        checks.check(abs(on_the_circle(window_azimuth() - presented)) < 0.01,
                     f"F follows: the window turned to {window_azimuth():.1f} degrees, the presenter's {presented:.1f}")

        # Rows: Up and Down step a row; a drag down turns the view up, as far as the top row.
        rows_log = open_window("rows", "rows.jsonl")
        wait_for(lambda: os.path.exists(rows_log) and any(line["product"]["samples_loaded"] == 18 for line in log_lines(rows_log)),
                 60, "the product in rows in the window")
        elevation = lambda: log_lines(rows_log)[-1]["product"]["elevation"]
        key("Up")
        taken_in(rows_log, "the window to take Up in")
        checks.check(abs(elevation() - 25) < 0.01, f"Up steps one row up: {elevation():.1f} degrees (25)")
        key("Down", "Down")
        taken_in(rows_log, "the window to take Down in")
        checks.check(abs(elevation()) < 0.01, f"Down twice: the lowest row, and no further: {elevation():.1f} degrees (0)")
        # A quick drag turns as far as a slow one: the moves queued behind the press count too.
        subprocess.run(["xdotool", "mousemove", "--sync", "200", "150", "sleep", "0.3", "mousedown", "1", "mousemove", "--sync", "200", "200",
                        "mousemove", "--sync", "200", "250", "mouseup", "1"], check=True)
        taken_in(rows_log, "the window to take the drag in")
        checks.check(abs(elevation() - 40) < 0.01, f"a drag of 100 pixels down turns the view 40 degrees up: {elevation():.1f}")
        subprocess.run(["xdotool", "mousemove", "--sync", "200", "100", "sleep", "0.3", "mousedown", "1", "mousemove", "--sync", "200", "300",
                        "mouseup", "1"], check=True)
        taken_in(rows_log, "the window to take the drag in")
        checks.check(abs(elevation() - 50) < 0.01, f"dragged further, the view stops at the top row: {elevation():.1f} degrees (50)")
finally:
    client.terminate()
    client.wait(timeout=10)
    server.stop()
checks.finish()
