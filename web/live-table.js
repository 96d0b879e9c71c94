// Live cells of a demo's reference table. A cell whose whole text is `{readout:<key>}`
// (declared in Rust with `live_cell!`, see `Table::live_cells` in crates/app/src/spec.rs)
// shows the current text of readout `<key>`; every other cell stays as declared. The text
// comes from Rust, already formatted and translated: no numbers are computed here.

import { setText } from './ui.js';

const LIVE = /^\{readout:([A-Za-z0-9_-]+)\}$/;

/**
 * Fills the live cells of `table` (the view `buildTable` returns: `{ rows: Map<key, tr> }`,
 * or null) with the texts of `readouts` (`[{ key, text }]`, as `Session.update` returns
 * them). Call after every update; the first call marks each live cell with
 * `data-live-readout="<key>"` so the declared marker never shows. A readout that is
 * missing shows as "—".
 */
export function fillLiveCells(table, readouts) {
  if (!table) return;
  const texts = new Map(readouts.map((r) => [r.key, r.text]));
  for (const tr of table.rows.values()) {
    for (const cell of tr.cells) {
      let key = cell.dataset.liveReadout;
      if (key === undefined) {
        const m = LIVE.exec(cell.textContent);
        if (!m) continue;
        key = m[1];
        cell.dataset.liveReadout = key;
      }
      setText(cell, texts.get(key) ?? '—');
    }
  }
}
