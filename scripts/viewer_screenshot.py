#!/usr/bin/python3
"""Takes docs/viewer.png, the screenshot of docs/viewer.md: `clrender view` on the demo scene in
headless Chromium, with two camera keys recorded and exported, a pixel explained and a
slightly different render dropped on the page for comparison.

    /usr/bin/python3 scripts/viewer_screenshot.py BUILD/clrender [OUTPUT.png]"""
import os
import sys
import tempfile
import time

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.join(root, "tests", "browser"))
import png_io  # noqa: E402
from viewer_session import Viewer, camera_params, open_browser  # noqa: E402


def wait(driver, script, timeout=120):
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        if driver.execute_script(script):
            return
        time.sleep(0.05)
    raise RuntimeError(f"timed out: {script}")


def main():
    if len(sys.argv) < 2:
        print(__doc__)
        return 1
    binary = os.path.abspath(sys.argv[1])
    output = os.path.abspath(sys.argv[2] if len(sys.argv) > 2 else os.path.join(root, "docs", "viewer.png"))
    still = "return window.clrenderViewer && window.clrenderViewer.ready && window.clrenderViewer.isStill()"
    size = (640, 360)
    with tempfile.TemporaryDirectory(prefix="clrender-screenshot-") as work:
        viewer = Viewer(binary, os.path.join(root, "scenes", "demo", "demo.json"),
                        ["--size", f"{size[0]}x{size[1]}", "--spp", "4", "--output-dir", work], cwd=work)
        driver = open_browser(1280, 1560)
        try:
            from selenium.webdriver.common.action_chains import ActionChains
            driver.get(viewer.url)
            wait(driver, still)
            driver.find_element("id", "record").click()
            camera = driver.execute_script("return window.clrenderViewer.camera()")
            camera["eye"] = [camera["eye"][0] + 4, camera["eye"][1] + 1.5, camera["eye"][2] - 1]
            driver.execute_script("window.clrenderViewer.setCamera(arguments[0])", camera)
            wait(driver, still)
            driver.find_element("id", "record").click()
            driver.find_element("id", "export").click()
            wait(driver, "return document.getElementById('path-json').value")
            # A "student's" render: the still frame with the yellow sphere shaded differently.
            width, height, pixels = png_io.decode(viewer.get("frame.png", **camera_params(camera, size, 4)))
            tinted = bytearray(pixels)
            for y in range(230, 360):
                for x in range(440, 570):
                    i = (y * width + x) * 4
                    if tinted[i] > 180 and tinted[i + 2] < 120:
                        tinted[i + 1] = max(0, tinted[i + 1] - 12 - (x - 440) // 8)
            student = os.path.join(work, "student.png")
            with open(student, "wb") as f:
                f.write(png_io.encode(width, height, bytes(tinted)))
            driver.find_element("id", "compare-file").send_keys(student)
            wait(driver, "return document.getElementById('diff-share').dataset.share")
            view = driver.find_element("id", "view")
            rect = driver.execute_script("return arguments[0].getBoundingClientRect().toJSON()", view)
            x, y = 505, 298  # a pixel of the yellow sphere
            ActionChains(driver).move_to_element_with_offset(
                view, round((x + 0.5) * rect["width"] / width - rect["width"] / 2),
                round((y + 0.5) * rect["height"] / height - rect["height"] / 2)).click().perform()
            wait(driver, "return !document.getElementById('explain').textContent.includes('asking')"
                         " && document.getElementById('explain').textContent.startsWith('Pixel')")
            driver.execute_script("document.activeElement.blur(); window.scrollTo(0, 0)")
            time.sleep(0.3)
            driver.save_screenshot(output)
        finally:
            driver.quit()
            viewer.stop()
    print(f"viewer_screenshot: wrote {output}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
