//! The `resonance` demo's declaration: parameters, readouts, plots and presets as tables,
//! one row each.

use super::{frequency, text, time, Results, View, P, R_RANGE};
use crate::declare::{Declaration, DAMPING_RATIO, NATURAL_FREQUENCY};
use crate::demos::rows::{self, readouts, sliders};
use crate::spec::Preset;
use zeta_solver::frf;

/// Parameters, readouts, plots and presets of `resonance`.
pub(super) fn declaration() -> Declaration<P, Results> {
    Declaration {
        equation_mathml: text::EQUATION,
        params: sliders! { P;
            quantity DAMPING_RATIO, (0.01, 2.0, 0.001), 0.1 => zeta, log_scale();
            log "r", "forcing ratio ω/ωₙ", "r", "", (R_RANGE.0, R_RANGE.1, 0.001), 1.0 => r;
            quantity NATURAL_FREQUENCY, (0.5, 20.0, 0.01), 6.0 => wn;
            linear "F0", "force amplitude", "F₀", "N", (0.1, 100.0, 0.1), 10.0 => f0;
            choice "view", "magnitude view", View::Linear => view;
        },
        readouts: readouts! { Results, |r|;
            number "peak_gain", "resonant peak |H|max", "", 4 => r.peak.map(|p| p.gain);
            number "peak_ratio", "peak at r = ω/ωₙ", "", 4 => r.peak.map(|p| p.ratio);
            number "Q", "quality factor Q = 1/(2ζ)", "", 4 => frf::quality_factor(r.p.zeta);
            number "peak_width", "half-power width of the |H| peak r₂ − r₁ (ζ < 0.383)", "", 4
                => frf::half_power_width(r.p.zeta);
            number "gain_at_r", "gain |H(r)| at the drive", "", 4
                => Some(frf::magnitude(r.p.r, r.p.zeta));
            number "phase_at_r", "phase ∠H(r) at the drive", "rad", 4
                => Some(frf::phase(r.p.r, r.p.zeta));
            number "amplitude", "steady amplitude X = |H|·F₀/k", "m", 4
                => r.resp.steady_state().map(|s| s.amplitude);
            number "beat_period", "beat period 2π/|ω − ω_d| (while beats show)", "s", 4
                => r.resp.beats().period();
            text "beats", "beats in x(t)" => text::beats(r.resp.beats());
        },
        // Key, title and width / height.
        plots: rows::plots(&[
            ("magnitude", frequency::MAGNITUDE_TITLE, 1.4),
            ("phase", frequency::PHASE_TITLE, 1.4),
            ("time", time::TIME_TITLE, 1.9),
        ]),
        // ζ and r only: ωₙ, F₀ and the view stay.
        presets: [
            ("At resonance, ζ = 0.05", 0.05, 1.0),
            ("Beating near resonance, r = 0.9", 0.01, 0.9),
            ("No peak, ζ ≈ 1/√2", 0.7072, 1.0),
            ("Quasi-static, r = 0.2", 0.1, 0.2),
            ("Isolation, r = 3", 0.1, 3.0),
        ]
        .into_iter()
        .map(|(label, zeta, r)| Preset {
            label,
            values: vec![("zeta", zeta), ("r", r)],
        })
        .collect(),
        schematic: true,
        ..Declaration::new("resonance", "Forced resonance", text::SUMMARY)
    }
}
