// Interface strings of the page itself, one table per language. (Strings that come from
// the demos are translated in Rust: crates/app/src/i18n/.) `?lang=` wins, then the
// browser's languages; English otherwise.
const STRINGS = {
  en: {
    skip: 'Skip to the demo',
    demo: 'Demo',
    share: 'Share / Embed',
    loading: 'Loading the solver…',
    footer: 'Zeta Lab — every number on this page is computed in Rust (compiled to WebAssembly) from closed-form solutions.',
    parameters: 'Parameters',
    readouts: 'Readouts',
    about: 'About this demo',
    plotInView: 'Plot in view',
    presets: 'Presets',
    reset: 'Reset to defaults',
    exactValue: 'exact value',
    exportGroup: 'Export {plot}',
    download: 'Download {plot} as {format}',
    play: 'Play',
    pause: 'Pause',
    soundOn: 'Sound on',
    soundOff: 'Sound off',
    soundHint: 'Hear x(t): pitch follows displacement',
    animTime: 'Animation time',
    timeWords: 'time {t} seconds',
    schematic: 'Animated schematic',
    dismiss: 'Dismiss notice',
    failed: 'Something went wrong and the demo was restarted: {text}',
    noDemo: 'There is no demo called “{id}”; showing {fallback}.',
    noWasm: 'The solver could not be loaded ({text}). This page needs WebAssembly.',
    copy: 'Copy',
    equation: 'Equation',
    tourHead: 'The paper, figure by figure',
    tourOpen: 'Open this state in the demo',
    tourPaper: 'The paper says',
    tourApp: 'The app computes',
    tourConfirmed: 'Confirmed.',
    tourDiffers: 'Differs.',
    copied: 'Copied',
    copyManual: 'Select and copy (Ctrl+C)',
    shareTitle: 'Share or embed “{title}”',
    embedView: ' Embed view (no site header)',
    autoplay: ' Start the animation',
    theme: 'Theme ',
    width: ' Width ',
    height: ' Height ',
    slidersShown: 'Sliders shown',
    slidersLocked: 'Sliders locked',
    plotsShown: 'Plots shown',
    link: 'Link',
    embedCode: 'Embed code',
    preview: 'Preview of the embedded demo',
    close: 'Close',
  },
  es: {
    skip: 'Ir a la demostración',
    demo: 'Demostración',
    share: 'Compartir / Insertar',
    loading: 'Cargando el resolvedor…',
    footer: 'Zeta Lab — cada número de esta página se calcula en Rust (compilado a WebAssembly) con soluciones analíticas.',
    parameters: 'Parámetros',
    readouts: 'Resultados',
    about: 'Acerca de esta demostración',
    plotInView: 'Gráfica a la vista',
    presets: 'Ajustes predefinidos',
    reset: 'Restablecer valores',
    exactValue: 'valor exacto',
    exportGroup: 'Exportar {plot}',
    download: 'Descargar {plot} como {format}',
    play: 'Reproducir',
    pause: 'Pausa',
    soundOn: 'Sonido sí',
    soundOff: 'Sonido no',
    soundHint: 'Escuchar x(t): el tono sigue al desplazamiento',
    animTime: 'Tiempo de la animación',
    timeWords: 'tiempo {t} segundos',
    schematic: 'Esquema animado',
    dismiss: 'Cerrar aviso',
    failed: 'Algo salió mal y la demostración se reinició: {text}',
    noDemo: 'No hay ninguna demostración llamada «{id}»; se muestra {fallback}.',
    noWasm: 'No se pudo cargar el resolvedor ({text}). Esta página necesita WebAssembly.',
    copy: 'Copiar',
    equation: 'Ecuación',
    tourHead: 'El artículo, figura por figura',
    tourOpen: 'Abrir este estado en la demostración',
    tourPaper: 'El artículo dice',
    tourApp: 'La aplicación calcula',
    tourConfirmed: 'Confirmado.',
    tourDiffers: 'Difiere.',
    copied: 'Copiado',
    copyManual: 'Seleccione y copie (Ctrl+C)',
    shareTitle: 'Compartir o insertar «{title}»',
    embedView: ' Vista insertada (sin cabecera)',
    autoplay: ' Iniciar la animación',
    theme: 'Tema ',
    width: ' Ancho ',
    height: ' Alto ',
    slidersShown: 'Deslizadores visibles',
    slidersLocked: 'Deslizadores bloqueados',
    plotsShown: 'Gráficas visibles',
    link: 'Enlace',
    embedCode: 'Código para insertar',
    preview: 'Vista previa de la demostración insertada',
    close: 'Cerrar',
  },
};

function pick() {
  const wanted = [new URLSearchParams(window.location.search).get('lang'), ...(navigator.languages || [navigator.language])];
  for (const tag of wanted) {
    const primary = String(tag || '').split(/[-_]/)[0].toLowerCase();
    if (primary in STRINGS) return primary;
  }
  return 'en';
}

export const LANG = pick();

/** The string `key` in the page language, with `{name}` placeholders filled from `vars`. */
export function t(key, vars = {}) {
  const s = STRINGS[LANG][key] ?? STRINGS.en[key] ?? key;
  return s.replace(/\{(\w+)\}/g, (_, k) => String(vars[k] ?? ''));
}

/** A number in the page language (decimal comma in Spanish). */
export function num(value, digits) {
  return new Intl.NumberFormat(LANG, { minimumFractionDigits: digits, maximumFractionDigits: digits }).format(value);
}

/** Translates the static page: elements carrying data-i18n="key". */
export function translatePage() {
  document.documentElement.lang = LANG;
  for (const el of document.querySelectorAll('[data-i18n]')) el.textContent = t(el.dataset.i18n);
}
