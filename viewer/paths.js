// Camera paths in clrender view: keys recorded from the live camera, played back in the page,
// exported as a scene with the keys as eyeLocations / lookatLocations, and rendered to a video
// by the server.
"use strict";

class ClrenderPaths {
  // viewer: {token, camera(), setCamera(camera, frame), settled(), sceneName}
  constructor(viewer) {
    this.viewer = viewer;
    this.keys = [];
    this.exported = null;       // the last exported scene, parsed
    this.playTimer = null;
    this.list = document.getElementById("keys");
    this.json = document.getElementById("path-json");
    this.download = document.getElementById("download");
    this.exportStatus = document.getElementById("export-status");
    this.progress = document.getElementById("video-progress");
    this.videoStatus = document.getElementById("video-status");
    document.getElementById("record").addEventListener("click", () => this.record());
    document.getElementById("clear-keys").addEventListener("click", () => this.clear());
    document.getElementById("play").addEventListener("click", () => this.togglePlay());
    document.getElementById("export").addEventListener("click", () => this.exportScene());
    this.videoButton = document.getElementById("render-video");
    this.videoButton.addEventListener("click", () => this.renderVideo());
    this.rendering = false;     // a video is being started or rendered, shown on this page
    this.showKeys();
    this.followRunningVideo();
  }

  // The camera shown: a path frame's camera still on its way from the server is waited for.
  // A camera equal to the last key is not recorded again: a double click on Record key had
  // stored it twice (a video then stood still for a segment).
  async record() {
    if (this.viewer.settled) await this.viewer.settled();
    const camera = this.viewer.camera();
    const last = this.keys[this.keys.length - 1];
    if (last && ClrenderCamera.equal(last, camera)) {
      this.exportStatus.className = "";
      this.exportStatus.textContent = "This camera is the last key already: move it to record another.";
      return;
    }
    this.keys.push(camera);
    this.showKeys();
  }

  clear() {
    this.stop();
    this.keys = [];
    this.showKeys();
  }

  showKeys() {
    const format = (p) => p.map((x) => Number(x.toPrecision(6))).join(", ");
    this.list.replaceChildren(...this.keys.map((key) => {
      const item = document.createElement("li");
      item.textContent = `eye [${format(key.eye)}]  look-at [${format(key.lookat)}]`;
      return item;
    }));
    // A video moves from key to key: with fewer than two there is none to render. While this
    // page's video renders the button is off: a second click (a double click) had been answered
    // 409 ("a video is rendering already") and shown as a failure, and the first video's
    // progress and its "Video written" then in the colour of that error.
    this.videoButton.disabled = this.keys.length < 2 || this.rendering;
    this.videoButton.title = this.rendering ? "a video is rendering"
      : this.keys.length < 2 ? "record two or more keys for a video" : "";
  }

  body() {
    // One up vector and field of view for the whole path (a scene has one): the first key's.
    return JSON.stringify({
      keys: this.keys.map((key) => ({ eye: key.eye, lookat: key.lookat })),
      up: this.keys[0].up,
      fov: this.keys[0].fov,
    });
  }

  async post(path) {
    const response = await fetch(clrenderAddress(path, this.viewer.token), {
      method: "POST", headers: { "Content-Type": "application/json" }, body: this.body(),
    });
    if (!response.ok) throw new Error(await clrenderErrorText(response));
    return response.json();
  }

  needKeys(status, least) {
    if (this.keys.length >= least) return true;
    status.textContent = least === 1 ? "Record at least one key first." : `Record at least ${least} keys first.`;
    status.className = "error";
    return false;
  }

  // Plays the keys with the frame count and fps of the exported scene when there is one (what
  // clrender renders), else clrender's defaults: 10 frames per segment, 24 frames per second.
  togglePlay() {
    if (this.playTimer !== null) { this.stop(); return; }
    if (!this.needKeys(this.exportStatus, 1)) return;  // (it had said nothing at all)
    const settings = (this.exported && this.exported.clrender) || {};
    const perSegment = settings.frames_per_segment || 10;
    const fps = settings.fps || 24;
    const frameCount = settings.frames || (settings.duration ? Math.round(settings.duration * fps) : 0) ||
                       (this.keys.length - 1) * perSegment + 1;
    const keys = this.keys.map((key) => ClrenderCamera.copy(key));
    const start = performance.now();
    document.getElementById("play").textContent = "Stop";
    this.viewer.hold();
    const step = () => {
      const k = Math.min(frameCount - 1, Math.floor((performance.now() - start) * fps / 1000));
      // (the live view shows as many of these cameras as it can render; none is queued)
      this.viewer.setCamera(ClrenderCamera.alongKeys(keys, k, frameCount, settings.interpolation), null);
      if (k >= frameCount - 1) { this.stop(); return; }
      this.playTimer = requestAnimationFrame(step);
    };
    this.playTimer = requestAnimationFrame(step);
  }

  stop() {
    if (this.playTimer === null) return;
    cancelAnimationFrame(this.playTimer);
    this.playTimer = null;
    document.getElementById("play").textContent = "Play";
    this.viewer.release();
  }

  async exportScene() {
    if (!this.needKeys(this.exportStatus, 1)) return;
    this.exportStatus.className = "";
    this.exportStatus.textContent = "exporting…";
    try {
      const answer = await this.post("export");
      this.exported = JSON.parse(answer.scene);
      this.json.textContent = answer.scene;  // for readers of the element's text
      this.json.value = answer.scene;
      this.json.dataset.file = answer.file || "";
      const name = (answer.file || `${this.viewer.sceneName || "scene"}-path.json`).split("/").pop();
      if (this.download.href.startsWith("blob:")) URL.revokeObjectURL(this.download.href);
      this.download.href = URL.createObjectURL(new Blob([answer.scene], { type: "application/json" }));
      this.download.download = name;
      this.download.textContent = `Download ${name}`;
      this.download.hidden = false;
      this.exportStatus.textContent = answer.file ? `Written to ${answer.file}` : "Exported.";
    } catch (error) {
      this.exportStatus.className = "error";
      this.exportStatus.textContent = `Export failed: ${clrenderFailureText(error)}`;
    }
  }

  async renderVideo() {
    if (this.rendering || !this.needKeys(this.videoStatus, 2)) return;
    await this.follow(async () => (await this.post("render-video")).job);
  }

  // A page loaded while a video renders (loaded again, or a second tab) shows that video's
  // progress, with Render video off until it ends, rather than a 409 at the next click.
  async followRunningVideo() {
    let state;
    try {
      const response = await fetch(clrenderAddress("job", this.viewer.token), { cache: "no-store" });
      if (!response.ok) return;  // 404: no video yet in this viewer's session
      state = await response.json();
    } catch (error) {
      return;  // the viewer does not answer: the image's panel says so
    }
    if (state.state !== "running" || this.rendering || !Number.isInteger(state.id)) return;
    await this.follow(async () => state.id);
  }

  // Shows the progress of the job that `start` returns (its number), until it ends.
  async follow(start) {
    this.rendering = true;
    this.showKeys();
    this.videoStatus.className = "";
    this.videoStatus.textContent = "starting the video…";
    this.progress.hidden = false;
    this.progress.value = 0;
    try {
      const job = await start();
      for (;;) {
        const response = await fetch(clrenderAddress("job", this.viewer.token, { id: job }), { cache: "no-store" });
        if (!response.ok) throw new Error(await clrenderErrorText(response));
        const state = await response.json();
        // (a video's frames are "done" only once it is written: until then the frame it is on)
        const rendered = Math.max(state.done, (state.frame || 0) - 1);
        if (state.total > 0) { this.progress.max = state.total; this.progress.value = rendered; }
        if (state.error) throw new Error(state.error);
        if (state.state === "done") {
          this.videoStatus.textContent = `Video written to ${state.file}`;
          this.videoStatus.dataset.file = state.file || "";
          return;
        }
        if (state.state === "failed") throw new Error("the render failed");
        // (until the render has counted its frames the job says 0 of 0)
        this.videoStatus.textContent = state.total > 0 ? `rendering frame ${Math.max(state.frame || 0, 1)} of ${state.total}`
          : "starting the video…";
        await new Promise((resolve) => setTimeout(resolve, 250));
      }
    } catch (error) {
      this.videoStatus.className = "error";
      this.videoStatus.textContent = `Video failed: ${clrenderFailureText(error)}`;
    } finally {
      this.rendering = false;
      this.showKeys();
    }
  }
}
