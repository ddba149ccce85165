"""Starts `clrender view` and a headless Chromium for the browser tests, the screenshot and the
viewer benchmark. Exit code 77 (CTest's skip) where Chromium, its driver or Selenium is missing."""
import atexit
import json
import os
import queue
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
import urllib.parse
import urllib.request

SKIP = 77
URL_PATTERN = re.compile(r"http://127\.0\.0\.1:\d+/\S*")


def browser_or_skip():
    """(chromium, chromedriver) paths, or exits 77 naming what is missing."""
    try:
        import selenium  # noqa: F401
    except ImportError:
        print("skipped: python3-selenium is not installed (scripts/install-deps.sh)")
        sys.exit(SKIP)
    chromium = shutil.which("chromium") or shutil.which("chromium-browser")
    driver = shutil.which("chromedriver")
    if not chromium or not driver:
        print("skipped: chromium or chromedriver is not installed (scripts/install-deps.sh)")
        sys.exit(SKIP)
    return chromium, driver


def open_browser(width=1280, height=900):
    """A headless Chromium driven by Selenium."""
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service
    chromium, driver = browser_or_skip()
    options = webdriver.ChromeOptions()
    options.binary_location = chromium
    for argument in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
                     f"--window-size={width},{height}", "--force-device-scale-factor=1",
                     "--disable-background-timer-throttling", "--disable-renderer-backgrounding"):
        options.add_argument(argument)
    # Chromium leaves its singleton folders (org.chromium.Chromium.*) in $TMPDIR even when it
    # quits: it gets a folder of its own, removed when this process ends.
    browser_tmp = tempfile.mkdtemp(prefix="clrender-browser-")
    atexit.register(shutil.rmtree, browser_tmp, True)
    service = Service(driver, env={**os.environ, "TMPDIR": browser_tmp})
    return webdriver.Chrome(service=service, options=options)


class Viewer:
    """`clrender view SCENE --no-browser --port 0 ARGS...` running until stop()."""

    def __init__(self, binary, scene, args=(), cwd=None, env=None, timeout=120):
        command = [binary, "view", scene, "--no-browser", "--port", "0", *args]
        self.process = subprocess.Popen(command, cwd=cwd, env=env, stdout=subprocess.PIPE,
                                        stderr=subprocess.PIPE, text=True)
        self.lines = queue.Queue()
        self.stderr = []
        self.readers = [threading.Thread(target=self._read, args=(self.process.stdout, self.lines.put), daemon=True),
                        threading.Thread(target=self._read, args=(self.process.stderr, self.stderr.append), daemon=True)]
        for reader in self.readers:
            reader.start()
        self.url = None
        while self.url is None:
            try:
                line = self.lines.get(timeout=timeout)
            except queue.Empty:
                self.stop()
                raise RuntimeError(f"{' '.join(command)} printed no address in {timeout} s: {''.join(self.stderr)}")
            if line is None:
                raise RuntimeError(f"{' '.join(command)} ended (exit {self.process.wait()}) "
                                   f"without an address: {''.join(self.stderr)}")
            match = URL_PATTERN.search(line)
            if match:
                self.url = match.group(0)
        parts = urllib.parse.urlsplit(self.url)
        self.base = f"{parts.scheme}://{parts.netloc}/"
        self.token = urllib.parse.parse_qs(parts.query).get("token", [""])[0]

    @staticmethod
    def _read(stream, put):
        for line in stream:
            put(line)
        put(None)

    def get(self, path, **params):
        """The body of GET path with the token and params, raising on an HTTP error."""
        query = urllib.parse.urlencode({"token": self.token, **params})
        with urllib.request.urlopen(f"{self.base}{path}?{query}", timeout=120) as response:
            return response.read()

    def scene(self):
        return json.loads(self.get("scene.json"))

    def stop(self):
        """SIGTERM, as Ctrl-C would end it; returns the exit code."""
        if self.process.poll() is None:
            self.process.send_signal(signal.SIGTERM)
            try:
                self.process.wait(timeout=20)
            except subprocess.TimeoutExpired:
                self.process.kill()
        code = self.process.wait()
        for reader in self.readers:
            reader.join(timeout=5)
        self.process.stdout.close()
        self.process.stderr.close()
        return code


def camera_params(camera, size, spp, frame=None):
    """The query of /frame.png for a camera as the page holds it."""
    params = {"eye": ",".join(repr(float(x)) for x in camera["eye"]),
              "lookat": ",".join(repr(float(x)) for x in camera["lookat"]),
              "up": ",".join(repr(float(x)) for x in camera["up"]),
              "fov": repr(float(camera["fov"])), "size": f"{size[0]}x{size[1]}", "spp": str(spp)}
    if frame is not None:
        params["frame"] = str(frame)
    return params

