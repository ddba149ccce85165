// The page's camera moves (viewer/camera.js) at every scale a scene may have, without a browser:
// `node tests/browser/camera_moves_test.js SOURCE_DIR` exits 0 when every check holds, 1 otherwise.
"use strict";

const fs = require("fs");
const path = require("path");

const source = fs.readFileSync(path.join(process.argv[2], "viewer", "camera.js"), "utf8");
const ClrenderCamera = new Function(`${source}\nreturn ClrenderCamera;`)();

let failures = 0;
function check(ok, what) {
  if (!ok) {
    failures += 1;
    console.log(`FAILED: ${what}`);
  }
}

function cameraAt(distance) {
  return { eye: [0, 0.6 * distance, 0.8 * distance], lookat: [0, 0, 0], up: [0, 1, 0], fov: 60 };
}

// One wheel notch is 10% closer or farther, the look-at point and the view direction kept, from a
// model of 1e-5 to a planet of 5e12 (the page held the distance within [1e-3, 1e6]: a notch out
// at 2e6 brought the eye closer, a notch in at 1e-5 took it 100 times away).
for (const distance of [1e-9, 1e-5, 0.5, 10, 2e6, 5e12]) {
  for (const factor of [1.1, 1 / 1.1]) {
    const before = cameraAt(distance);
    const after = ClrenderCamera.zoom(before, factor);
    const ratio = ClrenderCamera.distance(after) / distance;
    check(Math.abs(ratio - factor) < 1e-12, `zoom x${factor} at ${distance}: x${ratio}`);
    check(after.lookat.every((x, i) => x === before.lookat[i]), `zoom at ${distance} keeps the look-at point`);
    check(Math.abs(after.eye[1] / after.eye[2] - 0.75) < 1e-12, `zoom at ${distance} keeps the view direction`);
  }
}

// At the end of the coordinates a scene may have (+-1e15) a notch out leaves the camera as it is.
const farthest = { eye: [0, 0, 9.5e14], lookat: [0, 0, 0], up: [0, 1, 0], fov: 60 };
check(ClrenderCamera.zoom(farthest, 1.1).eye[2] === 9.5e14, "a notch out beyond 1e15 leaves the eye");

// Notches in never bring the eye onto the look-at point (which no scene allows).
let near = { eye: [0, 0, 1e-100], lookat: [0, 0, 0], up: [0, 1, 0], fov: 60 };
for (let i = 0; i < 10000; ++i) near = ClrenderCamera.zoom(near, 1 / 1.1);
check(ClrenderCamera.distance(near) > 0, "notches in stop short of the look-at point");

// Play goes through the keys as the exported scene will: every frame with the first key's fov
// and up, which the export writes (each segment had its first key's, the last frame the last
// key's: keys recorded with the fov slider moved between them played at other fields of view).
const keys = [{ eye: [0, 0, 10], lookat: [0, 0, 0], up: [0, 1, 0], fov: 60 },
              { eye: [10, 0, 0], lookat: [0, 0, 1], up: [0, 1, 0], fov: 30 },
              { eye: [0, 0, -10], lookat: [0, 0, 0], up: [1, 1, 0], fov: 90 }];
for (const interpolation of ["linear", "catmull-rom"]) {
  for (let k = 0; k < 21; ++k) {
    const camera = ClrenderCamera.alongKeys(keys, k, 21, interpolation);
    const what = `${interpolation} frame ${k}: fov ${camera.fov}, up ${camera.up}`;
    check(camera.fov === 60 && camera.up.join() === "0,1,0", what);
  }
  const last = ClrenderCamera.alongKeys(keys, 20, 21, interpolation);
  check(last.eye.join() === "0,0,-10" && last.lookat.join() === "0,0,0", `${interpolation}: the last key`);
  const middle = ClrenderCamera.alongKeys(keys, 10, 21, interpolation);
  check(middle.eye.join() === "10,0,0" && middle.lookat.join() === "0,0,1", `${interpolation}: the second key`);
}

if (failures) process.exit(1);
console.log("camera moves: every check held");
