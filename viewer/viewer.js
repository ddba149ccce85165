// clrender view's page: loads the scene's camera from the server, wires the mouse, wheel and
// keys to camera moves, and the panels (paths, explanations, comparison) to the server's
// endpoints. window.clrenderViewer is the page's state for scripts (the browser tests and the
// viewer benchmark read it).
"use strict";

(() => {
  const params = new URLSearchParams(location.search);
  const token = params.get("token") || "";
  const canvas = document.getElementById("view");
  const status = document.getElementById("status");
  const fpsText = document.getElementById("fps");
  const fovInput = document.getElementById("fov");
  const fovValue = document.getElementById("fov-value");
  const timeInput = document.getElementById("time");
  const timeValue = document.getElementById("time-value");
  const explainBox = document.getElementById("explain");

  let scene = null;     // the answer of /scene.json
  let live = null;
  let explainSerial = 0;

  const api = {
    ready: false,
    token,
    sceneName: "",
    camera: () => ClrenderCamera.copy(live.camera),
    setCamera: (camera, frame = null, inputTime = performance.now()) => {
      live.setCamera(camera, frame, inputTime);
      fovInput.value = String(camera.fov);
      fovValue.textContent = `${Number(camera.fov.toPrecision(4))}°`;
    },
    hold: () => live.hold(),
    release: () => live.release(),
    isStill: () => live.isStill(),
    shown: () => live.shown,
    framesInLastSecond: () => live.framesInLastSecond(),
    latencies: () => live.latencies.slice(),
    timings: () => live.timings.slice(),
    history: () => live.history.slice(),
    resetStats: () => { live.latencies = []; live.shownTimes = []; live.timings = []; },
    scene: () => scene,
    // What a still frame of the current view is rendered with: the comparison's reference.
    stillRequest: () => ({ camera: ClrenderCamera.copy(live.camera), frame: live.frame,
                           size: live.size.slice(), spp: live.stillSpp }),
    explain: (x, y, request, note) => explain(x, y, request, note),
  };
  window.clrenderViewer = api;

  function setStatus(text, isError = false) {
    status.textContent = text;
    status.className = isError ? "error" : "";
  }

  async function start() {
    try {
      const response = await fetch(clrenderAddress("scene.json", token), { cache: "no-store" });
      if (!response.ok) throw new Error(await clrenderErrorText(response));
      scene = await response.json();
    } catch (error) {
      setStatus(`Cannot load the scene: ${clrenderFailureText(error)}`, true);
      return;
    }
    api.sceneName = scene.name || "";
    document.getElementById("scene-name").textContent = api.sceneName;
    document.title = `clrender view: ${api.sceneName}`;
    live = new ClrenderLiveView(canvas, {
      token, size: scene.size, stillSpp: Math.max(1, scene.spp || 1), channel: params.get("channel") || "rgba",
      onShown: (shown) => {
        showFps();  // at once, not only on the next tick: a reader right after a move sees it
        canvas.dataset.spp = String(shown.spp);
        canvas.dataset.still = String(live.isStill());
        setStatus(`${shown.size[0]}x${shown.size[1]}, ${shown.spp} sample${shown.spp > 1 ? "s" : ""} per pixel` +
                  (live.isStill() ? " (the still frame, as clrender renders it)" : ""));
      },
      // (the program's name stays as it is written: "clrender view does not answer ...")
      onError: (text) => setStatus(text.startsWith("clrender") ? text : text.charAt(0).toUpperCase() + text.slice(1),
                                   true),
    });
    // Still samples: the scene's (the batch image) by default; 16 smooths a scene of 1.
    const stillSelect = document.getElementById("still-spp");
    const sceneSpp = live.stillSpp;
    [...new Set([sceneSpp, 1, 4, 16, 64])].sort((a, b) => a - b).forEach((n) => {
      const option = new Option(n === sceneSpp ? `${n} (the scene's)` : String(n), String(n));
      option.selected = n === sceneSpp;
      stillSelect.add(option);
    });
    stillSelect.addEventListener("change", () => live.setStillSpp(Number(stillSelect.value)));
    const frames = Math.max(1, scene.frames || 1);
    timeInput.max = String(frames - 1);
    document.getElementById("time-label").hidden = frames < 2;
    const sceneCamera = fromScene(scene.camera);
    api.setCamera(sceneCamera, frames > 1 ? 0 : null);
    new ClrenderPaths(api);
    const compare = new ClrenderCompare(api);
    api.comparison = () => (compare.result
      ? { off: compare.result.off, total: compare.result.total, share: compare.result.off / compare.result.total,
          worst: compare.result.worst, worstAt: [compare.result.worstX, compare.result.worstY] }
      : null);
    wireInput(sceneCamera, frames);
    setInterval(showFps, 250);  // and as the last second's images age out
    api.ready = true;
  }

  function fromScene(camera) {
    return { eye: camera.eye.map(Number), lookat: camera.lookat.map(Number), up: camera.up.map(Number),
             fov: Number(camera.fov) };
  }

  function showFps() {
    const n = live.framesInLastSecond();
    const shown = live.shown;
    const state = live.isStill() ? "still" : (shown ? `${shown.spp} spp, moving` : "waiting");
    fpsText.textContent = `${n} fps (${state})`;
  }

  // Maps a pointer position on a (possibly scaled) canvas to the image pixel under it.
  function pixelAt(target, event) {
    const rect = target.getBoundingClientRect();
    const x = Math.floor((event.clientX - rect.left) * target.width / rect.width);
    const y = Math.floor((event.clientY - rect.top) * target.height / rect.height);
    return [Math.min(target.width - 1, Math.max(0, x)), Math.min(target.height - 1, Math.max(0, y))];
  }

  async function explain(x, y, request, note) {
    const serial = ++explainSerial;
    const query = clrenderFrameQuery(token, request.camera, request.size, request.spp, request.frame);
    explainBox.textContent = `Pixel (${x}, ${y}): asking clrender…`;
    explainBox.dataset.x = String(x);
    explainBox.dataset.y = String(y);
    try {
      const response = await fetch(`explain?x=${x}&y=${y}&${query}`, { cache: "no-store" });
      const text = response.ok ? await response.text() : `Cannot explain it: ${await clrenderErrorText(response)}`;
      if (serial !== explainSerial) return;
      explainBox.textContent = `Pixel (${x}, ${y}) of the ${request.size[0]}x${request.size[1]} view` +
                               `${note ? `\n${note}` : ""}\n\n${text}`;
    } catch (error) {
      if (serial !== explainSerial) return;
      explainBox.textContent = `Pixel (${x}, ${y}): cannot explain it: ${clrenderFailureText(error)}`;
    }
  }

  function wireInput(sceneCamera, frames) {
    // Drag: orbit (a quarter turn across 300 CSS pixels). A press without movement is a click.
    // One pointer drags: a second finger (a pinch) or a pen while it is down is left out. It had
    // taken the drag over, and the first drag's hold of the view was never given back: the view
    // stayed at 1 sample per pixel, "moving", until the page was loaded again.
    let drag = null;
    canvas.addEventListener("pointerdown", (event) => {
      if (event.button !== 0 || drag) return;
      canvas.setPointerCapture(event.pointerId);
      canvas.focus();
      drag = { id: event.pointerId, x: event.clientX, y: event.clientY, startX: event.clientX, startY: event.clientY,
               moved: false };
    });
    canvas.addEventListener("pointermove", (event) => {
      if (!drag || event.pointerId !== drag.id) return;
      const dx = event.clientX - drag.x, dy = event.clientY - drag.y;
      if (!drag.moved && Math.hypot(event.clientX - drag.startX, event.clientY - drag.startY) < 4) return;
      if (!drag.moved) { drag.moved = true; live.hold(); }
      drag.x = event.clientX;
      drag.y = event.clientY;
      const perPixel = (Math.PI / 2) / 300;
      api.setCamera(ClrenderCamera.orbit(live.camera, -dx * perPixel, -dy * perPixel), null, event.timeStamp);
    });
    const endDrag = (event, cancelled) => {
      if (!drag || event.pointerId !== drag.id) return;
      const wasDrag = drag.moved;
      drag = null;
      if (wasDrag) live.release();
      else if (!cancelled && live.shown) {
        const [x, y] = pixelAt(canvas, event);
        const shown = live.shown;
        explain(x, y, { camera: shown.camera, frame: shown.frame, size: shown.size, spp: shown.spp });
      }
    };
    canvas.addEventListener("pointerup", (event) => endDrag(event, false));
    canvas.addEventListener("pointercancel", (event) => endDrag(event, true));
    // The capture lost without a pointerup (the pointer's element taken away, a capture taken by
    // another element): the drag ends, not a click. After a pointerup the drag has ended already.
    canvas.addEventListener("lostpointercapture", (event) => endDrag(event, true));

    // Wheel: zoom towards the look-at point, 10% per notch.
    canvas.addEventListener("wheel", (event) => {
      event.preventDefault();
      const notches = event.deltaMode === 0 ? event.deltaY / 100 : event.deltaY / 3;
      api.setCamera(ClrenderCamera.zoom(live.camera, Math.pow(1.1, notches)), null, event.timeStamp);
    }, { passive: false });

    // Keys: fly while held, at half the look-at distance per second (Shift: four times faster).
    const held = new Set();
    const moves = { KeyW: [1, 0, 0], ArrowUp: [1, 0, 0], KeyS: [-1, 0, 0], ArrowDown: [-1, 0, 0],
                    KeyA: [0, -1, 0], ArrowLeft: [0, -1, 0], KeyD: [0, 1, 0], ArrowRight: [0, 1, 0],
                    KeyQ: [0, 0, -1], KeyE: [0, 0, 1] };
    let flying = null;
    const typing = (event) => ["INPUT", "TEXTAREA", "SELECT"].includes(event.target.tagName);
    // Moves the camera as far as the held keys have taken it by `now`.
    const advance = (now) => {
      const seconds = Math.min(0.1, (now - flying.last) / 1000);
      if (seconds <= 0) return;
      flying.last = now;
      const speed = 0.5 * ClrenderCamera.distance(live.camera) * (flying.fast ? 4 : 1) * seconds;
      const sum = [0, 0, 0];
      held.forEach((code) => moves[code].forEach((m, i) => { sum[i] += m; }));
      if (sum.some((m) => m !== 0)) {
        api.setCamera(ClrenderCamera.fly(live.camera, sum[0] * speed, sum[1] * speed, sum[2] * speed), null, now);
      }
    };
    const fly = (now) => {
      if (held.size === 0) { flying = null; live.release(); return; }
      advance(now);
      flying.frame = requestAnimationFrame(fly);
    };
    // An image arrived before the next display frame moved the camera: move it now, so that
    // the next request need not wait for the display.
    live.onIdle = () => { if (flying !== null && held.size > 0) advance(performance.now()); };
    // A key pressed with Ctrl, Alt or Meta is the browser's shortcut (Ctrl+S, Ctrl+D, Alt+Left),
    // not a move: it had flown the camera and been kept from the browser, and on macOS a letter
    // pressed with Cmd sends no keyup, so the camera flew on until the window lost the focus.
    const shortcut = (event) => event.ctrlKey || event.altKey || event.metaKey;
    document.addEventListener("keydown", (event) => {
      if (typing(event) || shortcut(event) || !(event.code in moves) || !live) return;
      event.preventDefault();
      held.add(event.code);
      if (flying === null) {
        live.hold();
        flying = { last: event.timeStamp, fast: event.shiftKey };
        api.setCamera(live.camera, null, event.timeStamp);  // the input's time starts the latency
        flying.frame = requestAnimationFrame(fly);
      }
      flying.fast = event.shiftKey;
    });
    document.addEventListener("keyup", (event) => { held.delete(event.code); });
    window.addEventListener("blur", () => held.clear());

    fovInput.addEventListener("input", (event) => {
      const camera = ClrenderCamera.copy(live.camera);
      camera.fov = Number(fovInput.value);
      api.setCamera(camera, null, event.timeStamp);
    });
    const sceneFrame = frames > 1 ? 0 : null;
    document.getElementById("reset").addEventListener("click", () => {
      timeInput.value = "0";
      timeValue.textContent = "0";
      api.setCamera(sceneCamera, sceneFrame);
    });
    timeInput.addEventListener("input", (event) => placeFrame(Number(timeInput.value), event.timeStamp));
  }

  // Frame k of the scene's path: its camera is asked of the server, which places it as a batch
  // render does (the scene's interpolation, Catmull-Rom too), so that the camera a key records
  // and a drag starts from is the one shown, never a guess of the page's. Until it is here the
  // view is held: not still, and a key recorded meanwhile waits for it (api.settled).
  let placingSerial = 0;
  let placing = Promise.resolve();
  api.settled = () => placing;

  function placeFrame(k, inputTime) {
    timeValue.textContent = String(k);
    const serial = ++placingSerial;
    const version = live.version;  // a move meanwhile (a drag, Reset) wins over the late answer
    live.hold();
    placing = (async () => {
      try {
        const response = await fetch(clrenderAddress("camera.json", token, { frame: k }), { cache: "no-store" });
        if (!response.ok) throw new Error(await clrenderErrorText(response));
        const camera = fromScene(await response.json());
        if (serial === placingSerial && live.version === version) api.setCamera(camera, k, inputTime);
      } catch (error) {
        if (serial === placingSerial) setStatus(`Cannot place frame ${k}: ${clrenderFailureText(error)}`, true);
      } finally {
        live.release();
      }
    })();
  }

  start();
})();
