// The live image of clrender view: asks the server for the latest camera's frame as soon as
// the previous one has arrived (never more than one request in flight), 1 sample per pixel
// while the camera moves, then, once it has been still for a moment, frames of 4, 16, ...
// samples up to the scene's samples per pixel. The still frame uses the batch renderer's seeds, so it is the image
// `clrender SCENE` writes for that camera.
"use strict";

// The query string of a frame request; numbers are written as JavaScript's shortest exact
// form, so the server reads back exactly the doubles the page holds. A frame of the scene's
// animation (frame not null) is asked for by its number alone: the server places the camera
// on the path with clrender's own interpolation and uses that frame's samples, so the image is
// the batch render of that frame.
function clrenderFrameQuery(token, camera, size, spp, frame) {
  const params = new URLSearchParams();
  if (token) params.set("token", token);
  if (frame === null || frame === undefined) {
    params.set("eye", camera.eye.join(","));
    params.set("lookat", camera.lookat.join(","));
  }
  params.set("up", camera.up.join(","));
  params.set("fov", String(camera.fov));
  params.set("size", `${size[0]}x${size[1]}`);
  params.set("spp", String(spp));
  if (frame !== null && frame !== undefined) params.set("frame", String(frame));
  return params.toString();
}

// A request's address with the page's token: every request must carry it (the server sets no
// cookie). Without one (an address typed without it) the request is refused, and an empty
// token= would be a wrong token.
function clrenderAddress(path, token, params = {}) {
  const query = new URLSearchParams(params);
  if (token) query.set("token", token);
  const text = query.toString();
  return text ? `${path}?${text}` : path;
}

// The text of a failed response: the server answers errors as JSON {"error": ...} or text.
// Its 403 says nothing (to a foreign page): to the page itself it means that the page's token is
// not the viewer's, the viewer having been started again (with a new token) since the page was
// opened. "403: Forbidden" alone read as a refusal of the camera.
const clrenderForbiddenText = "403: the viewer does not take this page's requests: it was started again since " +
                              "the page was opened (each start has a new token); open the address it printed last";

async function clrenderErrorText(response) {
  const text = await response.text();
  if (response.status === 403 && !text.trim()) return clrenderForbiddenText;
  try {
    const parsed = JSON.parse(text);
    if (parsed && parsed.error) {
      return `${response.status}${parsed.parameter ? ` (${parsed.parameter})` : ""}: ${parsed.error}`;
    }
  } catch (e) { /* not JSON: the text as it is */ }
  return `${response.status}: ${text.trim() || response.statusText}`;
}

// The text of a request that got no answer at all: fetch rejects with a TypeError ("Failed to
// fetch") when the viewer has stopped or cannot be reached. Every panel says so in these words;
// the export, video, explanation and comparison panels had shown "Failed to fetch".
function clrenderFailureText(error) {
  return error instanceof TypeError ? "clrender view does not answer (has it stopped?)" : error.message;
}

class ClrenderLiveView {
  // options: token, size [w, h], stillSpp, channel ("rgba" or "png"), onShown(info), onError(text)
  constructor(canvas, options) {
    this.canvas = canvas;
    this.context = canvas.getContext("2d");
    this.token = options.token;
    this.size = options.size;
    this.stillSpp = options.stillSpp;
    this.channel = options.channel === "png" ? "png" : "rgba";
    this.onShown = options.onShown || (() => {});
    this.onError = options.onError || (() => {});
    this.onIdle = null;        // called when moving and the shown image is of the latest camera
    this.stillDelayMs = 120;   // no camera change for this long: the view is still
    this.camera = null;
    this.frame = null;         // the animation frame the camera comes from, null once moved
    this.version = 0;          // counts camera changes
    this.holds = 0;            // drags and held keys in progress: not still even without changes
    this.lastChange = 0;
    this.firstUnsentInput = null;  // time of the oldest input no request has carried yet
    this.inFlight = null;      // {version, spp, abort}
    this.shown = null;         // {version, spp, camera, frame, size}
    this.failedVersion = -1;   // a camera the server refused: not asked again until it changes
    this.busyUntil = 0;        // performance.now() before which the busy server is not asked
    this.shownTimes = [];      // performance.now() of each image shown, the last few seconds
    this.latencies = [];       // input-to-image times in ms, the most recent 2000
    this.history = [];         // {version, spp} of the last 100 images shown
    this.timings = [];         // per image shown: ms to the response's headers, to its body, to drawn
    this.stillTimer = null;
  }

  setCamera(camera, frame = null, inputTime = performance.now()) {
    this.camera = ClrenderCamera.copy(camera);
    this.frame = frame;
    this.version += 1;
    this.lastChange = performance.now();
    if (this.firstUnsentInput === null) this.firstUnsentInput = inputTime;
    // A still frame still rendering is of no use any more; a 1 spp frame is left to arrive,
    // since it shows the motion and the next request follows it at once.
    if (this.inFlight && this.inFlight.spp > 1) this.inFlight.abort.abort();
    this.pump();
  }

  // The samples per pixel of the still frame; the current view is rendered again with them.
  setStillSpp(spp) {
    this.stillSpp = spp;
    if (this.inFlight && this.inFlight.spp > 1) this.inFlight.abort.abort();
    this.pump();
  }

  hold() { this.holds += 1; }
  release() { this.holds = Math.max(0, this.holds - 1); this.lastChange = performance.now(); this.pump(); }

  isStill() {
    return this.holds === 0 && this.shown !== null && this.shown.version === this.version &&
           this.shown.spp === this.stillSpp;
  }

  framesInLastSecond(now = performance.now()) {
    while (this.shownTimes.length && this.shownTimes[0] < now - 1000) this.shownTimes.shift();
    return this.shownTimes.length;
  }

  pump() {
    if (this.inFlight || this.camera === null || this.failedVersion === this.version) return;
    const busy = this.busyUntil - performance.now();
    if (busy > 0) {
      clearTimeout(this.stillTimer);
      this.stillTimer = setTimeout(() => this.pump(), busy);
      return;
    }
    let upToDate = this.shown !== null && this.shown.version === this.version;
    if (upToDate && this.holds > 0 && this.onIdle) {
      this.onIdle();  // a continuous move (held keys) may move the camera now
      if (this.inFlight) return;
      upToDate = this.shown.version === this.version;
    }
    if (!upToDate) { this.request(1); return; }
    if (this.shown.spp === this.stillSpp) return;
    const wait = this.lastChange + this.stillDelayMs - performance.now();
    // Still: the samples go up fourfold at a time (1, 4, 16, ...) to the scene's, so that a
    // scene of many samples sharpens step by step instead of waiting for its last frame.
    if (this.holds === 0 && wait <= 0) {
      this.request(this.shown.spp < this.stillSpp ? Math.min(this.stillSpp, this.shown.spp * 4) : this.stillSpp);
      return;
    }
    clearTimeout(this.stillTimer);
    this.stillTimer = setTimeout(() => this.pump(), Math.max(wait, 10));
  }

  async request(spp) {
    const version = this.version, camera = ClrenderCamera.copy(this.camera), frame = this.frame;
    const size = this.size.slice();
    const inputTime = this.firstUnsentInput;
    this.firstUnsentInput = null;
    const abort = new AbortController();
    this.inFlight = { version, spp, abort };
    const url = `frame.${this.channel}?${clrenderFrameQuery(this.token, camera, size, spp, frame)}`;
    try {
      const sent = performance.now();
      const response = await fetch(url, { signal: abort.signal, cache: "no-store" });
      if (!response.ok) throw await this.failure(response);
      const answered = performance.now();
      const received = await this.draw(response);
      const now = performance.now();
      this.timings.push([answered - sent, received - answered, now - received]);
      if (this.timings.length > 2000) this.timings.shift();
      this.shownTimes.push(now);
      if (inputTime !== null) {
        this.latencies.push(now - inputTime);
        if (this.latencies.length > 2000) this.latencies.shift();
      }
      this.shown = { version, spp, camera, frame, size };
      this.history.push({ version, spp });
      if (this.history.length > 100) this.history.shift();
      this.onShown(this.shown);
    } catch (error) {
      if (error.name === "AbortError" || error.retryAfterMs) {
        if (inputTime !== null && this.firstUnsentInput === null) this.firstUnsentInput = inputTime;
        if (error.retryAfterMs) {
          this.busyUntil = performance.now() + error.retryAfterMs;
          this.onError(`${error.message}; asking again`);
        }
      } else {
        // Not asked again until the camera changes: a refused camera stays refused, and a
        // stopped server would only be asked in a tight loop.
        this.failedVersion = version;
        this.onError(error instanceof TypeError || error.forbidden ? clrenderFailureText(error)
          : `the server refused this view: ${error.message}`);
      }
    } finally {
      this.inFlight = null;
    }
    this.pump();
  }

  // The error of a failed frame. A 503 with Retry-After is the server busy sending frames to
  // other clients, not a refusal of this camera: the same view is asked again after the wait
  // it gives (taken as a refusal, the view stayed unsharpened until the camera moved).
  async failure(response) {
    const error = new Error(await clrenderErrorText(response));
    error.forbidden = response.status === 403;  // the page's, not this camera's
    const seconds = Number(response.headers.get("Retry-After"));
    if (response.status === 503 && seconds > 0) error.retryAfterMs = Math.min(seconds, 60) * 1000;
    return error;
  }

  async draw(response) {
    if (this.channel === "rgba") {
      const width = Number(response.headers.get("X-Width"));
      const height = Number(response.headers.get("X-Height"));
      const bytes = new Uint8ClampedArray(await response.arrayBuffer());
      const received = performance.now();
      if (!(width > 0 && height > 0) || bytes.length !== width * height * 4) {
        throw new Error(`the server sent ${bytes.length} bytes for a ${width}x${height} frame`);
      }
      this.resize(width, height);
      this.context.putImageData(new ImageData(bytes, width, height), 0, 0);
      return received;
    }
    const blob = await response.blob();
    const received = performance.now();
    const bitmap = await createImageBitmap(blob, { premultiplyAlpha: "none", colorSpaceConversion: "none" });
    this.resize(bitmap.width, bitmap.height);
    this.context.drawImage(bitmap, 0, 0);
    bitmap.close();
    return received;
  }

  resize(width, height) {
    if (this.canvas.width !== width || this.canvas.height !== height) {
      this.canvas.width = width;
      this.canvas.height = height;
      // As wide as the page allows, but no taller than most of the window.
      this.canvas.style.maxWidth = `min(100%, calc(85vh * ${width / height}))`;
    }
  }
}
