"""glint view's server: loopback by default, nothing of the file system, 4xx for bad or
huge requests, the command line's messages for bad settings, one render for every
client, abandoned passes, a port in use, and a clean stop on SIGTERM and SIGINT.

Usage: safety_test.py GLINT SCENE
"""
import os
import signal
import socket
import subprocess
import sys
import threading
import time

import numpy

from glintview import Server

GLINT, SCENE = sys.argv[1], sys.argv[2]
failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


def status_of(answer):
    """The status code of a raw HTTP answer, or None for no answer."""
    if not answer.startswith(b"HTTP/1."):
        return None
    return int(answer.split(b" ", 2)[1])


def listening_addresses(port):
    """Local addresses listening on `port`, from /proc/net/tcp and tcp6."""
    found = []
    for table in ("/proc/net/tcp", "/proc/net/tcp6"):
        try:
            lines = open(table).read().splitlines()[1:]
        except OSError:
            continue
        for line in lines:
            fields = line.split()
            address, hexport = fields[1].split(":")
            if int(hexport, 16) == port and fields[3] == "0A":  # LISTEN
                found.append(address)
    return found


server = Server(GLINT, SCENE, "--mode", "mc", "--size", "64", "--threads", "1")
try:
    server.wait_for_frame()

    # Loopback only unless --host says otherwise.
    check(server.host == "127.0.0.1", f"prints a loopback address ({server.host})")
    addresses = listening_addresses(server.port)
    check(addresses == ["0100007F"], f"listens on 127.0.0.1 only (/proc/net/tcp: {addresses})")

    # No request path reaches a file: every one of these is a 4xx without the file's text.
    probes = [
        "/../../../../etc/passwd", "/%2e%2e/%2e%2e/%2e%2e/etc/passwd",
        "/%2E%2E%2F%2E%2E%2Fetc%2Fpasswd", "/..%2f..%2f..%2fetc%2fpasswd",
        "/view.js/../../../../etc/passwd", "//etc/passwd", "/etc/passwd",
        "/api/../../CMakeLists.txt", "/../CMakeLists.txt", "/src/commands/view/view.js",
        "/CMakeLists.txt", "/scenes/cornell.json", "/api/scene.json/../../../etc/passwd",
        "/view.js%00.html", "/index.html/..", "/.%2e/.%2e/etc/passwd",
    ]
    for path in probes:
        answer = server.raw(f"GET {path} HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n"
                            .encode())
        code = status_of(answer)
        leaked = b"root:" in answer or b"cmake_minimum_required" in answer or b'"room"' in answer
        check(code is not None and 400 <= code < 500 and not leaked, f"GET {path}: {code}")
    answer = server.raw(b"GET http://127.0.0.1/etc/passwd HTTP/1.1\r\nHost: x\r\n"
                        b"Connection: close\r\n\r\n")
    check(b"root:" not in answer and (status_of(answer) or 400) >= 400,
          f"absolute-form request: {status_of(answer)}")

    # Malformed and huge requests: a 4xx (or the connection closed), never a crash.
    malformed = {
        "garbage": b"\x00\xff\x13garbage\r\n\r\n",
        "no version": b"GET /\r\n\r\n",
        "unknown version": b"GET / HTTP/9.9\r\n\r\n",
        "huge request line": b"GET /" + b"a" * 200000 + b" HTTP/1.1\r\nHost: x\r\n\r\n",
        "huge header": b"GET / HTTP/1.1\r\nHost: x\r\nX-Big: " + b"b" * 200000 + b"\r\n\r\n",
        "huge body": b"POST /api/settings HTTP/1.1\r\nHost: x\r\nContent-Length: 100000000\r\n"
                     b"Content-Type: application/x-www-form-urlencoded\r\n\r\n" + b"m" * 70000,
        "negative length": b"POST /api/settings HTTP/1.1\r\nHost: x\r\nContent-Length: -5\r\n\r\n",
        "bad chunk": b"POST /api/settings HTTP/1.1\r\nHost: x\r\nTransfer-Encoding: chunked\r\n"
                     b"\r\nzz\r\nmode=mc\r\n0\r\n\r\n",
        "unknown method": b"BREW /api/state HTTP/1.1\r\nHost: x\r\n\r\n",
        "settings by GET body": b"PUT /api/settings HTTP/1.1\r\nHost: x\r\nContent-Length: 7\r\n"
                                b"\r\nmode=mc",
    }
    for name, request in malformed.items():
        try:
            code = status_of(server.raw(request))
        except (ConnectionResetError, BrokenPipeError):
            code = None
        check(code is None or 400 <= code < 500, f"malformed ({name}): {code}")
    # cpp-httplib skips a header line that has no colon and answers the rest.
    code = status_of(server.raw(b"GET /api/state HTTP/1.1\r\nHost x\r\n\r\n"))
    check(code == 200, f"a header line without a colon is skipped: {code}")
    status, _, _ = server.get("/api/state")
    check(status == 200 and server.proc.poll() is None, "the server survived all of them")

    # The page's frames (RGBE) are the render's radiance (the PFM download) within 1%.
    for _ in range(20):
        _, h1, rgbe = server.get("/api/frame")
        _, h2, pfm = server.get("/api/image?format=pfm")
        if h1["X-Glint-Frame"] == h2["X-Glint-Frame"]:
            break
    b = numpy.frombuffer(rgbe, dtype=numpy.uint8).reshape(-1, 4).astype(float)
    decoded = numpy.where(b[:, 3:] > 0, (b[:, :3] + 0.5) * numpy.exp2(b[:, 3:] - 136), 0.0)
    header_end = pfm.index(b"\n", pfm.index(b"\n", 3) + 1) + 1
    linear = numpy.frombuffer(pfm[header_end:], dtype="<f4").reshape(64, 64, 3)[::-1]
    linear = linear.reshape(-1, 3).astype(float)
    top = numpy.maximum(linear.max(axis=1, keepdims=True), 1e-30)
    worst = float((numpy.abs(decoded - linear) / top).max())
    check(h1["X-Glint-Frame"] == h2["X-Glint-Frame"] and worst < 0.01,
          f"RGBE frames within 1% of the PFM (largest error {worst:.4f} of the pixel's largest channel)")

    # Bad parameters of the API get a 400 and a message.
    for path, words in [
        ("/api/tree?x=abc&y=1", "expected a whole number"),
        ("/api/tree?x=9999&y=1", "outside the image"),
        ("/api/tree?x=-1&y=1", "expected a whole number"),
        ("/api/image?format=gif", "expected png, pfm or exr"),
        ("/api/image?format=png&exposure=-1", "expected a positive number"),
    ]:
        status, body = server.json(path)
        check(status == 400 and words in body.get("error", ""), f"{path}: {status} {body}")

    # Bad settings get the command line's own message; the render goes on.
    for query, flags in [
        ("mode=mc&set=/objects/1/ior=0.5", ["--mode", "mc", "--set", "/objects/1/ior=0.5"]),
        ("mode=mc&set=/objects/9/ior=1.2", ["--mode", "mc", "--set", "/objects/9/ior=1.2"]),
        ("mode=whitted&walls=diffuse", ["--mode", "whitted", "--walls", "diffuse"]),
        ("mode=mc&walls=terminal&mirror-light=brdf",
         ["--mode", "mc", "--walls", "terminal", "--mirror-light", "brdf"]),
    ]:
        cli = subprocess.run([GLINT, "render", SCENE, "--size", "8", "-o", "/dev/null/x.png",
                              *flags], capture_output=True, text=True)
        expected = cli.stderr.strip().removeprefix("glint: ")
        status, body = server.json("/api/settings", query)
        check(status == 400 and body.get("error") == expected and cli.returncode == 1,
              f"POST {query}: {status} {body.get('error')!r} (command line: {expected!r})")
    for query, words in [("mode=film", "--mode film: expected whitted or mc"),
                         ("walls=soft", "--walls soft: expected terminal or diffuse"),
                         ("branches=0", "--branches 0: expected a whole number in [1, 64]"),
                         ("colour=red", "unknown setting 'colour'")]:
        status, body = server.json("/api/settings", query)
        check(status == 400 and words in body.get("error", ""), f"POST {query}: {body}")
    # A bad value never drops the query's good ones (#26): mode=mc is applied.
    status, body = server.json("/api/settings", "set=/objects/1/ior=0.5&mode=mc")
    applied = body.get("applied", {})
    check(status == 400 and "/objects/1/ior" in body.get("error", "") and
          applied.get("settings", {}).get("mode") == "mc" and applied["settings"]["set"] == [],
          f"a bad --set keeps mode=mc: {applied.get('settings')}")
    status, body = server.json("/api/settings", "walls=diffuse&mode=mc&branches=0")
    check(status == 400 and body["applied"]["settings"]["walls"] == "diffuse",
          f"walls=diffuse before mode=mc is kept: {body['applied']['settings']}")
    check(body["applied"]["scene"] == SCENE,
          f"the page's command line has the scene as given: {body['applied']['scene']}")
    # A slider's bad value falls back to its last good one; the other --set stay.
    server.json("/api/settings", "mode=mc&set=/objects/1/ior=1.1&set=/objects/0/exponent=20")
    status, body = server.json("/api/settings",
                               "mode=mc&set=/objects/1/ior=0.5&set=/objects/0/exponent=20")
    check(status == 400 and body["applied"]["settings"]["set"] ==
          ["/objects/1/ior=1.1", "/objects/0/exponent=20"],
          f"a bad slider value keeps the last good one: {body['applied']['settings']['set']}")
    status, body = server.json("/api/settings", "mode=whitted&set=")
    check(status == 200, f"back to Whitted: {status}")
    state = server.wait_for_frame()
    generation = state["generation"]

    # Two clients see the same render; a change by one is the other's too.
    results = []
    threads = [threading.Thread(target=lambda: results.append(server.json("/api/state")[1]))
               for _ in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    check(len(results) == 2 and results[0]["generation"] == results[1]["generation"],
          "two clients at once: the same generation")
    status, body = server.json("/api/settings", "mode=mc&set=/objects/1/ior=1.3")
    check(status == 200 and body["generation"] == generation + 1 and body["settings"]["set"] ==
          ["/objects/1/ior=1.3"], f"a change: generation {body.get('generation')}")
    state = server.wait_for_frame(after=state["frame"]["id"])
    check(state["generation"] == generation + 1, "the other client sees the new generation")
finally:
    code, seconds, rest = server.stop(signal.SIGTERM)
check(code == 0 and seconds < 1.0, f"SIGTERM: exit {code} after {seconds:.3f} s")

# With no page asking, the render rests after 10 s: the process goes back to idle (#26).
server = Server(GLINT, SCENE, "--size", "32", "--threads", "1")
try:
    server.wait_for_frame()
    time.sleep(11.0)  # LiveRender::kIdleSeconds and a margin; nothing asks meanwhile

    def cpu_seconds():
        with open(f"/proc/{server.proc.pid}/stat") as f:
            fields = f.read().rsplit(")", 1)[1].split()
        return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")

    before = cpu_seconds()
    time.sleep(2.0)
    idle = cpu_seconds() - before
    check(idle < 0.1, f"resting with no page: {idle:.3f} s of CPU in 2 s")
    _, state = server.json("/api/state")  # a page asks: rendering resumes
    frame = state["frame"]["id"]
    state = server.wait_for_frame(after=frame)
    check(state["status"] == "rendering", f"a page asked: {state['status']}, frame {frame} -> "
          f"{state['frame']['id']}")
finally:
    server.stop(signal.SIGTERM)

# --max-spp and --time stop the accumulation; the server stays (#26).
for flags, what in [(["--max-spp", "6"], "spp"), (["--time", "0.6"], "seconds")]:
    server = Server(GLINT, SCENE, "--size", "32", "--threads", "1", *flags)
    try:
        deadline = time.time() + 20
        state = {}
        while time.time() < deadline:
            _, state = server.json("/api/state")
            if state.get("status") == "done":
                break
            time.sleep(0.1)
        frame = state.get("frame", {})
        ok = state.get("status") == "done" and (
            frame.get("spp") == 6 if what == "spp" else 0.6 <= frame.get("seconds", 0) < 3.0)
        check(ok, f"{' '.join(flags)}: status {state.get('status')}, {frame.get('spp')} rays "
              f"per pixel, {frame.get('seconds')} s")
        time.sleep(0.5)
        _, later = server.json("/api/state")
        check(later["frame"]["id"] == frame.get("id"), f"{' '.join(flags)}: no pass after done")
    finally:
        server.stop(signal.SIGTERM)

# Long passes are abandoned, not finished, when the settings change.
server = Server(GLINT, SCENE, "--mode", "mc", "--walls", "diffuse", "--size", "64", "--spp",
                "1024", "--threads", "1")
try:
    time.sleep(0.5)  # the first pass (several seconds) is under way
    start = time.time()
    status, body = server.json("/api/settings", "mode=whitted&set=")
    state = server.wait_for_frame()
    waited = time.time() - start
    check(status == 200 and state["abandoned"] == 1 and state["generation"] == 2,
          f"a pass in flight abandoned ({state['abandoned']}); the new frame after {waited:.2f} s")
    # An idle connection left open does not hold the stop back.
    idle = socket.create_connection((server.host, server.port))
    idle.sendall(b"GET /api/state HTTP/1.1\r\nHost: x\r\n\r\n")
    idle.recv(65536)
finally:
    code, seconds, rest = server.stop(signal.SIGINT)
check(code == 0 and seconds < 1.0, f"SIGINT with a keep-alive connection open: exit {code} "
      f"after {seconds:.3f} s")

# With a reference, a setting that changes the image's size is refused (the compare
# views need the reference's size).
reference = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "data",
                         "whitted-cornell-64.pfm")
server = Server(GLINT, SCENE, "--set", "/camera/resolution=[64,64]", "--reference", reference,
                "--threads", "1")
try:
    server.wait_for_frame()
    status, body = server.json("/api/settings", "set=/camera/resolution=[32,32]")
    check(status == 400 and "--reference: expected an image of 32x32 pixels (the render's size), "
          "found 64x64" in body.get("error", ""), f"a size other than the reference's: {body}")
    status, state = server.json("/api/state")
    check(status == 200 and state["generation"] == 1, "the render goes on at 64x64")
finally:
    server.stop()

# A port in use: a clear error and exit code 1.
blocker = socket.socket()
blocker.bind(("127.0.0.1", 0))
blocker.listen()
port = blocker.getsockname()[1]
run = subprocess.run([GLINT, "view", SCENE, "--port", str(port)], capture_output=True,
                     text=True, timeout=30)
check(run.returncode == 1 and f"--port {port}: cannot listen on 127.0.0.1:{port} (Address "
      "already in use)" in run.stderr, f"port in use: exit {run.returncode}: {run.stderr.strip()}")
blocker.close()

print(f"{len(failures)} failure(s)")
sys.exit(1 if failures else 0)
