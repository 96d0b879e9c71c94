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
