// A plain static host page for Zeta Lab (see docs/embedding.md): it embeds one view,
// resizes the frame to the page inside (zeta:resize), checks a task from the readouts
// (zeta:change) and records the student's prediction (zeta:prediction).
const params = new URLSearchParams(window.location.search);
const appUrl = new URL(params.get('app') || '../dist/', window.location.href);
const appOrigin = appUrl.origin;
const view = new URLSearchParams(params.get('q') || 'demo=quarter-car&zeta=0.3&predict=overshoot&tol=5%25&controls=zeta');
view.set('embed', '1');
view.set('origin', window.location.origin); // the frame then talks to this origin only
appUrl.search = view.toString();

const frame = document.getElementById('zeta');
const log = document.getElementById('log');
const task = document.getElementById('task');
frame.src = appUrl.href;

/** Every message from the frame, for the curious (and the end-to-end tests). */
window.messages = [];
/** Sends a message to the frame (only to the app's origin). */
window.send = (msg) => frame.contentWindow.postMessage(msg, appOrigin);

window.addEventListener('message', (ev) => {
  if (ev.origin !== appOrigin || ev.source !== frame.contentWindow) return;
  const msg = ev.data;
  if (!msg || typeof msg.type !== 'string') return;
  window.messages.push(msg);
  const item = document.createElement('li');
  item.textContent = `${msg.type} ${JSON.stringify(msg).slice(0, 160)}`;
  log.append(item);
  if (msg.type === 'zeta:resize') {
    // The few lines a host needs to grow and shrink the frame with its content:
    frame.style.height = `${Math.min(Math.max(msg.height, 200), 4000)}px`;
  } else if (msg.type === 'zeta:change' || msg.type === 'zeta:ready') {
    const overshoot = Number(msg.readouts && msg.readouts.overshoot);
    if (Number.isFinite(overshoot)) {
      task.textContent = overshoot < 5
        ? `Done: ζ = ${msg.params.zeta} gives an overshoot of ${overshoot.toFixed(2)} %.`
        : `Not yet: the overshoot is ${overshoot.toFixed(2)} % (aim for under 5 %).`;
    }
  } else if (msg.type === 'zeta:prediction') {
    // An xAPI statement without an actor: an LMS adds the learner and sends it to its LRS.
    const statement = { actor: { name: 'the signed-in student' }, ...msg.statement };
    console.log('xAPI statement', statement);
  }
});
