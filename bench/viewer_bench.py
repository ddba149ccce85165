#!/usr/bin/python3
"""clrender view's speed as a user sees it, measured in the page (headless Chromium):

  - frames per second while the camera moves continuously (a key held: the page flies the
    camera every display frame and shows every image the server sends, 1 sample per pixel);
  - input-to-image latency while moving: for each image shown, the time from the oldest input
    it is the first to show to the moment it is on the canvas;
  - input-to-image latency of a single input on a still view (a wheel notch).

    /usr/bin/python3 bench/viewer_bench.py BUILD/clrender SCENE [SCENE...] [--size 1280x720]
                     [--seconds 5] [--channel rgba|png] [--inputs 15]

Prints one table row per scene and channel (Markdown) and, with --json FILE, the figures."""
import argparse
import json
import os
import statistics
import sys
import time

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "browser"))
from viewer_session import Viewer, open_browser  # noqa: E402


def wait(driver, script, timeout=120):
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        if driver.execute_script(script):
            return
        time.sleep(0.02)
    raise RuntimeError(f"timed out: {script}")


def wait_still(driver):
    wait(driver, "return window.clrenderViewer && window.clrenderViewer.ready && window.clrenderViewer.isStill()")


def percentile(values, p):
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(round(p / 100 * (len(ordered) - 1))))] if ordered else float("nan")


def measure(driver, viewer, channel, seconds, inputs):
    from selenium.webdriver.common.action_chains import ActionChains
    from selenium.webdriver.common.actions.wheel_input import ScrollOrigin
    driver.get(f"{viewer.url}&channel={channel}")
    wait_still(driver)
    view = driver.find_element("id", "view")
    driver.execute_script("arguments[0].focus()", view)
    # Moving: strafe with D held; the page moves the camera every display frame.
    driver.execute_script("window.clrenderViewer.resetStats()")
    start = driver.execute_script("return performance.now()")
    ActionChains(driver).key_down("d").perform()
    time.sleep(seconds)
    shown, latencies, timings, now = driver.execute_script(
        "const v = window.clrenderViewer; return [v.framesInLastSecond(), v.latencies(), v.timings(), performance.now()]")
    ActionChains(driver).key_up("d").perform()
    fps_text = driver.find_element("id", "fps").text
    moving_seconds = (now - start) / 1000
    frames = len(latencies)
    wait_still(driver)
    # Single inputs on a still view: one wheel notch, then wait for the still frame again.
    singles = []
    for i in range(inputs):
        driver.execute_script("window.clrenderViewer.resetStats()")
        ActionChains(driver).scroll_from_origin(ScrollOrigin.from_element(view), 0, 100 if i % 2 else -100).perform()
        wait(driver, "return window.clrenderViewer.latencies().length > 0")
        singles.append(driver.execute_script("return window.clrenderViewer.latencies()[0]"))
        wait_still(driver)
    return {"channel": channel, "moving_seconds": moving_seconds, "frames_moving": frames,
            "fps_moving": frames / moving_seconds, "fps_last_second": shown, "fps_text": fps_text,
            "latency_moving_median_ms": statistics.median(latencies) if latencies else None,
            "latency_moving_p95_ms": percentile(latencies, 95),
            "latency_single_median_ms": statistics.median(singles), "latency_single_max_ms": max(singles),
            # where a moving frame's time goes: to the response's headers (the server's render),
            # to its whole body, and decoding and drawing it
            "server_median_ms": statistics.median(t[0] for t in timings),
            "body_median_ms": statistics.median(t[1] for t in timings),
            "draw_median_ms": statistics.median(t[2] for t in timings)}


def load_average():
    """The one-minute load average (the benchmark shares its cores with whatever else runs)."""
    with open("/proc/loadavg") as f:
        return float(f.read().split()[0])


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("binary")
    parser.add_argument("scenes", nargs="+")
    parser.add_argument("--size", default="1280x720")
    parser.add_argument("--seconds", type=float, default=5)
    parser.add_argument("--inputs", type=int, default=15)
    parser.add_argument("--channel", action="append", choices=["rgba", "png"])
    parser.add_argument("--json")
    args = parser.parse_args()
    channels = args.channel or ["rgba"]
    driver = open_browser(1600, 1100)
    results = []
    print(f"{os.cpu_count()} CPUs, load average {load_average():.1f} at the start")
    print("| scene | size | channel | fps moving (in the page) | latency moving, median / p95 | latency of one input, median / max "
          "| a frame's time: server / body / draw (medians) |")
    print("|---|---|---|---:|---:|---:|---:|")
    try:
        for scene in args.scenes:
            viewer = Viewer(os.path.abspath(args.binary), scene, ["--size", args.size, "--spp", "1"])
            try:
                for channel in channels:
                    load_before = load_average()
                    r = measure(driver, viewer, channel, args.seconds, args.inputs)
                    r.update(scene=scene, size=args.size, load_average=[load_before, load_average()])
                    results.append(r)
                    print(f"| {os.path.basename(scene)} | {args.size} | {channel} | {r['fps_moving']:.1f} | "
                          f"{r['latency_moving_median_ms']:.1f} / {r['latency_moving_p95_ms']:.1f} ms | "
                          f"{r['latency_single_median_ms']:.1f} / {r['latency_single_max_ms']:.1f} ms | "
                          f"{r['server_median_ms']:.1f} / {r['body_median_ms']:.1f} / {r['draw_median_ms']:.1f} ms |",
                          flush=True)
            finally:
                viewer.stop()
    finally:
        driver.quit()
    if args.json:
        with open(args.json, "w") as f:
            json.dump(results, f, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main())
