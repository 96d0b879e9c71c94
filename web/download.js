// Files of a plot, for the page's export buttons and the host page's `zeta:export`
// (embed.js): CSV, SVG or PNG, each with the view's state token and the app version written
// in (see view.js and export.rs), so that dropping the file back onto the page reopens the
// same view.
import { fullGlue } from './glue.js';
import { currentToken } from './view.js';

function bytesOf(text) {
  return new TextEncoder().encode(text);
}

/**
 * Plot `key` as a stamped file: {mime, bytes}. `h`: {app, isDark} from main.js. A first
 * module has no exports and no stamps: the full one takes over first (fullGlue).
 */
export async function plotFile(h, key, format) {
  const app = h.app;
  if (!app.view.canvases.has(key)) throw new Error(`no plot “${String(key).slice(0, 40)}”`);
  if (!['csv', 'svg', 'png'].includes(format)) throw new Error(`unknown format “${String(format).slice(0, 8)}” (png, svg or csv)`);
  const full = await fullGlue();
  const token = currentToken(h);
  const canvas = app.view.canvases.get(key);
  const w = canvas.clientWidth || 800;
  const hgt = canvas.clientHeight || 500;
  const stamped = (mime, bytes) => ({ mime, bytes: full.stampExport(format, bytes, token) });
  if (format === 'csv') return stamped('text/csv', bytesOf(app.session.csv(key)));
  if (format === 'svg') return stamped('image/svg+xml', bytesOf(app.session.svg(key, w, hgt, h.isDark(), document.createElement('canvas'))));
  const big = document.createElement('canvas');
  big.width = w * 2;
  big.height = hgt * 2;
  app.session.renderTo(key, big, 2, h.isDark());
  const blob = await new Promise((ok) => big.toBlob(ok, 'image/png'));
  if (!blob) throw new Error('the browser could not encode the PNG');
  return stamped('image/png', new Uint8Array(await blob.arrayBuffer()));
}

/** Saves plot `key` as `zeta-<demo>-<key>.<format>` through a temporary object URL. */
export async function downloadPlot(h, key, format) {
  const name = `zeta-${h.app.demoId}-${key}.${format}`;
  const file = await plotFile(h, key, format);
  const url = URL.createObjectURL(new Blob([file.bytes], { type: file.mime }));
  const a = document.createElement('a');
  a.href = url;
  a.download = name;
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 10000);
}
