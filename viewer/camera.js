// Camera moves of clrender view: orbit around the look-at point, zoom, fly, and the
// interpolation between recorded keys. A camera is {eye, lookat, up, fov} with points as
// [x, y, z] and fov in degrees across the image's larger side, as in the scene file.
"use strict";

const ClrenderCamera = (() => {
  const add = (a, b) => [a[0] + b[0], a[1] + b[1], a[2] + b[2]];
  const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
  const scale = (a, s) => [a[0] * s, a[1] * s, a[2] * s];
  const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
  const length = (a) => Math.sqrt(dot(a, a));
  const unit = (a) => { const l = length(a); return l > 0 ? scale(a, 1 / l) : [0, 0, 0]; };
  const lerp = (a, b, t) => add(a, scale(sub(b, a), t));

  // Rodrigues' rotation of v about the unit axis k by angle radians.
  function rotate(v, k, angle) {
    const c = Math.cos(angle), s = Math.sin(angle);
    return add(add(scale(v, c), scale(cross(k, v), s)), scale(k, dot(k, v) * (1 - c)));
  }

  function copy(camera) {
    return { eye: camera.eye.slice(), lookat: camera.lookat.slice(), up: camera.up.slice(), fov: camera.fov };
  }

  function equal(a, b) {
    return a.fov === b.fov && ["eye", "lookat", "up"].every((k) => a[k].every((x, i) => x === b[k][i]));
  }

  // Turns the eye around the look-at point: yaw about the up vector, pitch about the camera's
  // right axis. The pitch stops 1 degree short of the up vector (and of its opposite), where the
  // view direction would be parallel to up and the camera undefined (the scene rules).
  function orbit(camera, yaw, pitch) {
    const up = unit(camera.up);
    let offset = sub(camera.eye, camera.lookat);
    const radius = length(offset);
    if (radius === 0 || length(up) === 0) return camera;
    offset = rotate(offset, up, yaw);
    const polar = Math.acos(Math.max(-1, Math.min(1, dot(unit(offset), up))));
    const limit = Math.PI / 180;
    const wanted = Math.max(limit, Math.min(Math.PI - limit, polar - pitch));
    const right = unit(cross(offset, up));
    if (length(right) > 0) offset = rotate(offset, right, polar - wanted);
    const next = copy(camera);
    next.eye = add(camera.lookat, scale(unit(offset), radius));
    return next;
  }

  // Moves the eye towards (factor < 1) or away from (factor > 1) the look-at point.
  function zoom(camera, factor) {
    const offset = sub(camera.eye, camera.lookat);
    const radius = length(offset);
    const wanted = Math.min(1e6, Math.max(1e-3, radius * factor));
    if (radius === 0) return camera;
    const next = copy(camera);
    next.eye = add(camera.lookat, scale(offset, wanted / radius));
    return next;
  }

  // Moves eye and look-at point together: forward along the view, right across it, and up
  // along the up vector, each in scene units.
  function fly(camera, forward, right, upward) {
    const dir = unit(sub(camera.lookat, camera.eye));
    const side = unit(cross(dir, camera.up));
    const move = add(add(scale(dir, forward), scale(side, right)), scale(unit(camera.up), upward));
    const next = copy(camera);
    next.eye = add(camera.eye, move);
    next.lookat = add(camera.lookat, move);
    return next;
  }

  function distance(camera) { return length(sub(camera.eye, camera.lookat)); }

  // The camera of frame k of an animation through keys with linear interpolation, as clrender
  // places it (docs/scene-format.md, Extensions): frame k of F lies at s = k (N - 1) / (F - 1).
  function alongKeys(keys, k, frameCount) {
    if (keys.length === 1 || frameCount < 2) return copy(keys[0]);
    if (k >= frameCount - 1) return copy(keys[keys.length - 1]);  // exactly the last key
    const s = k * (keys.length - 1) / (frameCount - 1);
    const i = Math.min(keys.length - 2, Math.floor(s));
    const t = s - i;
    if (t === 0) return copy(keys[i]);
    const next = copy(keys[i]);
    next.eye = lerp(keys[i].eye, keys[i + 1].eye, t);
    next.lookat = lerp(keys[i].lookat, keys[i + 1].lookat, t);
    return next;
  }

  return { copy, equal, orbit, zoom, fly, distance, alongKeys, sub, length };
})();
