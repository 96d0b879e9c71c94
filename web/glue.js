// The wasm-bindgen glue of the module instance in use. The page starts with the small
// first module for the default demo and moves to the full one (or, after a trap, to a
// fresh instance), so modules call the free functions through this, never through a
// static import of the glue (which would also load the full glue before the first plot).
let current = null;

/** The glue of the instance in use (set by main.js before any demo is shown). */
export function glue() {
  return current;
}

/** Called by main.js whenever it moves to another instance. */
export function useGlue(module) {
  current = module;
}

let moveToFull = async () => {};

/**
 * The glue of the full module, once the open demo runs on it. A first module holds only
 * what the first plot needs: exports (CSV, SVG, the stamp written into every file), the
 * stamp read from a dropped file, the prediction form's number parser and the host's
 * schema wait for the full module, which the page fetches right after the first plot.
 * Rejects if it cannot be loaded (a later call tries again).
 */
export async function fullGlue() {
  await moveToFull();
  return current;
}

/** Called once by main.js: how the page moves the open demo to the full module. */
export function useFullModuleWith(move) {
  moveToFull = move;
}
