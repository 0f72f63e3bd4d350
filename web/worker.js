// The solver's web worker (src/app/jobs/web_worker.rs, src/app/jobs/remote.rs): a second instance of the program that runs the solver
// stages off the page's thread. The page posts jobs and receives results as bytes. Messages that arrive
// while the module is still loading wait here, in order.
import init, { tiltpad_worker_receive } from "./pkg/tiltpad.js";

const waiting = [];
let ready = false;
self.onmessage = (e) => {
  if (ready) {
    tiltpad_worker_receive(new Uint8Array(e.data));
  } else {
    waiting.push(e.data);
  }
};
init().then(() => {
  ready = true;
  for (const data of waiting.splice(0)) {
    tiltpad_worker_receive(new Uint8Array(data));
  }
});
