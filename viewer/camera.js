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

  // The coordinates a scene may have (docs/scene-format.md, Numeric ranges).
  const kMaxCoordinate = 1e15;

  // Moves the eye towards (factor < 1) or away from (factor > 1) the look-at point, by that
  // factor at every distance: a scene may be a model of 1e-5 or a planet of 1e8. A move that
  // would take the eye beyond the coordinates a scene may have, or so near the look-at point
  // that their distance rounds to 0 (no orbit could turn it), leaves the camera as it is (a
  // distance held within [1e-3, 1e6] made a notch out from 2e6 bring the eye closer, and a
  // notch in at 1e-5 move it 100 times away).
  function zoom(camera, factor) {
    const next = copy(camera);
    next.eye = add(camera.lookat, scale(sub(camera.eye, camera.lookat), factor));
    if (!(length(sub(next.eye, camera.lookat)) > 0) || !next.eye.every((x) => Math.abs(x) <= kMaxCoordinate)) {
      return camera;
    }
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

  // The interpolation of clrender's camera paths (host/scene/camera_path.cpp), step for step:
  // frame k of F lies numerator / denominator of the way from key `segment` to the next, in
  // whole numbers, so that a frame on a key is that key exactly.
  const lerpExact = (a, b, numerator, denominator) => a.map((x, i) => x + ((b[i] - x) * numerator) / denominator);
  const lerpKnots = (a, ta, b, tb, t) => a.map((x, i) => (x * (tb - t) + b[i] * (t - ta)) / (tb - ta));
  const knotInterval = (from, to) => Math.sqrt(length(sub(to, from)));
  const same = (a, b) => a[0] === b[0] && a[1] === b[1] && a[2] === b[2];

  // The centripetal Catmull-Rom segment from p1 (u = 0) to p2 (u = 1), Barry-Goldman's pyramid.
  function centripetalCatmullRom(p0, p1, p2, p3, u) {
    const t0 = 0, t1 = t0 + knotInterval(p0, p1), t2 = t1 + knotInterval(p1, p2), t3 = t2 + knotInterval(p2, p3);
    const t = t1 + u * (t2 - t1);
    const a1 = lerpKnots(p0, t0, p1, t1, t), a2 = lerpKnots(p1, t1, p2, t2, t), a3 = lerpKnots(p2, t2, p3, t3, t);
    const b1 = lerpKnots(a1, t0, a2, t2, t), b2 = lerpKnots(a2, t1, a3, t3, t);
    return lerpKnots(b1, t1, b2, t2, t);
  }

  // One point curve (eyes or look-at points) at a path position, neighbours mirrored at the
  // ends and where they coincide with a key, as clrender does.
  function pointOnPath(points, segment, numerator, denominator, interpolation) {
    const from = points[segment], to = points[segment + 1];
    if (numerator === 0) return from.slice();
    if (interpolation !== "catmull-rom" || same(from, to)) return lerpExact(from, to, numerator, denominator);
    const mirror = (p, q) => p.map((x, i) => 2.0 * x - q[i]);
    const before = segment === 0 || same(points[segment - 1], from) ? mirror(from, to) : points[segment - 1];
    const after = segment + 2 >= points.length || same(points[segment + 2], to) ? mirror(to, from) : points[segment + 2];
    return centripetalCatmullRom(before, from, to, after, numerator / denominator);
  }

  // The camera of frame k of F of an animation through keys ("linear" or "catmull-rom"), with
  // the first key's up and fov: the exported scene has one of each, the first key's (Play gave
  // each segment its first key's, and the last frame the last key's: keys recorded with the
  // slider moved between them played at other fields of view than the export renders).
  function alongKeys(keys, k, frameCount, interpolation = "linear") {
    const next = copy(keys[0]);
    if (keys.length === 1 || frameCount < 2) return next;
    const denominator = frameCount - 1;
    const scaled = k * (keys.length - 1);
    const segment = Math.floor(scaled / denominator), numerator = scaled % denominator;
    if (segment >= keys.length - 1) {
      next.eye = keys[keys.length - 1].eye.slice();
      next.lookat = keys[keys.length - 1].lookat.slice();
      return next;
    }
    next.eye = pointOnPath(keys.map((key) => key.eye), segment, numerator, denominator, interpolation);
    next.lookat = pointOnPath(keys.map((key) => key.lookat), segment, numerator, denominator, interpolation);
    return next;
  }

  return { copy, equal, orbit, zoom, fly, distance, alongKeys, sub, length };
})();
