#!/usr/bin/env python3
"""A call in real headless browsers (SPEC F7-F11, W4): two Chromium members with fake cameras
and microphones (Debian's chromium, chromium-driver, python3-selenium) and one native
inkwire-client member, all on a real inkwire-server on 127.0.0.1.

Each member's camera is a clip made from real face photos that turn from neutral to a smile:
the Yale faces' development subjects from ../shared/data/yalefaces when they are there, else
two of libdlib's example photos (whose expression does not change: the smile checks are then
skipped with a message). The browsers' microphones speak sentences made by espeak-ng.
Checks: everyone joins and sees everyone; a browser member's smile arrives as a smile at the
other browser and at the native member (its frame log); one browser understands the other:
speech recognition (pocketsphinx, listening for either sentence's words) finds the other's words
in what it heard, not its own; mute stops the voice packets, camera off stops the crops, leave
removes the tile.
  call_browser_test.py BIN_DIR OUT_DIR
Skips with a message without chromium, chromedriver, selenium, espeak-ng, pocketsphinx or the
dlib photos."""
import array
import json
import os
import re
import shutil
import subprocess
import sys
import time
import wave

sys.path.insert(0, os.path.dirname(__file__))
from browser_support import Checks, Server, chromium, face_clip, skip, wait_until  # skips without the browser

BIN, OUT = sys.argv[1], sys.argv[2]
YALE = os.path.join(os.path.dirname(__file__), "..", "..", "..", "shared", "data", "yalefaces")
DLIB = "/usr/share/doc/libdlib19.1/examples/faces"
for tool in ("espeak-ng", "pocketsphinx_continuous"):
    if not shutil.which(tool):
        skip(f"{tool} is missing (scripts/setup.sh installs it)")
if not os.path.exists(os.path.join(DLIB, "2008_001322.jpg")):
    skip(f"libdlib-dev's example photos are missing ({DLIB})")
shutil.rmtree(OUT, ignore_errors=True)
os.makedirs(OUT)
checks = Checks()
yale = os.path.exists(os.path.join(YALE, "subject02_normal.png"))
if not yale:
    print("../shared/data/yalefaces is absent: libdlib's photos stand in and the smiles are not checked")


def speech(name, text, voice):
    path = os.path.join(OUT, f"{name}.wav")
    subprocess.run(["espeak-ng", "-v", voice, "-s", "150", "-w", path, text], check=True)
    return path


SENTENCES = {"ada": "Hello everybody. Can you all hear me? The weather is lovely today.",
             "bea": "Yes I can hear you. Shall we meet at the station at noon tomorrow?"}
# Each sentence's own content words (short words such as "I", "at" and "is" are what the
# recogniser hears in anything).
OWN_WORDS = {"ada": {"hello", "everybody", "weather", "lovely", "today"}, "bea": {"yes", "shall", "meet", "station", "noon", "tomorrow"}}
words_of = lambda text: re.findall(r"[a-z]+", text.lower())


def recognised(samples, rate, name):
    """The words pocketsphinx hears in `samples` (floats at `rate`), listening for the words of
    both sentences in any order and number: its general language model hears little in
    synthetic speech, and a choice between the two speakers' words is what the check needs."""
    path = os.path.join(OUT, f"{name}.wav")
    with wave.open(path, "wb") as w:
        w.setnchannels(1), w.setsampwidth(2), w.setframerate(rate)
        w.writeframes(array.array("h", [max(-32768, min(32767, int(x * 32768))) for x in samples]).tobytes())
    vocabulary = sorted(set(words_of(SENTENCES["ada"])) | set(words_of(SENTENCES["bea"])))
    grammar = os.path.join(OUT, "words.jsgf")
    with open(grammar, "w") as f:
        f.write("#JSGF V1.0;\ngrammar words;\npublic <s> = ( " + " | ".join(vocabulary) + " )* ;\n")
    out = subprocess.run(["pocketsphinx_continuous", "-infile", path, "-jsgf", grammar, "-logfn", "/dev/null"],
                         capture_output=True, text=True, check=True).stdout
    return words_of(out)


if yale:
    faces = {n: (os.path.abspath(os.path.join(YALE, f"subject{s}_normal.png")), os.path.abspath(os.path.join(YALE, f"subject{s}_happy.png")))
             for n, s in (("ada", "02"), ("bea", "05"), ("nat", "07"))}
else:
    faces = {n: (os.path.join(DLIB, f), os.path.join(DLIB, f)) for n, f in (("ada", "2008_001322.jpg"), ("bea", "2008_002079.jpg"), ("nat", "2009_004587.jpg"))}
clips = {n: face_clip(OUT, n, *faces[n]) for n in faces}
words = {"ada": speech("ada", SENTENCES["ada"], "en"), "bea": speech("bea", SENTENCES["bea"], "en+f3")}

server = Server(BIN, OUT, os.path.join(OUT, "data"), {"http": "127.0.0.1:0", "sessions": [{"name": "call", "kind": "conference"}]})
element = "document.querySelector('inkwire-call')"
drivers = {}
native = None
try:
    for name in ("ada", "bea"):
        driver = chromium(os.path.join(OUT, f"profile-{name}"), 640, 520,
                          ["--use-fake-ui-for-media-stream", "--use-fake-device-for-media-stream", f"--use-file-for-fake-video-capture={clips[name][1]}",
                           f"--use-file-for-fake-audio-capture={words[name]}", "--autoplay-policy=no-user-gesture-required"])
        driver.get(f"http://127.0.0.1:{server.http}/call/call")
        drivers[name] = driver
        # As a member does: the neutral photo taken while the face is neutral (the clip's first
        # three seconds; the next browser's start can take longer than that).
        wait_until(lambda: driver.execute_script(f"return {element}.preview.videoWidth > 0"), 60)
        driver.execute_script(f"return {element}.takePhoto()")
    ada, bea = drivers["ada"], drivers["bea"]
    # The native member publishes its camera only; it records what it sees and hears, for 60 s:
    # longer than the browsers take on a loaded machine, so it is still there when Bea leaves.
    native = subprocess.Popen([f"{BIN}/inkwire-client", "--connect", f"127.0.0.1:{server.tcp}", "--session", "call", "--name", "Nat",
                               "--camera", clips["nat"][0], "--headless", "--frames", "900", "--fps", "15", "--size", "480x240",
                               "--out", os.path.join(OUT, "nat.mp4"), "--audio-out", os.path.join(OUT, "nat-heard.wav"),
                               "--frame-log", os.path.join(OUT, "nat.jsonl"), "--cache", os.path.join(OUT, "cache-nat")],
                              stderr=open(os.path.join(OUT, "nat.log"), "w"))
    for name, driver in drivers.items():
        wait_until(lambda: driver.execute_script(f"return {element}.preview.videoWidth > 0"), 60)
        level = driver.execute_script(f"return {element}.level.value")
        checks.check(driver.execute_script(f"return {element}.preview.videoWidth") == 320, f"{name}: the camera's preview shows before joining")
        driver.execute_script(f"const e = {element}; e.nameInput.value = '{name.capitalize()}'; e.join(); e.link.record();")
    names = lambda d: sorted(m["name"] for m in d.execute_script(f"return {element}.members"))
    wait_until(lambda: names(ada) == ["Ada", "Bea", "Nat"] and names(bea) == ["Ada", "Bea", "Nat"], 60, poll=0.2)
    checks.check(all(d.execute_script(f"return {element}.hasAttribute('joined')") for d in drivers.values()), "both browsers are in the call ('joined')")
    checks.check(names(ada) == ["Ada", "Bea", "Nat"] and names(bea) == ["Ada", "Bea", "Nat"], f"everyone sees everyone: {names(ada)}, {names(bea)}")
    checks.check(level > -60, f"the microphone's level meter moved before joining ({level:.1f} dB)")
    wait_until(lambda: ada.execute_script(f"return {element}.firstFaceAt"), 60, poll=0.2)
    module_bytes, joined_at, first_face = ada.execute_script(f"const e = {element}; return [e.tiles.moduleBytes, e.joinedAt, e.firstFaceAt]")
    print(f"Ada's page: the renderer's module {module_bytes} bytes fetched in pre-join; joined {joined_at:.0f} ms after the page began, "
          f"the first face drawn {first_face - joined_at:.0f} ms after joining")

    # Smiles arrive as smiles (the clips smile from their fourth second on). Watched until every
    # smile has come (up to 45 s, while the native member is still in the call: on a loaded
    # machine the native member plays its clip slower than real time, and the analyst runs
    # behind); without the Yale faces, for as long as every member's expression took to show once.
    seen = {}
    keys = (("ada", "Bea"), ("bea", "Ada"), ("ada", "Nat"))
    def watched():
        for viewer, driver in drivers.items():
            for m in driver.execute_script(f"return {element}.members"):
                seen.setdefault((viewer, m["name"]), set()).add(m["expression"])
        return all(({"smile", "laugh"} if yale else {"neutral", "smile", "laugh", "surprise", "wink", "sad", "sleepy"}) & seen.get(key, set())
                   for key in keys)
    wait_until(watched, 45, poll=0.2)
    print("expressions seen:", {f"{v} sees {n}": sorted(e) for (v, n), e in seen.items()})
    if yale:
        checks.check("smile" in seen.get(("ada", "Bea"), set()) or "laugh" in seen.get(("ada", "Bea"), set()), "Bea's neutral then smile arrives at Ada as a smile")
        checks.check("smile" in seen.get(("bea", "Ada"), set()) or "laugh" in seen.get(("bea", "Ada"), set()), "Ada's smile arrives at Bea")
        checks.check("smile" in seen.get(("ada", "Nat"), set()) or "laugh" in seen.get(("ada", "Nat"), set()), "the native member's smile arrives in the browser")

    # Ada understands Bea: what she heard holds Bea's own words, not Ada's. (Bea's fake
    # microphone loops her sentence from her browser's start, so the call carries it at whatever
    # phase she joined; recognition does not mind where. On three runs here: 4-5 of Bea's six
    # words and at most one of Ada's; Ada's own sentence gives 5 of hers and 1 of Bea's.)
    # To the recogniser's 16 kHz from 48: each three samples averaged (a low-pass first, so what
    # lies above 8 kHz does not fold down into the speech as every third sample alone lets it).
    # On a busy machine the recogniser finds 2-6 of Bea's six words in one listen: when it finds
    # fewer than three, Ada listens 12 s of sound longer and all she heard is recognised again. Two of
    # Bea's words and more of hers than of Ada's own still say whose voice arrived (Ada's own
    # sentence gives 5 of hers and 1 of Bea's).
    # recording() hands over what was played since it was last asked: the page keeps every part.
    gather = f"""const r = await {element}.link.recording();
      if (r.sampleRate !== 48000) throw new Error(`played at ${{r.sampleRate}} Hz`);
      window.heardSoFar = [...(window.heardSoFar ?? []), r.samples];
      return window.heardSoFar.reduce((n, p) => n + p.length, 0);"""
    for listen in range(2):
        ada.execute_script(gather)
        heard = ada.execute_script("""const out = [];
          for (const s of window.heardSoFar) for (let i = 0; i + 2 < s.length; i += 3) out.push((s[i] + s[i + 1] + s[i + 2]) / 3);
          return out;""")
        got = recognised(heard, 16000, "ada-heard")
        beas, adas = sorted(OWN_WORDS["bea"] & set(got)), sorted(OWN_WORDS["ada"] & set(got))
        stats = ada.execute_script(f"return {element}.voiceStats")
        print(f"Ada heard ({stats['played']} packets played, {stats['late']} too late to play, delay {stats['delayMs']:.0f} ms):", " ".join(got))
        if len(beas) >= 3 or listen == 1:
            break
        wait_until(lambda: ada.execute_script(gather) >= len(heard) * 3 + 12 * 48000, 120, poll=0.5)
    checks.check(len(heard) > 16000 and len(beas) >= 2 and len(beas) > len(adas),
                 f"Ada hears Bea: in {len(heard) / 16000:.1f} s of sound, Bea's words {beas} (2 or more, more than her own), her own {adas}")

    # Mute stops voice packets; camera off stops crops; leave removes the tile. Once Ada's roster
    # shows Bea muted with her camera off (the server has heard so), Bea sends nothing while Ada,
    # speaking and seen, sends 30 voice packets and 15 pictures (the window whatever the load).
    bea.execute_script(f"{element}.setMuted(true); {element}.setCameraOff(true);")
    bea_entry = lambda: [m for m in ada.execute_script(f"return {element}.roster.members") if m["name"] == "Bea"]
    wait_until(lambda: bea_entry() and not bea_entry()[0]["microphone"] and not bea_entry()[0]["camera"], 60)
    checks.check(bool(bea_entry()) and not bea_entry()[0]["microphone"] and not bea_entry()[0]["camera"], "Ada sees Bea muted with her camera off")
    # The worker's own count, asked afresh (the page's copy of it is refreshed only now and then).
    sent = lambda d: d.execute_script(f"const e = {element}, f = await e.link.figures(); return [f.voiceSent, e.camera.sent]")
    voice0, crops0 = sent(bea)
    ada0 = sent(ada)
    wait_until(lambda: (lambda now: now[0] - ada0[0] >= 30 and now[1] - ada0[1] >= 15)(sent(ada)), 60, poll=0.2)
    voice1, crops1 = sent(bea)
    ada1 = sent(ada)
    checks.check(voice1 == voice0, f"muted, Bea sends no voice ({voice1 - voice0} packets while Ada sent {ada1[0] - ada0[0]})")
    checks.check(crops1 == crops0, f"camera off, Bea sends no crops ({crops1 - crops0} while Ada sent {ada1[1] - ada0[1]})")

    # Ada's connection is cut under her (as a lost network would): her page joins again by itself,
    # and Bea sees her back in one tile, under her number of before (the same tile). (How soon is
    # the bench's: call_first_face.py's rejoin_ms.)
    number_of = lambda d, name: [m["member"] for m in d.execute_script(f"return {element}.roster.members") if m["name"] == name]
    before = number_of(bea, "Ada")
    ada.execute_script(f"{element}.link.worker.postMessage({{ op: 'cut' }})")
    cut, gone = time.time(), False
    def back_again():
        global gone
        now = number_of(bea, "Ada")
        gone = gone or not now
        return gone and bool(now)
    wait_until(back_again, 60, poll=0.05)
    back = time.time() - cut
    checks.check(gone and number_of(bea, "Ada") == before,
                 f"Ada's cut connection: gone from Bea's roster and back (in {back:.1f} s) in one tile, number {number_of(bea, 'Ada')} (was {before})")
    checks.check(ada.execute_script(f"return {element}.hasAttribute('joined')"), "Ada's page is in the call again")
    # The native member's clip may have ended by now on a slow machine: it then left by itself.
    staying = ["Ada", "Nat"] if native.poll() is None else ["Ada"]
    bea.execute_script(f"{element}.hangUp()")
    wait_until(lambda: "Bea" not in names(ada), 60)
    checks.check(names(ada) == staying, f"Bea left: her tile is gone, the others stay ({names(ada)}, {staying} expected)")
    ada.save_screenshot(os.path.join(OUT, "ada-after-bea-left.png"))
    import urllib.request
    metrics = urllib.request.urlopen(f"http://127.0.0.1:{server.http}/metrics").read().decode()
    figures = {line.split()[0]: float(line.split()[1]) for line in metrics.splitlines() if line.startswith("inkwire_call_")}
    crops = figures.get("inkwire_call_crops_analysed_total", 0)
    if crops:
        print(f"the server analysed {crops:.0f} crops at {1000 * figures['inkwire_call_analysis_seconds_total'] / crops:.1f} ms each")
finally:
    for d in drivers.values():
        d.quit()
    if native:
        native.wait(timeout=90)
    server.stop()

log = [json.loads(line) for line in open(os.path.join(OUT, "nat.jsonl"))]
nat_saw = {m["name"]: set() for line in log for m in line.get("members", [])}
for line in log:
    for m in line.get("members", []):
        nat_saw[m["name"]].add(m["expression"])
print("the native member saw:", {n: sorted(e) for n, e in nat_saw.items()})
if yale:
    checks.check(bool({"smile", "laugh"} & nat_saw.get("Ada", set())), "the native member's frame log shows Ada's smile")
checks.check(native.returncode == 0 and os.path.getsize(os.path.join(OUT, "nat-heard.wav")) > 100000,
             "the native member recorded the call with its sound")
checks.finish()
