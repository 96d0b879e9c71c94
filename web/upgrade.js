// The switch from a demo's first module to the full one (issue 13), loaded after the first
// plot: what it needs is not part of the bytes the page downloads before it. main.js
// starts it once the first module has drawn, with its state `app` and the helpers it
// shares (`page`, see main.js's `upgrade` call); the menu's and a click's immediate
// switches stay in main.js (`adopt`, `useFullModule`).

import { activeLanguage, adoptInstance, prepareInstance } from './i18n.js';
import { currentQuery } from './url.js';
import { useGlue } from './glue.js';

let app;
let page;

/**
 * Resolves when the controls have rested (`page.rest` ms), no frame is pending, no study
 * is being refined and the animation is not playing.
 */
function betweenBursts() {
  return new Promise((resolve) => {
    const check = () => {
      const busy = app.framePending || app.recovering || app.needsRecovery || app.refineTimer || app.playing;
      const wait = page.restLeft(page.rest);
      if (busy || wait > 0) setTimeout(check, Math.max(50, wait));
      else resolve();
    };
    check();
  });
}

/**
 * After the first plot from the first module: loads the full module behind the page and
 * switches to it while the controls rest, with the same values, so nothing the user sees
 * changes (but a study the first module left provisional, now whole), and in steps that
 * each fit in a frame at a slow device's speed: the full
 * module's session computes behind the page (computeBehind), takes over (takeOver), and
 * redraws the plots one a frame. Input in between starts again at the next rest.
 */
export async function upgrade(state, helpers) {
  [app, page] = [state, helpers];
  let mod;
  for (let tries = 0; !mod; tries++) {
    try {
      mod = await page.loadFull();
    } catch (err) {
      console.warn('Zeta Lab: the full module could not be loaded yet:', err && err.message);
      // Asked for again 2, 4 and 8 s later (a dropped connection); a menu choice or a click
      // on a plot tries again too.
      if (tries === 3) return;
      await new Promise((done) => setTimeout(done, 2000 << tries));
    }
  }
  while (app.module === 'first') {
    await betweenBursts();
    if (app.module !== 'first') return;
    const behind = await computeBehind(mod);
    if (behind?.failed) {
      try {
        page.adopt(mod); // at once, as a menu choice does
      } catch (err) {
        page.reportFailure(err);
      }
      return;
    }
    if (behind) takeOver(mod, behind);
  }
}

/**
 * The full module's session for the open demo with the page's values, computed behind the
 * page, each step a task of its own: its figures (no plot drawn: the first module's are on
 * screen), then any study in slices. `null` if input came, the demo or language changed,
 * (then again at the next rest); `{failed: true}` if a step failed; `{session, language}`
 * otherwise.
 */
async function computeBehind({ glue }) {
  const { lastInput, revision, demoId, session: shown } = app;
  const language = activeLanguage().tag;
  const moved = () =>
    app.lastInput !== lastInput || app.revision !== revision || app.dragging || app.playing ||
    app.refineTimer || app.session !== shown || app.demoId !== demoId || app.module !== 'first' ||
    app.needsRecovery || activeLanguage().tag !== language;
  const nextTask = () => new Promise((resolve) => setTimeout(resolve, 0));
  let session = null;
  try {
    prepareInstance(glue);
    await nextTask();
    if (moved()) return null;
    glue.message('page-loading', {}); // builds its English catalogue (parsed on first use)
    await nextTask();
    if (moved()) return null;
    session = new glue.Session(demoId);
    session.applyQuery(currentQuery());
    for (const [k, v] of shown.values()) session.set(k, String(v));
    for (const key of app.view.shownPlots) {
      session.attach(key, app.view.canvases.get(key));
      session.setVisible(key, false);
    }
    if (app.view.animation) session.attach('schematic', app.view.animation.canvas);
    await nextTask();
    if (moved()) throw null;
    let out = session.update(window.devicePixelRatio || 1, page.isDark());
    for (;;) {
      await nextTask();
      if (moved()) throw null;
      const done = session.refine(page.slice);
      if (done === undefined) break;
      page.showStudyProgress(done); // the study the first module left provisional (integrators')
      if (done >= 1) {
        await nextTask();
        if (moved()) throw null;
        out = session.update(window.devicePixelRatio || 1, page.isDark());
        break;
      }
    }
    return { session, language, out };
  } catch (err) {
    try {
      session?.free();
    } catch {
      // dropped either way
    }
    if (err === null) return null; // moved on: again at the next rest
    console.warn('Zeta Lab: the full module could not compute behind the page:', err && err.message);
    return { failed: true };
  }
}

/**
 * The full module's session (computeBehind) takes over from the first module's: the
 * plots on screen show what it would draw, so it redraws them one a frame (a first
 * drawing fills its kept layers and text fits) while the controls rest.
 */
function takeOver({ glue, exports }, { session, language, out }) {
  const old = app.session;
  try {
    app.missing.push(...app.wasm.takeMissingMessages()); // reported by the diagnostics
  } catch {
    // a failed first instance cannot answer
  }
  adoptInstance(glue, language);
  app.wasm = glue;
  useGlue(glue);
  app.exports = exports;
  app.module = 'full';
  app.session = session;
  // The same numbers, but a study the first module left provisional (the integrators')
  // is whole now: its readouts and marks (the plots follow in the catch-up).
  page.showResults(out);
  for (const key of app.view.shownPlots) session.setVisible(key, app.onScreen.has(key));
  app.staleLeft = true;
  app.schematicStale = Boolean(app.view.animation);
  app.settling = true; // observeVisibility leaves the drawing to the catch-up meanwhile
  page.observeVisibility();
  page.scheduleCatchUp(0);
  try {
    old.free();
  } catch {
    // the first instance is dropped either way
  }
}
