// Comparing a dropped image (a student's render of the same scene and camera) with clrender's
// still frame: a heat map of the differing pixels, the share of pixels off by more than the
// tolerance in any colour channel, and click-to-explain on the heat map.
"use strict";

// Reads a binary PPM (P6, maxval 255 or less): clrender writes PPM frames, which browsers do
// not decode themselves. Returns ImageData, or throws with the reason.
function clrenderDecodePpm(bytes) {
  let at = 0;
  const token = () => {
    for (;;) {
      while (at < bytes.length && /\s/.test(String.fromCharCode(bytes[at]))) at += 1;
      if (bytes[at] !== 35) break;  // '#': a comment to the end of the line
      while (at < bytes.length && bytes[at] !== 10) at += 1;
    }
    let text = "";
    while (at < bytes.length && !/\s/.test(String.fromCharCode(bytes[at]))) text += String.fromCharCode(bytes[at++]);
    return text;
  };
  if (token() !== "P6") throw new Error("not a binary PPM (P6)");
  const width = Number(token()), height = Number(token()), maxval = Number(token());
  at += 1;  // the one whitespace byte after maxval
  if (!(width > 0 && height > 0 && maxval > 0 && maxval < 256)) throw new Error("a PPM header clrender cannot read");
  if (bytes.length - at < width * height * 3) throw new Error("the PPM file is cut short");
  const out = new Uint8ClampedArray(width * height * 4);
  for (let i = 0; i < width * height; i += 1) {
    for (let c = 0; c < 3; c += 1) out[i * 4 + c] = Math.round(bytes[at + i * 3 + c] * 255 / maxval);
    out[i * 4 + 3] = 255;
  }
  return new ImageData(out, width, height);
}

async function clrenderDecodeImage(file) {
  const bytes = new Uint8Array(await file.arrayBuffer());
  if (bytes[0] === 80 && bytes[1] === 54) return clrenderDecodePpm(bytes);  // "P6"
  let bitmap;
  try {
    bitmap = await createImageBitmap(new Blob([bytes]), { premultiplyAlpha: "none", colorSpaceConversion: "none" });
  } catch (error) {
    throw new Error(`${file.name} is not an image the browser can read (PNG, JPEG, PPM, …)`);
  }
  const canvas = document.createElement("canvas");
  canvas.width = bitmap.width;
  canvas.height = bitmap.height;
  const context = canvas.getContext("2d");
  context.drawImage(bitmap, 0, 0);
  bitmap.close();
  return context.getImageData(0, 0, canvas.width, canvas.height);
}

// The per-pixel comparison: a pixel is off when one of its R, G, B values differs by more than
// tolerance (0-255). Alpha is left out: clrender's images are opaque.
function clrenderDiffImages(reference, other, tolerance) {
  const { width, height } = reference;
  const a = reference.data, b = other.data;
  const heat = new ImageData(width, height);
  const h = heat.data;
  const largest = new Uint8Array(width * height);
  let off = 0, worst = 0, worstAt = 0;
  for (let p = 0, i = 0; p < width * height; p += 1, i += 4) {
    const d = Math.max(Math.abs(a[i] - b[i]), Math.abs(a[i + 1] - b[i + 1]), Math.abs(a[i + 2] - b[i + 2]));
    largest[p] = d;
    if (d > worst) { worst = d; worstAt = p; }
    if (d > tolerance) {
      off += 1;
      // yellow for a difference just over the tolerance, red from 64/255 up
      const t = Math.min(1, (d - tolerance) / Math.max(1, 64 - tolerance));
      h[i] = 255; h[i + 1] = Math.round(255 * (1 - t)); h[i + 2] = 0;
    } else {
      // matching pixels: clrender's image, dimmed, so the differences stand out
      const grey = Math.round((a[i] * 0.3 + a[i + 1] * 0.59 + a[i + 2] * 0.11) * 0.35);
      h[i] = grey; h[i + 1] = grey; h[i + 2] = grey;
    }
    h[i + 3] = 255;
  }
  return { width, height, off, total: width * height, worst, worstX: worstAt % width,
           worstY: Math.floor(worstAt / width), heat, largest };
}

class ClrenderCompare {
  // viewer: {token, stillRequest() -> {camera, frame, size, spp}, explain(x, y, request, note)}
  constructor(viewer) {
    this.viewer = viewer;
    this.reference = null;
    this.student = null;
    this.request = null;        // the camera and size the reference was rendered with
    this.result = null;
    this.share = document.getElementById("diff-share");
    this.canvas = document.getElementById("diff");
    this.tolerance = document.getElementById("tolerance");
    this.overlay = document.getElementById("drop-overlay");
    const input = document.getElementById("compare-file");
    input.addEventListener("change", () => { if (input.files.length) this.compareFile(input.files[0]); input.value = ""; });
    this.tolerance.addEventListener("input", () => this.show());
    this.canvas.addEventListener("click", (event) => this.explainAt(event));
    let depth = 0;
    const hasFiles = (event) => event.dataTransfer && Array.from(event.dataTransfer.types || []).includes("Files");
    document.addEventListener("dragenter", (event) => { if (hasFiles(event)) { depth += 1; this.overlay.hidden = false; } });
    document.addEventListener("dragleave", () => { depth = Math.max(0, depth - 1); if (depth === 0) this.overlay.hidden = true; });
    document.addEventListener("dragover", (event) => { event.preventDefault(); });
    document.addEventListener("drop", (event) => {
      event.preventDefault();
      depth = 0;
      this.overlay.hidden = true;
      const files = event.dataTransfer ? event.dataTransfer.files : null;
      if (files && files.length) this.compareFile(files[0]);
    });
  }

  message(text, isError) {
    this.share.textContent = text;
    this.share.className = isError ? "error" : "";
    delete this.share.dataset.share;
  }

  async compareFile(file) {
    this.canvas.hidden = true;
    this.result = null;
    this.message(`comparing ${file.name} with clrender's render of this view…`, false);
    try {
      const request = this.viewer.stillRequest();
      const [reference, student] = await Promise.all([this.fetchReference(request), clrenderDecodeImage(file)]);
      if (reference.width !== student.width || reference.height !== student.height) {
        this.message(`${file.name} is ${student.width}x${student.height} but this view renders ` +
                     `${reference.width}x${reference.height}: compare a render of the same size ` +
                     `(clrender SCENE --size ${reference.width}x${reference.height}, or start clrender view ` +
                     `with --size ${student.width}x${student.height}).`, true);
        return;
      }
      this.reference = reference;
      this.student = student;
      this.request = request;
      this.fileName = file.name;
      this.show();
    } catch (error) {
      this.message(`Cannot compare ${file.name}: ${clrenderFailureText(error)}`, true);
    }
  }

  async fetchReference(request) {
    const query = clrenderFrameQuery(this.viewer.token, request.camera, request.size, request.spp, request.frame);
    const response = await fetch(`frame.rgba?${query}`, { cache: "no-store" });
    if (!response.ok) throw new Error(await clrenderErrorText(response));
    const width = Number(response.headers.get("X-Width")), height = Number(response.headers.get("X-Height"));
    return new ImageData(new Uint8ClampedArray(await response.arrayBuffer()), width, height);
  }

  show() {
    if (!this.reference) return;
    const tolerance = Math.max(0, Math.min(255, Math.round(Number(this.tolerance.value) || 0)));
    const result = clrenderDiffImages(this.reference, this.student, tolerance);
    this.result = result;
    this.canvas.width = result.width;
    this.canvas.height = result.height;
    this.canvas.getContext("2d").putImageData(result.heat, 0, 0);
    this.canvas.hidden = false;
    const share = result.off / result.total;
    let text = `${(100 * share).toFixed(2)}% of the pixels of ${this.fileName} differ by more than ` +
               `${tolerance}/255 (${result.off} of ${result.total})`;
    text += result.worst > 0
      ? `; the largest difference, ${result.worst}/255, is at pixel (${result.worstX}, ${result.worstY}).`
      : "; the images are identical.";
    if (result.off > 0) text += " Click a yellow or red pixel of the heat map to explain it.";
    this.share.textContent = text;
    this.share.className = "";
    this.share.dataset.share = String(share);
    this.share.dataset.off = String(result.off);
    this.share.dataset.total = String(result.total);
  }

  explainAt(event) {
    if (!this.result) return;
    const rect = this.canvas.getBoundingClientRect();
    const x = Math.min(this.result.width - 1, Math.floor((event.clientX - rect.left) * this.result.width / rect.width));
    const y = Math.min(this.result.height - 1, Math.floor((event.clientY - rect.top) * this.result.height / rect.height));
    const i = (y * this.result.width + x) * 4;
    const rgb = (data) => `(${data[i]}, ${data[i + 1]}, ${data[i + 2]})`;
    const note = `${this.fileName} has ${rgb(this.student.data)}, clrender ${rgb(this.reference.data)}: ` +
                 `a difference of ${this.result.largest[y * this.result.width + x]}/255.`;
    this.viewer.explain(x, y, this.request, note);
  }
}
