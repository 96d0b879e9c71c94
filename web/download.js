// Saves a Blob as a file through a temporary object URL. PNG, SVG and CSV files get the
// view's state token and the app version written in (see view.js, embed.js and export.rs), so that
// dropping the file back onto the page reopens the same view.
import { fullGlue } from './glue.js';
import { tokenNow } from './view.js';

function save(blob, name) {
  const url = URL.createObjectURL(blob);
  const a = document.createElement('a');
  a.href = url;
  a.download = name;
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 10000);
}

export function download(blob, name) {
  const format = /\.(png|svg|csv)$/.exec(name);
  const token = format && tokenNow();
  if (!token) {
    save(blob, name);
    return;
  }
  // The stamp is written by the full module (see fullGlue).
  Promise.all([fullGlue(), blob.arrayBuffer()]).then(
    ([glue, buf]) => save(new Blob([glue.stampExport(format[1], new Uint8Array(buf), token)], { type: blob.type }), name),
    () => save(blob, name),
  );
}
