// Optional sonification: while the animation plays, a tone whose pitch follows the
// displacement (−1 … 1 → 220 … 880 Hz). Off by default; the values come from Rust.
export function createSonifier() {
  let ctx = null;
  let osc = null;
  let gain = null;
  return {
    enabled: false,
    start() {
      if (!ctx) {
        const Ctx = window.AudioContext || window.webkitAudioContext;
        if (!Ctx) return false;
        ctx = new Ctx();
        gain = ctx.createGain();
        gain.gain.value = 0;
        gain.connect(ctx.destination);
        osc = ctx.createOscillator();
        osc.type = 'sine';
        osc.connect(gain);
        osc.start();
      }
      ctx.resume();
      this.enabled = true;
      return true;
    },
    stop() {
      this.enabled = false;
      if (gain) gain.gain.setTargetAtTime(0, ctx.currentTime, 0.02);
    },
    /** Sets the tone for a normalised displacement, or silences it (null). */
    play(x) {
      if (!this.enabled || !ctx) return;
      if (x === null || x === undefined || !Number.isFinite(x)) {
        gain.gain.setTargetAtTime(0, ctx.currentTime, 0.02);
        return;
      }
      const clamped = Math.max(-1, Math.min(1, x));
      osc.frequency.setTargetAtTime(440 * Math.pow(2, clamped), ctx.currentTime, 0.01);
      gain.gain.setTargetAtTime(0.08, ctx.currentTime, 0.02);
    },
  };
}
