"""Helpers of glint view's tests: start the server, ask it over HTTP, drive Chromium.

Chromium (Debian `chromium`, tools/setup.sh --dev) is driven through the DevTools
protocol with python3-websocket: no other dependency.
"""
import base64
import io
import json
import os
import re
import shutil
import signal
import socket
import subprocess
import tempfile
import time
import urllib.error
import urllib.request

import websocket  # python3-websocket

# Never through a proxy: the server is on this machine.
_OPENER = urllib.request.build_opener(urllib.request.ProxyHandler({}))


class Server:
    """`glint view SCENE ARGS --port 0`, stopped with SIGTERM."""

    def __init__(self, glint, scene, *args):
        self.proc = subprocess.Popen([glint, "view", scene, "--port", "0", *args],
                                     stderr=subprocess.PIPE, text=True)
        line = self.proc.stderr.readline()
        match = re.search(r"glint view: http://([0-9.]+):(\d+)/", line)
        if not match:
            self.proc.kill()
            raise RuntimeError(f"glint view did not say where it listens: {line!r}")
        self.host, self.port = match.group(1), int(match.group(2))
        self.url = f"http://{self.host}:{self.port}"

    def get(self, path, data=None, timeout=10):
        """(status, headers, body) of one request; a 4xx or 5xx is an answer too."""
        request = urllib.request.Request(self.url + path,
                                         data=data.encode() if data is not None else None)
        try:
            with _OPENER.open(request, timeout=timeout) as r:
                return r.status, dict(r.headers), r.read()
        except urllib.error.HTTPError as e:
            return e.code, dict(e.headers), e.read()

    def json(self, path, data=None):
        status, _, body = self.get(path, data)
        return status, json.loads(body)

    def wait_for_frame(self, after=0, timeout=20):
        deadline = time.time() + timeout
        while time.time() < deadline:
            _, state = self.json("/api/state")
            if "frame" in state and state["frame"]["id"] > after:
                return state
            time.sleep(0.05)
        raise AssertionError("no frame within %g s" % timeout)

    def raw(self, request_bytes, timeout=3):
        """Sends bytes as they are and returns the answer (b'' if the server closed the
        connection without one): the headers and as much body as they announce."""
        with socket.create_connection((self.host, self.port), timeout=timeout) as s:
            try:
                s.sendall(request_bytes)
            except (BrokenPipeError, ConnectionResetError):
                pass  # the server may answer before it has read everything
            data = b""
            try:
                while True:
                    head, sep, body = data.partition(b"\r\n\r\n")
                    if sep:
                        length = re.search(rb"(?i)content-length: *(\d+)", head)
                        if len(body) >= (int(length.group(1)) if length else 0):
                            return data
                    chunk = s.recv(65536)
                    if not chunk:
                        return data
                    data += chunk
            except (socket.timeout, ConnectionResetError):
                return data

    def stop(self, sig=signal.SIGTERM):
        """Sends `sig`; returns (exit code, seconds it took, the rest of stderr)."""
        start = time.time()
        self.proc.send_signal(sig)
        try:
            code = self.proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            code = self.proc.wait()
        seconds = time.time() - start
        return code, seconds, self.proc.stderr.read()


class Browser:
    """Headless Chromium with one page, driven through the DevTools protocol."""

    def __init__(self, width=1400, height=1100):
        exe = shutil.which("chromium")
        if exe is None:
            raise RuntimeError("chromium is not installed (tools/setup.sh --dev installs it)")
        self.profile = tempfile.mkdtemp(prefix="glint-chromium-")
        self.proc = subprocess.Popen(
            [exe, "--headless=new", "--no-sandbox", "--disable-gpu", "--no-first-run",
             "--no-default-browser-check", "--remote-debugging-port=0",
             "--remote-allow-origins=*", f"--user-data-dir={self.profile}",
             f"--window-size={width},{height}", "about:blank"],
            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        port_file = os.path.join(self.profile, "DevToolsActivePort")
        deadline = time.time() + 60
        while not (os.path.exists(port_file) and open(port_file).read().count("\n") >= 1):
            if time.time() > deadline or self.proc.poll() is not None:
                raise RuntimeError("chromium did not start its DevTools server")
            time.sleep(0.1)
        port = int(open(port_file).read().split()[0])
        targets = json.loads(_OPENER.open(f"http://127.0.0.1:{port}/json/list", timeout=10).read())
        page = next(t for t in targets if t["type"] == "page")
        self.ws = websocket.create_connection(page["webSocketDebuggerUrl"], timeout=60,
                                              suppress_origin=True)
        self.next_id = 0
        self.console = []
        self.call("Runtime.enable")
        self.call("Page.enable")

    def call(self, method, **params):
        self.next_id += 1
        self.ws.send(json.dumps({"id": self.next_id, "method": method, "params": params}))
        while True:
            message = json.loads(self.ws.recv())
            if message.get("method") == "Runtime.exceptionThrown":
                self.console.append(message["params"]["exceptionDetails"].get("text", ""))
            if message.get("method") == "Runtime.consoleAPICalled":
                self.console.append(" ".join(str(a.get("value", "")) for a in
                                             message["params"]["args"]))
            if message.get("id") == self.next_id:
                if "error" in message:
                    raise RuntimeError(f"{method}: {message['error']}")
                return message.get("result", {})

    def open(self, url, settle=0.0):
        self.call("Page.navigate", url=url)
        self.wait_for("document.readyState === 'complete'")
        time.sleep(settle)

    def eval(self, expression):
        result = self.call("Runtime.evaluate", expression=expression, returnByValue=True,
                           awaitPromise=True)
        if "exceptionDetails" in result:
            raise RuntimeError(f"{expression}: {result['exceptionDetails']}")
        return result["result"].get("value")

    def wait_for(self, expression, timeout=20):
        deadline = time.time() + timeout
        while time.time() < deadline:
            if self.eval(f"Boolean({expression})"):
                return
            time.sleep(0.05)
        raise AssertionError(f"not true within {timeout} s: {expression}")

    def screenshot(self, selector=None):
        """PNG bytes of the page, or of the element `selector` only."""
        params = {"format": "png", "captureBeyondViewport": True}
        if selector:
            box = self.eval(f"(() => {{ const r = document.querySelector('{selector}')"
                            ".getBoundingClientRect(); return [r.x, r.y, r.width, r.height]; })()")
            params["clip"] = {"x": box[0], "y": box[1], "width": box[2], "height": box[3],
                              "scale": 1}
        return base64.b64decode(self.call("Page.captureScreenshot", **params)["data"])

    def click(self, x, y):
        for kind in ("mousePressed", "mouseReleased"):
            self.call("Input.dispatchMouseEvent", type=kind, x=x, y=y, button="left",
                      clickCount=1)

    def close(self):
        try:
            self.call("Browser.close")
        except Exception:  # noqa: BLE001 - it may be gone already
            pass
        try:
            self.proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.proc.kill()
        shutil.rmtree(self.profile, ignore_errors=True)


def pixels(png_bytes):
    """The PNG as a numpy array of RGB bytes."""
    import numpy
    from PIL import Image
    return numpy.asarray(Image.open(io.BytesIO(png_bytes)).convert("RGB"), dtype=numpy.int16)
