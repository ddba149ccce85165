// The page's live view (viewer/live.js) against a stand-in server, without a browser:
// `node tests/browser/live_view_test.js SOURCE_DIR` exits 0 when every check holds, 1 otherwise.
"use strict";

const fs = require("fs");
const path = require("path");

const load = (name) => fs.readFileSync(path.join(process.argv[2], "viewer", name), "utf8");
globalThis.ImageData = class {
  constructor(data, width, height) { Object.assign(this, { data, width, height }); }
};
const ClrenderLiveView = new Function(`${load("camera.js")}\n${load("live.js")}\nreturn ClrenderLiveView;`)();

const frame = () => new Response(new Uint8Array(2 * 2 * 4),
                                 { status: 200, headers: { "X-Width": "2", "X-Height": "2" } });
const busy = () => new Response('{"error": "frames of 400 MiB are still being sent to other clients"}',
                                { status: 503, headers: { "Retry-After": "1" } });
const refused = () => new Response('{"error": "fov must be between 0 and 180", "parameter": "fov"}', { status: 400 });
// The server's 403: no body, as it answers a wrong token (a viewer started again since the page
// was opened) or a foreign Host.
const forbidden = () => new Response(null, { status: 403, statusText: "Forbidden" });

// Starts a live view whose server gives `answers` in turn; after `ms`, the requests it made and
// whether a frame is on the canvas.
function run(answers, ms) {
  const asked = [];
  globalThis.fetch = async (url) => {
    asked.push(performance.now());
    return (answers[asked.length - 1] || frame)();
  };
  const canvas = { width: 1, height: 1, style: {}, getContext: () => ({ putImageData() {} }) };
  const errors = [];
  const live = new ClrenderLiveView(canvas, { token: "t", size: [2, 2], stillSpp: 1, onError: (e) => errors.push(e) });
  live.setCamera({ eye: [0, 0, 5], lookat: [0, 0, 0], up: [0, 1, 0], fov: 60 });
  return new Promise((resolve) => setTimeout(() => resolve({ asked, shown: live.shown !== null, errors }), ms));
}

(async () => {
  let failures = 0;
  const check = (ok, what) => { if (!ok) { failures += 1; console.log(`FAILED: ${what}`); } };

  // A 503 with Retry-After is the server busy, not a refusal: the view is asked again after the
  // wait, and shown (it was taken as a refusal, and never asked again until the camera moved).
  const retried = await run([busy], 1600);
  check(retried.asked.length === 2, `a busy server's view asked ${retried.asked.length} times, not 2`);
  check(retried.shown, "the view is shown once the server has room");
  check(retried.asked.length < 2 || retried.asked[1] - retried.asked[0] >= 990, "asked again only after Retry-After");

  // A refused camera stays refused until it changes: no second request.
  const refusal = await run([refused], 1600);
  check(refusal.asked.length === 1 && !refusal.shown, `a refused view asked ${refusal.asked.length} times, not once`);
  check(refusal.errors.length === 1 && refusal.errors[0].includes("400 (fov)"), `the refusal shown: ${refusal.errors}`);

  // A 403 is the page's token or address, not the camera: the message says what to do, and is
  // not "the server refused this view: 403: Forbidden".
  const stale = await run([forbidden], 300);
  check(stale.asked.length === 1 && !stale.shown, `a forbidden view asked ${stale.asked.length} times, not once`);
  check(stale.errors.length === 1 && stale.errors[0].startsWith("403: ") &&
        stale.errors[0].includes("open the address it printed") && !stale.errors[0].includes("refused this view"),
        `the 403 shown: ${stale.errors}`);

  if (failures) process.exit(1);
  console.log("live view: every check held");
})();
