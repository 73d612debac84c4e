"""Many visitors' first views of one product at once, on the wire as a browser fetches them (the
`load` rows of the web benchmark, web_bench.py): over plain HTTP from a static host (nginx, or
the server's own /products/), the manifest, the first photo and its matte, on one kept-alive
connection where the host keeps it; or over the server's WebSocket as the element read products
before, hello, join, the snapshot and the two files in chunks. The element's scripts are left
out: the same files either way, and a CDN's. What is measured: visitors per second, each one's
time to its first view (p50, p99), and the CPU seconds the serving processes spent (read from
/proc), hence visitors per CPU second. The visitors run in this one Python process, apart from
the processes measured.

  visit_all(lambda: static_visit(port, "/truck", [photo_file, matte_file]), visitors, concurrency, pids) -> dict
  (the WebSocket path: lambda: websocket_visit(port, session, [(sha256, size), ...], protocol_version))"""
import asyncio
import os
import struct
import time

MAGIC = 0x574B4E49
HELLO, WELCOME, JOIN, SNAPSHOT, ASSET_REQUEST, ASSET_CHUNK, ERROR = 1, 2, 6, 8, 15, 16, 3
CHUNK = 64 * 1024


def cpu_seconds(pids):
    """User + system seconds of these processes (and their threads) so far."""
    tick = os.sysconf("SC_CLK_TCK")
    total = 0.0
    for pid in pids:
        with open(f"/proc/{pid}/stat") as f:
            fields = f.read().rsplit(")", 1)[1].split()
        total += (int(fields[11]) + int(fields[12])) / tick  # utime, stime
    return total


async def http_get(reader, writer, host, path):
    """One GET on an open connection: (status, body bytes, whether the host keeps it open)."""
    writer.write(f"GET {path} HTTP/1.1\r\nHost: {host}\r\nAccept-Encoding: gzip\r\n\r\n".encode())
    head = await reader.readuntil(b"\r\n\r\n")
    lines = head.decode("latin-1").split("\r\n")
    status = int(lines[0].split()[1])
    headers = {k.strip().lower(): v.strip() for k, _, v in (line.partition(":") for line in lines[1:] if line)}
    if headers.get("transfer-encoding", "").lower() == "chunked":  # nginx's way with what it gzips as it sends
        body = b""
        while True:  # each chunk: its size in hex, CRLF, the bytes, CRLF; a last one of size 0
            size = int((await reader.readuntil(b"\r\n")).split(b";")[0], 16)
            body += (await reader.readexactly(size + 2))[:size]
            if size == 0:
                break
    else:
        body = await reader.readexactly(int(headers.get("content-length", "0")))
    return status, body, headers.get("connection", "").lower() != "close"


async def static_visit(port, path, files):
    """The manifest and the files of a first view over HTTP/1.1, reconnecting where the host closes:
    (bytes received, requests)."""
    host = f"127.0.0.1:{port}"
    reader = writer = None
    received = requests = 0
    try:
        for name in ["product.json"] + files:
            if writer is None:
                reader, writer = await asyncio.open_connection("127.0.0.1", port)
            status, body, kept = await http_get(reader, writer, host, f"{path}/{name}")
            requests += 1
            if status != 200:
                raise RuntimeError(f"{path}/{name} answered {status}")
            received += len(body)
            if not kept:
                writer.close()
                reader = writer = None
    finally:
        if writer:
            writer.close()
    return received, requests


def message(kind, payload):
    return struct.pack("<IH", len(payload), kind) + payload


def text(s):
    b = s.encode()
    return struct.pack("<H", len(b)) + b


async def websocket_visit(port, session, assets, protocol_version):
    """hello, join, the snapshot, then each asset (hash hex, size) in chunks, as the element did:
    (bytes received, messages sent)."""
    import websockets
    received, requests = 0, 2  # hello and join, then each asset request
    async with websockets.connect(f"ws://127.0.0.1:{port}/ws", ping_interval=None, max_size=2**20,
                                  origin=f"http://127.0.0.1:{port}") as ws:
        await ws.send(message(HELLO, struct.pack("<IH", MAGIC, protocol_version) + text("load")))
        await ws.send(message(JOIN, text(session) + text("") + b"\0"))  # session, token, open_room
        wanted = {bytes.fromhex(h): size for h, size in assets}
        have = {h: 0 for h in wanted}
        asked = False
        while any(have[h] < wanted[h] for h in wanted):
            frame = await asyncio.wait_for(ws.recv(), 30)
            received += len(frame)
            kind = struct.unpack_from("<H", frame, 4)[0]
            if kind == ERROR:
                raise RuntimeError(f"the server refused the visit: {frame[9:].decode(errors='replace')}")
            if kind == SNAPSHOT and not asked:
                asked = True
                for h, size in wanted.items():
                    for offset in range(0, size, CHUNK):
                        await ws.send(message(ASSET_REQUEST, h + struct.pack("<QI", offset, min(CHUNK, size - offset))))
                        requests += 1
            elif kind == ASSET_CHUNK:
                h = frame[6:38]
                (length,) = struct.unpack_from("<I", frame, 46)
                have[h] = have.get(h, 0) + length
    return received, requests


async def visit_all_async(visit, visitors, concurrency):
    times, failures, received, requests = [], [], 0, 0
    queue = iter(range(visitors))

    async def worker():
        nonlocal received, requests
        for _ in queue:
            start = time.perf_counter()
            try:
                got, asked = await visit()  # (not `received += await ...`: that reads `received` before the wait)
                received += got
                requests += asked
                times.append(time.perf_counter() - start)
            except Exception as error:  # a refused or broken visit counts as a failure, not a time
                failures.append(str(error))

    start = time.perf_counter()
    await asyncio.gather(*(worker() for _ in range(concurrency)))
    return time.perf_counter() - start, times, failures, received, requests


def visit_all(visit, visitors, concurrency, pids):
    """Runs `visitors` first views (`visit`, an async function returning the bytes it received and
    the requests it made),
    `concurrency` at once, measuring the processes `pids`."""
    cpu_before = cpu_seconds(pids)
    wall, times, failures, received, requests = asyncio.run(visit_all_async(visit, visitors, concurrency))
    cpu = cpu_seconds(pids) - cpu_before
    times.sort()
    pick = lambda p: 1000 * times[min(len(times) - 1, int(p * len(times)))] if times else None
    return {"visitors": visitors, "failed": len(failures), "visitors_per_second": len(times) / wall,
            "requests_per_second": requests / wall, "p50_ms": pick(0.5), "p99_ms": pick(0.99), "cpu_seconds": cpu,
            "cpu_ms_per_visitor": 1000 * cpu / max(1, len(times)), "visitors_per_cpu_second": len(times) / cpu if cpu > 0 else None,
            "bytes_per_visitor": received / max(1, len(times)), "first_failure": failures[0] if failures else ""}
