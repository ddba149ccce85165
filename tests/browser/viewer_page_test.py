#!/usr/bin/python3
"""The page of `clrender view` in a real browser (headless Chromium through Selenium): load,
drag, fly, record and export a camera path and render the export, click to explain, drop an
image and read the difference, the time slider over an animation's path, the video.

    /usr/bin/python3 tests/browser/viewer_page_test.py BUILD/clrender SOURCE_DIR

One browser session and one server serve every test. Exit 77 (a skip) where Chromium,
chromedriver or Selenium is missing."""
import base64
import json
import os
import re
import subprocess
import sys
import tempfile
import time
import unittest
import urllib.parse
import urllib.request

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import png_io  # noqa: E402
from viewer_session import Viewer, browser_or_skip, camera_params, open_browser  # noqa: E402

BINARY = SOURCE_DIR = None
SIZE = (192, 108)
SPP = 16


def run_clrender(*args, cwd=None):
    result = subprocess.run([BINARY, *args], cwd=cwd, capture_output=True, text=True, timeout=300)
    if result.returncode != 0:
        raise AssertionError(f"clrender {' '.join(args)} exited {result.returncode}: {result.stderr}")
    return result.stdout


def read_png(path):
    with open(path, "rb") as f:
        return png_io.decode(f.read())


class ViewerPage(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.work = tempfile.TemporaryDirectory(prefix="clrender-view-test-")
        cls.scene_path = os.path.join(SOURCE_DIR, "scenes", "demo", "demo.json")
        cls.viewer = Viewer(BINARY, cls.scene_path,
                            ["--size", f"{SIZE[0]}x{SIZE[1]}", "--spp", str(SPP), "--output-dir", cls.work.name],
                            cwd=cls.work.name)
        cls.driver = None
        try:
            cls.driver = open_browser()
            cls.driver.set_script_timeout(60)
            cls.load(cls.viewer)
        except BaseException:
            cls.tearDownClass()  # unittest does not when setUpClass fails: no server left behind
            raise

    @classmethod
    def tearDownClass(cls):
        if cls.driver is not None:
            cls.driver.quit()
        cls.viewer.stop()
        cls.work.cleanup()

    @classmethod
    def load(cls, viewer):
        cls.driver.get(viewer.url)
        cls.wait_still()

    @classmethod
    def wait_until(cls, script, timeout=60, what="the page"):
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            value = cls.driver.execute_script(script)
            if value:
                return value
            time.sleep(0.05)
        status = cls.driver.execute_script("return document.getElementById('status').textContent")
        raise AssertionError(f"timed out waiting for {what}: {script}; status: {status}")

    @classmethod
    def wait_still(cls):
        cls.wait_until("return window.clrenderViewer && window.clrenderViewer.ready && window.clrenderViewer.isStill()",
                       what="the still frame")

    def assert_same_image(self, expected, actual, message):
        """Equal (width, height, RGBA) images; a failure counts the differing pixels (unittest's
        own diff of two large byte strings takes minutes)."""
        self.assertEqual(expected[:2], actual[:2], f"{message}: sizes differ")
        if expected[2] == actual[2]:
            return
        a, b = expected[2], actual[2]
        differing = [p for p in range(len(a) // 4) if a[p * 4:p * 4 + 4] != b[p * 4:p * 4 + 4]]
        first = differing[0]
        self.fail(f"{message}: {len(differing)} of {len(a) // 4} pixels differ, the first at "
                  f"({first % expected[0]}, {first // expected[0]}): {tuple(a[first * 4:first * 4 + 4])} expected, "
                  f"{tuple(b[first * 4:first * 4 + 4])} shown")

    def camera(self):
        return self.driver.execute_script("return window.clrenderViewer.camera()")

    def canvas_pixels(self, element_id="view"):
        """(width, height, RGBA bytes) of a canvas, read in the page."""
        result = self.driver.execute_script("""
            const canvas = document.getElementById(arguments[0]);
            const data = canvas.getContext('2d').getImageData(0, 0, canvas.width, canvas.height).data;
            let text = '';
            for (let i = 0; i < data.length; i += 8192) text += String.fromCharCode(...data.subarray(i, i + 8192));
            return [canvas.width, canvas.height, btoa(text)];""", element_id)
        return result[0], result[1], base64.b64decode(result[2])

    def frame_png(self, camera, spp=SPP, frame=None):
        return png_io.decode(self.viewer.get("frame.png", **camera_params(camera, SIZE, spp, frame)))

    def set_camera(self, camera):
        self.driver.execute_script("window.clrenderViewer.setCamera(arguments[0])", camera)
        self.wait_still()

    def reset(self):
        self.driver.find_element("id", "reset").click()
        self.wait_still()

    def test_a_still_view_is_the_batch_render(self):
        scene = self.viewer.scene()
        self.assertEqual(scene["size"], list(SIZE))
        self.assertEqual(scene["spp"], SPP)
        self.reset()
        width, height, shown = self.canvas_pixels()
        self.assertEqual((width, height), SIZE)
        # Still, the samples went up fourfold at a time to the scene's.
        history = self.driver.execute_script("return window.clrenderViewer.history()")
        version = history[-1]["version"]
        self.assertEqual([h["spp"] for h in history if h["version"] == version], [1, 4, 16])
        served = self.frame_png(scene["camera"])
        self.assert_same_image(served, (width, height, shown), "#view differs from /frame.png at the scene's camera")
        batch = os.path.join(self.work.name, "batch.png")
        run_clrender(self.scene_path, "--size", f"{SIZE[0]}x{SIZE[1]}", "--spp", str(SPP), "-o", batch)
        self.assert_same_image(read_png(batch), served, "/frame.png differs from the batch render")

    def test_b_drag_orbits_around_the_look_at_point(self):
        from selenium.webdriver.common.action_chains import ActionChains
        self.reset()
        before_camera = self.camera()
        before = self.canvas_pixels()
        view = self.driver.find_element("id", "view")
        chain = ActionChains(self.driver).move_to_element(view).click_and_hold()
        for _ in range(8):
            chain.move_by_offset(8, 2).pause(0.03)
        chain.release().perform()
        fps_text = self.driver.find_element("id", "fps").text  # read at once, as a user glances at it
        self.assertGreater(int(re.match(r"\s*(\d+)", fps_text).group(1)), 0, fps_text)
        self.wait_still()
        after_camera = self.camera()
        self.assertEqual(after_camera["lookat"], before_camera["lookat"])
        self.assertNotEqual(after_camera["eye"], before_camera["eye"])

        def distance(c):
            return sum((e - l) ** 2 for e, l in zip(c["eye"], c["lookat"])) ** 0.5
        self.assertAlmostEqual(distance(after_camera), distance(before_camera), places=9)
        after = self.canvas_pixels()
        self.assertNotEqual(after[2], before[2], "the image did not change after the drag")
        self.assert_same_image(self.frame_png(after_camera), after, "the still view after a drag is not /frame.png")

    def test_c_held_key_flies_and_fps_counts_frames(self):
        from selenium.webdriver.common.action_chains import ActionChains
        self.reset()
        before = self.camera()
        self.driver.execute_script("document.getElementById('view').focus()")
        ActionChains(self.driver).key_down("w").perform()
        time.sleep(0.8)
        fps_text = self.driver.find_element("id", "fps").text
        moving_spp = self.driver.execute_script("return window.clrenderViewer.shown().spp")
        ActionChains(self.driver).key_up("w").perform()
        self.wait_still()
        match = re.match(r"\s*(\d+)", fps_text)
        self.assertIsNotNone(match, f"#fps does not start with a number: {fps_text!r}")
        self.assertGreater(int(match.group(1)), 0, f"#fps while flying: {fps_text!r}")
        self.assertEqual(moving_spp, 1, "frames shown while moving are not 1 sample per pixel")
        after = self.camera()
        offset = [e - l for e, l in zip(before["eye"], before["lookat"])]
        moved = [e - l for e, l in zip(after["eye"], after["lookat"])]
        for a, b in zip(offset, moved):
            self.assertAlmostEqual(a, b, places=6)  # flying moves eye and look-at point together
        forward = [l - e for e, l in zip(before["eye"], before["lookat"])]
        step = [a - b for a, b in zip(after["eye"], before["eye"])]
        self.assertGreater(sum(f * s for f, s in zip(forward, step)), 0, "W did not fly forward")

    def test_d_record_export_and_render_the_export(self):
        self.reset()
        second = self.camera()
        first = dict(second, eye=[second["eye"][0] + 3.0, second["eye"][1] + 1.0, second["eye"][2] - 2.0])
        self.set_camera(first)
        self.driver.find_element("id", "record").click()
        self.reset()
        self.driver.find_element("id", "record").click()
        self.driver.find_element("id", "export").click()
        text = self.wait_until("return document.getElementById('path-json').value", what="the exported scene")
        exported = json.loads(text)
        self.assertEqual(exported["eyeLocations"], [first["eye"], second["eye"]])
        looks = exported.get("lookatLocations") or [exported["lookat"]] * 2
        self.assertEqual(looks, [first["lookat"], second["lookat"]])
        path = self.driver.execute_script("return document.getElementById('path-json').dataset.file")
        self.assertTrue(path and os.path.isfile(os.path.join(self.work.name, path)), f"no exported file {path!r}")
        path = os.path.join(self.work.name, path)
        with open(path) as f:
            self.assertEqual(json.load(f), exported, "the file differs from #path-json")
        self.assertGreaterEqual(int(run_clrender(path, "--frame-count").split()[0]), 2)
        # Frame 0 of the export is the first key's view: the same seeds as the view's still frame.
        rendered = os.path.join(self.work.name, "export_frame0.png")
        run_clrender(path, "--frames", "0", "-o", rendered)
        self.assert_same_image(read_png(rendered), self.frame_png(first), "the export's frame 0 is not the first key's view")
        self.driver.find_element("id", "clear-keys").click()

    def test_h_render_video_shows_progress_and_writes_the_video(self):
        self.reset()
        self.driver.find_element("id", "clear-keys").click()
        button = self.driver.find_element("id", "render-video")
        first = self.camera()
        self.driver.find_element("id", "record").click()
        # One key is a still: no video is offered until there are two.
        self.wait_until("return document.getElementById('keys').children.length === 1", what="the first key")
        self.assertFalse(button.is_enabled(), "Render video is offered with one key")
        self.set_camera(dict(first, eye=[first["eye"][0] - 2.0, first["eye"][1], first["eye"][2]]))
        self.driver.find_element("id", "record").click()
        self.wait_until("return !document.getElementById('render-video').disabled", what="Render video with two keys")
        button.click()
        text = self.wait_until("const t = document.getElementById('video-status').textContent;"
                               "return t.startsWith('Video') ? t : ''", timeout=240, what="the video")
        self.assertTrue(text.startswith("Video written to"), text)
        progress = self.driver.find_element("id", "video-progress")
        self.assertEqual(progress.get_attribute("value"), progress.get_attribute("max"))
        self.assertEqual(int(progress.get_attribute("max")), 11)  # 2 keys: 10 frames per segment + 1
        path = self.driver.execute_script("return document.getElementById('video-status').dataset.file")
        with open(os.path.join(self.work.name, path), "rb") as f:
            self.assertEqual(f.read(12)[4:8], b"ftyp", "the video is not an MP4")
        self.driver.find_element("id", "clear-keys").click()

    def test_e_click_explains_the_pixel_under_the_pointer(self):
        from selenium.webdriver.common.action_chains import ActionChains
        self.reset()
        # Shown at twice its size, the click must still name the image pixel under it.
        self.driver.execute_script("document.getElementById('view').style.width = arguments[0] + 'px'", SIZE[0] * 2)
        try:
            view = self.driver.find_element("id", "view")
            rect = self.driver.execute_script("return arguments[0].getBoundingClientRect().toJSON()", view)
            self.assertAlmostEqual(rect["width"], SIZE[0] * 2, delta=0.5)
            x, y = 131, 40
            # the middle of the pixel's 2x2 block, as an offset from the element's centre
            dx = round(2 * x + 1 - rect["width"] / 2)
            dy = round(2 * y + 1 - rect["height"] / 2)
            ActionChains(self.driver).move_to_element_with_offset(view, dx, dy).click().perform()
            text = self.wait_until("const t = document.getElementById('explain').textContent;"
                                   "return t.includes('asking') ? '' : t", what="the explanation")
        finally:
            self.driver.execute_script("document.getElementById('view').style.width = ''")
        self.assertTrue(text.startswith(f"Pixel ({x}, {y})"), text[:200])
        expected = run_clrender(self.scene_path, "--explain-pixel", f"{x},{y}",
                                "--size", f"{SIZE[0]}x{SIZE[1]}", "--spp", str(SPP))
        first_lines = "\n".join(expected.splitlines()[:3])
        self.assertIn(first_lines, text, "#explain is not clrender's explanation of that pixel")

    def drop_file(self, name, data):
        """Drops a file on the page as a user's drag and drop does (a DataTransfer with the file)."""
        self.driver.execute_script("""
            const bytes = Uint8Array.from(atob(arguments[1]), (c) => c.charCodeAt(0));
            const transfer = new DataTransfer();
            transfer.items.add(new File([bytes], arguments[0], { type: 'image/png' }));
            for (const type of ['dragenter', 'dragover', 'drop']) {
              document.body.dispatchEvent(new DragEvent(type, { dataTransfer: transfer, bubbles: true, cancelable: true }));
            }""", name, base64.b64encode(data).decode())

    def wait_comparison(self, name):
        return self.wait_until(
            "const e = document.getElementById('diff-share');"
            f"return e.textContent.includes('comparing') || !e.textContent.includes({json.dumps(name)}) ? '' : e.textContent",
            what=f"the comparison with {name}")

    def test_f_dropped_image_shows_the_share_of_differing_pixels(self):
        from selenium.webdriver.common.action_chains import ActionChains
        self.reset()
        width, height, reference = self.frame_png(self.camera())
        student = bytearray(reference)
        changed = [(5, 7), (100, 50), (191, 107), (0, 0), (64, 80)]
        for x, y in changed:  # off by 40/255 in red: counted
            i = (y * width + x) * 4
            student[i] = student[i] + 40 if student[i] < 200 else student[i] - 40
        for x in range(20, 30):  # off by 2/255: within the default tolerance
            i = (60 * width + x) * 4 + 1
            student[i] = student[i] + 2 if student[i] < 200 else student[i] - 2
        path = os.path.join(self.work.name, "student.png")
        with open(path, "wb") as f:
            f.write(png_io.encode(width, height, bytes(student)))
        self.driver.find_element("id", "compare-file").send_keys(path)
        text = self.wait_comparison("student.png")
        share = self.driver.find_element("id", "diff-share")
        self.assertEqual(int(share.get_attribute("data-off")), len(changed), text)
        self.assertEqual(int(share.get_attribute("data-total")), width * height)
        self.assertTrue(text.startswith(f"{100 * len(changed) / (width * height):.2f}%"), text)
        comparison = self.driver.execute_script("return window.clrenderViewer.comparison()")
        self.assertEqual((comparison["off"], comparison["total"]), (len(changed), width * height))
        self.assertEqual(comparison["worst"], 40)
        # The heat map marks exactly the changed pixels.
        heat_width, heat_height, heat = self.canvas_pixels("diff")
        self.assertEqual((heat_width, heat_height), (width, height))
        # (marked: full red, no blue; the dimmed grey of matching pixels stays below 90)
        marked = {(p % width, p // width) for p in range(width * height) if heat[p * 4] == 255 and heat[p * 4 + 2] == 0}
        self.assertEqual(marked, set(changed))
        # A tolerance of 1 counts the pixels off by 2 as well.
        tolerance = self.driver.find_element("id", "tolerance")
        tolerance.clear()
        tolerance.send_keys("1")
        self.wait_until(f"return document.getElementById('diff-share').dataset.off === '{len(changed) + 10}'",
                        what="the comparison at tolerance 1")
        tolerance.clear()
        tolerance.send_keys("2")
        # Clicking a differing pixel of the heat map (shown at four times its size) explains it.
        diff = self.driver.find_element("id", "diff")
        # Wholly in view: WebDriver's offsets count from the centre of an element's visible part.
        self.driver.execute_script("arguments[0].style.width = arguments[1] + 'px';"
                                   "arguments[0].scrollIntoView({block: 'center'})", diff, width * 4)
        rect = self.driver.execute_script("return arguments[0].getBoundingClientRect().toJSON()", diff)
        x, y = changed[1]
        ActionChains(self.driver).move_to_element_with_offset(
            diff, round(4 * x + 2 - rect["width"] / 2), round(4 * y + 2 - rect["height"] / 2)).click().perform()
        text = self.wait_until("const t = document.getElementById('explain').textContent;"
                               "return t.includes('asking') ? '' : t", what="the explanation of a differing pixel")
        self.assertTrue(text.startswith(f"Pixel ({x}, {y})"), text[:200])
        self.assertIn("a difference of 40/255", text)
        # The same image dropped: nothing differs.
        self.drop_file("same.png", png_io.encode(width, height, reference))
        text = self.wait_comparison("same.png")
        self.assertTrue(text.startswith("0.00%"), text)
        self.assertEqual(share.get_attribute("data-off"), "0")
        # clrender's own PPM of the same view (browsers do not read PPM; the page does): the same.
        ppm = os.path.join(self.work.name, "batch.ppm")
        run_clrender(self.scene_path, "--size", f"{SIZE[0]}x{SIZE[1]}", "--spp", str(SPP), "-o", ppm)
        self.driver.find_element("id", "compare-file").send_keys(ppm)
        text = self.wait_comparison("batch.ppm")
        self.assertTrue(text.startswith("0.00%"), text)
        # Another size: a clear message and no heat map.
        self.drop_file("small.png", png_io.encode(10, 5, bytes(10 * 5 * 4)))
        text = self.wait_comparison("small.png")
        self.assertIn(f"small.png is 10x5 but this view renders {width}x{height}", text)
        self.assertFalse(diff.is_displayed())

    def test_g_path_slider_shows_the_batch_render_of_that_frame(self):
        # An animation: the demo scene with three camera keys on a Catmull-Rom path (whose
        # frames between keys the page cannot place by straight lines), in a folder of its own.
        folder = os.path.join(self.work.name, "animation")
        os.makedirs(folder)
        with open(self.scene_path) as f:
            scene = json.load(f)
        for billboard in scene["billboards"]:
            billboard["filename"] = os.path.join(os.path.dirname(self.scene_path), billboard["filename"])
        del scene["eye"]
        scene["eyeLocations"] = [[0, 1.5, 14], [6, 3, 10], [9, 1, 2]]
        scene["clrender"] = {"interpolation": "catmull-rom"}
        path = os.path.join(folder, "animation.json")
        with open(path, "w") as f:
            json.dump(scene, f)
        viewer = Viewer(BINARY, path, ["--size", f"{SIZE[0]}x{SIZE[1]}", "--spp", str(SPP),
                                       "--output-dir", folder], cwd=folder)
        try:
            self.assertEqual(viewer.scene()["frames"], 21)
            self.load(viewer)
            frame = 7
            self.driver.execute_script("""
                const slider = document.getElementById('time');
                slider.value = String(arguments[0]);
                slider.dispatchEvent(new Event('input', { bubbles: true }));""", frame)
            self.wait_until(f"return window.clrenderViewer.isStill() && window.clrenderViewer.shown().frame === {frame}",
                            what=f"frame {frame}")
            shown = self.canvas_pixels()
            batch = os.path.join(folder, "frame7.png")
            run_clrender(path, "--frames", str(frame), "-o", batch, "--size", f"{SIZE[0]}x{SIZE[1]}",
                         "--spp", str(SPP))
            self.assert_same_image(shown, read_png(batch), "the path slider's frame is not the batch render's")
            # The page's own Catmull-Rom (its playback of exported paths) places frame 7 where
            # clrender does: the eye --explain-pixel prints for that frame (9 digits).
            placed = self.driver.execute_script(
                "const keys = arguments[0].map((eye) => ({eye, lookat: [0, 1, 0], up: [0, 1, 0], fov: 60}));"
                "return ClrenderCamera.alongKeys(keys, arguments[1], 21, 'catmull-rom').eye",
                scene["eyeLocations"], frame)
            explained = run_clrender(path, "--frames", str(frame), "--explain-pixel", "0,0", "--size", "8x8")
            eye = [float(x) for x in re.search(r"Eye = \(([^)]*)\)", explained).group(1).split(",")]
            for a, b in zip(placed, eye):
                self.assertAlmostEqual(a, b, delta=1e-7 * max(1.0, abs(b)))
            linear = self.driver.execute_script(
                "const keys = arguments[0].map((eye) => ({eye, lookat: [0, 1, 0], up: [0, 1, 0], fov: 60}));"
                "return ClrenderCamera.alongKeys(keys, arguments[1], 21, 'linear').eye", scene["eyeLocations"], frame)
            self.assertGreater(max(abs(a - b) for a, b in zip(linear, eye)), 1e-3, "the check cannot tell the curves apart")
            # Record key there records the camera shown: the server's frame 7, bit for bit, not
            # the page's guess of it; the export holds it.
            served = json.loads(viewer.get("camera.json", frame=str(frame)))
            self.driver.find_element("id", "clear-keys").click()
            self.driver.find_element("id", "record").click()
            self.wait_until("return document.getElementById('keys').children.length === 1", what="the recorded key")
            self.assertEqual(self.camera(), {k: served[k] for k in ("eye", "lookat", "up", "fov")})
            self.driver.find_element("id", "export").click()
            text = self.wait_until("return document.getElementById('path-json').value", what="the exported scene")
            self.assertEqual(json.loads(text)["eyeLocations"], [served["eye"]])
            for a, b in zip(served["eye"], eye):
                self.assertAlmostEqual(a, b, delta=1e-7 * max(1.0, abs(b)))
            self.driver.find_element("id", "clear-keys").click()
        finally:
            self.load(self.viewer)
            viewer.stop()

    def still_view_matches_batch(self, scene_path, size, spp, folder, batch_args=()):
        """Loads the page for scene_path and checks its still view against the batch render."""
        viewer = Viewer(BINARY, scene_path, ["--size", f"{size[0]}x{size[1]}", "--spp", str(spp),
                                             "--output-dir", folder], cwd=folder)
        try:
            self.load(viewer)
            shown = self.canvas_pixels()
            batch = os.path.join(folder, "batch.png")
            run_clrender(scene_path, "--size", f"{size[0]}x{size[1]}", "--spp", str(spp), "-o", batch, *batch_args)
            self.assert_same_image(read_png(batch), shown, f"the still view of {scene_path} is not the batch render")
        finally:
            self.load(self.viewer)
            viewer.stop()

    def test_i_course_scene_still_view_is_the_batch_render(self):
        scene = os.path.join(SOURCE_DIR, "..", "shared", "course-scenes", "spring2023-a03", "testScene_grads.json")
        if not os.path.isfile(scene):
            self.skipTest(f"{scene} is absent (the course material beside the source tree)")
        folder = os.path.join(self.work.name, "course")
        os.makedirs(folder)
        self.still_view_matches_batch(scene, (160, 120), 2, folder)

    def test_j_impostors_after_a_drag_are_the_batch_render(self):
        # Impostors are placed for the camera (and their view chosen) on the server, as a batch
        # render places them: after orbiting, the still view is the batch render from there.
        from selenium.webdriver.common.action_chains import ActionChains
        folder = os.path.join(self.work.name, "impostors")
        os.makedirs(folder)
        images = os.path.dirname(self.scene_path)
        with open(self.scene_path) as f:
            scene = json.load(f)
        for billboard in scene["billboards"]:
            billboard["filename"] = os.path.join(images, billboard["filename"])
        scene["clrender"] = {"impostors": [
            {"center": [6, 0.5, 1], "width": 3, "height": 3, "views": [
                {"filename": os.path.join(images, "cutout.png"), "direction": [0, 0, 1]},
                {"filename": os.path.join(images, "checker.png"), "direction": [1, 0, 0]}]},
            {"center": [-3, 3, 2], "width": 2, "height": 2, "facing": "free", "ambient": [1, 0.5, 0]}]}
        path = os.path.join(folder, "impostors.json")
        with open(path, "w") as f:
            json.dump(scene, f)
        viewer = Viewer(BINARY, path, ["--size", f"{SIZE[0]}x{SIZE[1]}", "--spp", str(SPP),
                                       "--output-dir", folder], cwd=folder)
        try:
            self.load(viewer)
            before = self.canvas_pixels()
            view = self.driver.find_element("id", "view")
            chain = ActionChains(self.driver).move_to_element(view).click_and_hold()
            for _ in range(12):  # 240 pixels: the eye turns 72 degrees, to the first impostor's other view
                chain.move_by_offset(-20, 0).pause(0.02)
            chain.release().perform()
            self.wait_still()
            camera = self.camera()
            to_eye = [camera["eye"][0] - 6, camera["eye"][2] - 1]
            self.assertGreater(to_eye[0], 1.5 * abs(to_eye[1]), f"the eye {camera['eye']} did not turn to the side")
            shown = self.canvas_pixels()
            self.assertNotEqual(shown[2], before[2])
            batch = os.path.join(folder, "batch.png")
            vector = lambda v: json.dumps([float(x) for x in v])  # noqa: E731
            run_clrender(path, "-D", f"eye={vector(camera['eye'])}", "-D", f"lookat={vector(camera['lookat'])}",
                         "-D", f"up={vector(camera['up'])}", "-D", f"fov_angle={float(camera['fov'])!r}",
                         "--size", f"{SIZE[0]}x{SIZE[1]}", "--spp", str(SPP), "-o", batch)
            self.assert_same_image(read_png(batch), shown, "the still view after a drag is not the batch render")
        finally:
            self.load(self.viewer)
            viewer.stop()
    def test_k_a_refused_camera_is_reported_and_the_next_one_shown(self):
        self.reset()
        camera = self.camera()
        self.driver.execute_script("window.clrenderViewer.setCamera(arguments[0])", dict(camera, fov=1e-9))
        status = self.wait_until("const s = document.getElementById('status');"
                                 "return s.className === 'error' ? s.textContent : ''", what="the refusal")
        self.assertIn("400 (fov)", status)
        self.set_camera(camera)  # the next camera is asked for and shown
        self.assertNotEqual(self.driver.find_element("id", "status").get_attribute("class"), "error")

    def test_l_play_moves_the_camera_through_the_keys(self):
        self.reset()
        self.driver.find_element("id", "clear-keys").click()
        self.driver.find_element("id", "play").click()  # no key yet: says so, plays nothing
        self.assertEqual(self.driver.find_element("id", "export-status").text, "Record at least one key first.")
        self.assertEqual(self.driver.find_element("id", "play").text, "Play")
        start = self.camera()
        end = dict(start, eye=[start["eye"][0] + 4.0, start["eye"][1], start["eye"][2] - 4.0])
        from selenium.webdriver.common.action_chains import ActionChains
        ActionChains(self.driver).double_click(self.driver.find_element("id", "record")).perform()
        self.wait_until("return document.getElementById('export-status').textContent.includes('last key')",
                        what="the second click of a double click on Record key")
        self.assertEqual(len(self.driver.find_elements("css selector", "#keys li")), 1, "a double click recorded two keys")
        self.set_camera(end)
        self.driver.find_element("id", "record").click()
        self.reset()
        first_version = self.driver.execute_script("return window.clrenderViewer.history().slice(-1)[0].version")
        # The page records the camera at every animation frame while it plays: polled through the
        # driver (a round trip of 100 ms and more on a loaded machine), the half-second play
        # could show as two cameras.
        self.driver.execute_script("""
            window.seenWhilePlaying = [];
            const play = document.getElementById('play');
            const record = () => {
              window.seenWhilePlaying.push(window.clrenderViewer.camera().eye);
              if (play.textContent !== 'Play') requestAnimationFrame(record);
            };
            play.click();
            requestAnimationFrame(record);""")
        self.wait_until("return document.getElementById('play').textContent === 'Play'", what="the end of play")
        seen = self.driver.execute_script("return window.seenWhilePlaying")
        self.wait_still()
        self.assertEqual(self.camera()["eye"], end["eye"], "play did not end at the last key")
        # On the way: points of the straight segment between the keys, strictly inside it.
        inside = [e for e in seen if start["eye"][0] < e[0] < end["eye"][0]]
        self.assertGreaterEqual(len(inside), 2, f"cameras seen while playing: {seen}")
        for eye in inside:
            t = (eye[0] - start["eye"][0]) / 4.0
            for axis, step in enumerate([4.0, 0.0, -4.0]):
                self.assertAlmostEqual(eye[axis], start["eye"][axis] + t * step, places=9)
        shown = self.driver.execute_script("return window.clrenderViewer.history()")
        self.assertGreater(len({h["version"] for h in shown if h["version"] > first_version}), 2,
                           "no images shown while playing")
        self.driver.find_element("id", "clear-keys").click()

    def test_m_still_samples_control_renders_the_view_again(self):
        from selenium.webdriver.support.ui import Select
        self.reset()
        select = Select(self.driver.find_element("id", "still-spp"))
        self.assertEqual(select.first_selected_option.get_attribute("value"), str(SPP))
        try:
            select.select_by_value("4")
            self.wait_until("return window.clrenderViewer.isStill() && window.clrenderViewer.shown().spp === 4",
                            what="the still frame at 4 samples")
            self.assert_same_image(self.frame_png(self.camera(), spp=4), self.canvas_pixels(),
                                   "the still frame at 4 samples is not /frame.png at 4")
        finally:
            select.select_by_value(str(SPP))
            self.wait_until(f"return window.clrenderViewer.isStill() && window.clrenderViewer.shown().spp === {SPP}",
                            what="the still frame at the scene's samples")

    def test_n_the_page_loads_nothing_from_elsewhere(self):
        # Markup that reached the page (an inline handler, a data: or blob: script, a
        # javascript: link) runs nothing under the viewer's Content-Security-Policy.
        outcome = self.driver.execute_async_script("""
            const done = arguments[arguments.length - 1];
            window.injectedRan = [];
            const refused = [];
            document.addEventListener('securitypolicyviolation', (e) => refused.push(e.effectiveDirective));
            const box = document.createElement('div');
            box.hidden = true;
            box.innerHTML = '<img src="data:image/png;base64,AAAA" onerror="window.injectedRan.push(1)">' +
                            '<a id="injected-link" href="javascript:window.injectedRan.push(2)">x</a>';
            document.body.append(box);
            for (const source of ['data:text/javascript,window.injectedRan.push(3)',
                                  URL.createObjectURL(new Blob(['window.injectedRan.push(4)'], {type: 'text/javascript'}))]) {
              const script = document.createElement('script');
              script.src = source;
              document.body.append(script);
            }
            document.getElementById('injected-link').click();
            setTimeout(() => { box.remove(); done([window.injectedRan, refused]); }, 500);""")
        self.assertEqual(outcome[0], [], "injected script ran")
        self.assertTrue({"script-src-attr", "script-src-elem"} <= set(outcome[1]), outcome[1])
        resources = self.driver.execute_script(
            "return performance.getEntriesByType('resource').map((e) => e.name)"
            ".concat(Array.from(document.querySelectorAll('[src], [href]'), (e) => e.src || e.href))")
        self.assertTrue(resources)
        for name in resources:
            if name.startswith(("blob:", "data:")) or name.endswith("#"):
                continue
            self.assertTrue(name.startswith(self.viewer.base), f"{name} is not the viewer's own")

    def test_o_wheel_zooms_and_the_fov_slider_sets_the_field_of_view(self):
        from selenium.webdriver.common.action_chains import ActionChains
        from selenium.webdriver.common.actions.wheel_input import ScrollOrigin
        self.reset()
        before = self.camera()

        def distance(c):
            return sum((e - l) ** 2 for e, l in zip(c["eye"], c["lookat"])) ** 0.5
        view = self.driver.find_element("id", "view")
        ActionChains(self.driver).scroll_from_origin(ScrollOrigin.from_element(view), 0, -100).perform()
        self.wait_still()
        zoomed = self.camera()
        self.assertEqual(zoomed["lookat"], before["lookat"])
        self.assertAlmostEqual(distance(zoomed), distance(before) / 1.1, places=9)  # one notch in: 10% closer
        self.driver.execute_script("""
            const fov = document.getElementById('fov');
            fov.value = '35';
            fov.dispatchEvent(new Event('input', { bubbles: true }));""")
        self.wait_still()
        camera = self.camera()
        self.assertEqual(camera["fov"], 35)
        self.assert_same_image(self.frame_png(camera), self.canvas_pixels(), "the view at a field of view of 35")
        self.reset()
        self.assertEqual(self.camera()["fov"], before["fov"])

    def test_p_no_cookie_and_every_request_carries_the_token(self):
        # No cookie (every port of 127.0.0.1 would get it): the page names its files and asks
        # for every frame, scene and export with the token, and the bare address opens nothing.
        self.assertEqual(self.driver.get_cookies(), [])
        addresses = self.driver.execute_script(
            "return performance.getEntriesByType('resource').map((entry) => entry.name)")
        own = [a for a in addresses if a.startswith(self.viewer.base)]
        self.assertTrue(any("/viewer.js?" in a for a in own) and any("/frame." in a for a in own), own[:10])
        for address in own:
            query = urllib.parse.parse_qs(urllib.parse.urlsplit(address).query)
            self.assertEqual(query.get("token"), [self.viewer.token], address)
        try:
            self.driver.get(self.viewer.base)
            self.assertEqual(self.driver.execute_script("return document.getElementById('view')"), None,
                             "the page opened without the token")
        finally:
            self.load(self.viewer)
    def test_q_a_second_finger_on_the_image_does_not_keep_the_view_moving(self):
        # A pinch: one finger drags, a second comes down and both move apart. The second finger
        # had taken the drag over, and the first drag's hold was never given back: the view
        # stayed at 1 sample per pixel, "moving", for good.
        from selenium.webdriver.common.actions import interaction
        from selenium.webdriver.common.actions.action_builder import ActionBuilder
        self.reset()
        left, top, width, height = self.driver.execute_script(
            "const r = document.getElementById('view').getBoundingClientRect(); return [r.left, r.top, r.width, r.height]")
        x, y = int(left + width / 2), int(top + height / 2)
        actions = ActionBuilder(self.driver)
        first = actions.add_pointer_input(interaction.POINTER_TOUCH, "first")
        second = actions.add_pointer_input(interaction.POINTER_TOUCH, "second")
        first.create_pointer_move(x=x - 10, y=y)
        second.create_pause(0)
        first.create_pointer_down()
        second.create_pause(0)
        first.create_pointer_move(x=x - 50, y=y, duration=200)
        second.create_pause(0.2)
        first.create_pause(0)
        second.create_pointer_move(x=x + 10, y=y)
        first.create_pause(0)
        second.create_pointer_down()
        first.create_pointer_move(x=x - 80, y=y, duration=200)
        second.create_pointer_move(x=x + 40, y=y, duration=200)
        first.create_pointer_up(0)
        second.create_pause(0)
        first.create_pause(0)
        second.create_pointer_up(0)
        actions.perform()
        try:
            self.wait_until("return window.clrenderViewer.isStill()", timeout=15, what="the still view after a pinch")
        except AssertionError:
            self.load(self.viewer)  # a page whose view can become still, for the tests after this one
            raise
        self.assertIn("still", self.driver.find_element("id", "fps").text)

    def test_r_a_key_pressed_with_ctrl_alt_or_meta_is_the_browsers(self):
        from selenium.webdriver.common.action_chains import ActionChains
        from selenium.webdriver.common.keys import Keys
        self.reset()
        self.driver.find_element("id", "view").click()  # the focus on the image, as after a drag
        self.wait_still()
        before = self.camera()
        # (Alt+Left, the browser's Back, would leave the page once the page lets it through.)
        for modifier, key in ((Keys.CONTROL, "s"), (Keys.CONTROL, "d"), (Keys.ALT, "a"), (Keys.META, "w")):
            ActionChains(self.driver).key_down(modifier).key_down(key).pause(0.3).key_up(key).key_up(modifier).perform()
        time.sleep(0.3)
        self.assertEqual(self.camera(), before, "a browser shortcut flew the camera")

    def test_s_a_double_click_on_render_video_renders_one_video_and_says_so(self):
        from selenium.webdriver.common.action_chains import ActionChains
        self.reset()
        self.driver.find_element("id", "clear-keys").click()
        first = self.camera()
        self.driver.find_element("id", "record").click()
        self.set_camera(dict(first, eye=[first["eye"][0] + 2.0, first["eye"][1], first["eye"][2]]))
        self.driver.find_element("id", "record").click()
        self.wait_until("return !document.getElementById('render-video').disabled", what="Render video with two keys")
        videos = {name for name in os.listdir(self.work.name) if name.endswith(".mp4")}
        ActionChains(self.driver).double_click(self.driver.find_element("id", "render-video")).perform()
        seen = set()
        deadline = time.monotonic() + 240
        while time.monotonic() < deadline:
            text, kind = self.driver.execute_script(
                "const s = document.getElementById('video-status'); return [s.textContent, s.className]")
            seen.add((text.split(":")[0], kind))
            if text.startswith("Video written") or text.startswith("Video failed"):
                break
            time.sleep(0.02)
        self.assertTrue(text.startswith("Video written to"), f"{text} (seen: {sorted(seen)})")
        self.assertNotEqual(kind, "error", "the video written is shown as an error")
        self.assertNotIn("Video failed", {t for t, _ in seen}, "a double click was reported as a failed video")
        self.assertFalse([t for t, _ in seen if re.search(r"\bof 0\b", t)], f"a count of no frames: {sorted(seen)}")
        self.assertEqual(len({name for name in os.listdir(self.work.name) if name.endswith(".mp4")} - videos), 1)
        self.driver.find_element("id", "clear-keys").click()

    def test_t_the_keyboard_reaches_every_control_and_the_panels_are_announced(self):
        from selenium.webdriver.common.action_chains import ActionChains
        from selenium.webdriver.common.keys import Keys
        self.driver.execute_script("document.activeElement.blur()")
        reached = []
        for _ in range(25):
            ActionChains(self.driver).send_keys(Keys.TAB).perform()
            reached.append(self.driver.execute_script("return document.activeElement.id"))
        for control in ("view", "fov", "still-spp", "reset", "compare-file", "tolerance", "record", "play",
                        "clear-keys", "export"):
            self.assertIn(control, reached, f"Tab does not reach #{control}: {reached}")
        # What a panel says after a click (an export failed, the video written, the comparison,
        # an explanation) is read out by a screen reader, as the image's status is.
        for panel in ("status", "export-status", "video-status", "diff-share", "explain"):
            element = self.driver.find_element("id", panel)
            self.assertTrue(element.get_attribute("role") in ("status", "alert") or element.get_attribute("aria-live"),
                            f"#{panel} is not a live region")

    def test_u_a_stopped_viewer_is_named_in_every_panel(self):
        from selenium.webdriver.common.action_chains import ActionChains
        viewer = Viewer(BINARY, self.scene_path, ["--size", f"{SIZE[0]}x{SIZE[1]}", "--spp", "1",
                                                  "--output-dir", self.work.name], cwd=self.work.name)
        try:
            self.load(viewer)
            first = self.camera()
            self.driver.find_element("id", "record").click()
            self.set_camera(dict(first, eye=[first["eye"][0] + 2.0, first["eye"][1], first["eye"][2]]))
            self.driver.find_element("id", "record").click()
            self.wait_until("return !document.getElementById('render-video').disabled", what="two keys")
            viewer.stop()
            self.driver.find_element("id", "export").click()
            self.driver.find_element("id", "render-video").click()
            ActionChains(self.driver).move_to_element(self.driver.find_element("id", "view")).click().perform()
            expected = "clrender view does not answer (has it stopped?)"
            for panel, prefix in (("export-status", "Export failed: "), ("video-status", "Video failed: "),
                                  ("explain", "cannot explain it: ")):
                text = self.wait_until(f"const t = document.getElementById('{panel}').textContent;"
                                       f"return t.includes({json.dumps(prefix)}) ? t : ''", timeout=20, what=panel)
                self.assertIn(prefix + expected, text)
            self.driver.execute_script("window.clrenderViewer.setCamera(window.clrenderViewer.camera())")
            text = self.wait_until("const t = document.getElementById('status').textContent;"
                                   "return t.includes('answer') ? t : ''", timeout=20, what="the image's status")
            self.assertEqual(text, expected)
        finally:
            viewer.stop()
            self.load(self.viewer)

    def test_v_a_page_loaded_while_a_video_renders_follows_it(self):
        # A video started (here by a request, as by a page since closed or loaded again), and
        # then the page loaded: it shows that video's progress with Render video off, and its
        # end, where its next click had been answered 409.
        # (a video long enough, 111 frames at 16 samples a pixel, to be rendering when the page
        # has loaded: about 2 s here)
        viewer = Viewer(BINARY, self.scene_path, ["--size", "640x360", "--spp", "16", "--output-dir", self.work.name],
                        cwd=self.work.name)
        try:
            keys = [{"eye": [-3 + 0.5 * k, 2, 12 - 0.5 * k], "lookat": [0, 1, 0]} for k in range(12)]
            request = urllib.request.Request(
                f"{viewer.base}render-video?token={viewer.token}", method="POST",
                data=json.dumps({"keys": keys, "name": "earlier"}).encode(),
                headers={"Content-Type": "application/json", "Origin": viewer.base.rstrip("/")})
            with urllib.request.urlopen(request, timeout=60) as response:
                self.assertEqual(json.loads(response.read())["job"], 1)
            self.load(viewer)
            seen = set()
            deadline = time.monotonic() + 240
            while time.monotonic() < deadline:
                text, off = self.driver.execute_script(
                    "return [document.getElementById('video-status').textContent,"
                    " document.getElementById('render-video').disabled]")
                seen.add((text, off))
                if text.startswith("Video"):
                    break
                time.sleep(0.02)
            self.assertEqual(text, f"Video written to {os.path.join(self.work.name, 'earlier.mp4')}", f"seen: {sorted(seen)}")
            frames = [int(m.group(1)) for t, off in seen if off for m in [re.match(r"rendering frame (\d+) of 111$", t)] if m]
            self.assertTrue(frames, f"no progress with the button off: {sorted(seen)}")
            self.assertGreater(max(frames), min(frames), f"the frame shown never moved: {sorted(seen)}")
        finally:
            viewer.stop()
            self.load(self.viewer)


def main():
    global BINARY, SOURCE_DIR
    if len(sys.argv) < 3:
        print(__doc__)
        return 1
    BINARY, SOURCE_DIR = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    browser_or_skip()
    program = unittest.main(argv=[sys.argv[0], *sys.argv[3:]], exit=False, verbosity=2)
    return 0 if program.result.wasSuccessful() else 1


if __name__ == "__main__":
    sys.exit(main())
