"""The server's WebSocket against a client library that keeps RFC 6455 strictly (Debian's
python3-websockets): a Ping gets a Pong with its data (5.5.2), a Close is echoed with its status
code (5.5.1), and connections the server ends carry a code that says why: 1002 for a protocol
error (a text message), 1009 for a message over the frame limit. Each leaves another member
served. Skips with a message without python3-websockets.

usage: websocket_rfc_test.py BIN_DIR OUT_DIR"""
import asyncio
import os
import struct
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from inkwire_test import PROTOCOL_VERSION, Checks, Server, skip  # noqa: E402

try:
    import websockets
except ImportError:
    skip("python3-websockets is not installed (scripts/setup.sh installs it)")

MAGIC, VERSION = 0x574B4E49, PROTOCOL_VERSION
HELLO, WELCOME, ERROR, JOIN, SNAPSHOT = 1, 2, 3, 6, 8


def frame(kind, payload):
    return struct.pack("<IH", len(payload), kind) + payload


def text(s):
    b = s.encode()
    return struct.pack("<H", len(b)) + b


def hello(name):
    return frame(HELLO, struct.pack("<IH", MAGIC, VERSION) + text(name))


def kind_of(message):
    return struct.unpack_from("<H", message, 4)[0]


async def greeted(url, name):
    ws = await websockets.connect(url, ping_interval=None, max_size=2**20)
    await ws.send(hello(name))
    answer = await asyncio.wait_for(ws.recv(), 5)
    assert kind_of(answer) == WELCOME, f"expected welcome, got type {kind_of(answer)}"
    return ws


async def closing_code(ws):
    """Reads until the server closes; the status code of its Close frame."""
    try:
        while True:
            await asyncio.wait_for(ws.recv(), 5)
    except websockets.ConnectionClosed as closed:
        return closed.rcvd.code if closed.rcvd else None


async def main(checks, url):
    bystander = await greeted(url, "bystander")
    await bystander.send(frame(JOIN, text("cows") + text("") + b"\0"))  # session, token, open_room
    snapshot = await asyncio.wait_for(bystander.recv(), 5)
    checks.check(kind_of(snapshot) == SNAPSHOT, "a member joins over WebSocket and gets the snapshot")

    ws = await greeted(url, "pinger")
    try:
        pong = await ws.ping(b"are you there")
        await asyncio.wait_for(pong, 5)
        checks.check(True, "a Ping is answered with a Pong carrying its data")
    except asyncio.TimeoutError:
        checks.check(False, "a Ping is answered with a Pong carrying its data (none within 5 s)")
    await ws.close(code=4001, reason="bye")
    checks.check(ws.close_code == 4001, f"a Close is echoed with its status code (got {ws.close_code})")

    ws = await greeted(url, "texter")
    await ws.send("hello as text")
    code = await closing_code(ws)
    checks.check(code == 1002, f"a text message ends the connection with 1002, protocol error (got {code})")

    ws = await greeted(url, "flooder")
    await ws.send(b"\0" * (200 * 1024))
    code = await closing_code(ws)
    checks.check(code == 1009, f"a message over the frame limit ends the connection with 1009, too big (got {code})")

    pong = await bystander.ping(b"still here")
    await asyncio.wait_for(pong, 5)
    checks.check(bystander.open, "the member who did nothing wrong is still served")
    await bystander.close()


if __name__ == "__main__":
    bin_dir, out = sys.argv[1], sys.argv[2]
    os.makedirs(out, exist_ok=True)
    config = {"http": "127.0.0.1:0", "sessions": [{"name": "cows", "kind": "scene", "assets": []}]}
    server = Server(bin_dir, out, os.path.join(out, "data"), config)
    checks = Checks()
    try:
        asyncio.run(main(checks, f"ws://127.0.0.1:{server.http}/ws"))
    finally:
        server.stop()
    checks.finish()
