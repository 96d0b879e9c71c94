//! The tolerance demo's prose: summary, equation, labels and the figures' text
//! alternatives.

use super::ranges::{BandName, Member, Ranges};
use super::{HistOf, System, P};
use crate::format::{si, significant, significant_plain};
use crate::i18n::number;
use crate::t;
use zeta_solver::design::monte_carlo::Distribution;

pub(super) const SUMMARY: &str =
    "Real parts are not their nominal values. Choose the system: the quarter \
                      car (sprung mass m, spring k and the damper set for ζ at nominal mass; \
                      the mass varies by ±dm as the car is loaded) or the series RLC loop \
                      (R, L and C each within ±dR, ±dL, ±dC). Only the chosen system's sliders \
                      are used; the other group is ignored. The exact ranges of ζ, ωₙ and Q come \
                      from the corners of the tolerance box. The Monte Carlo run draws N designs \
                      (seeded, so the same seed gives the same result): uniform within the \
                      tolerance, or normal with the tolerance as 3σ. The yield is the share of \
                      draws with ζ inside the spec window and a 5 % settling time (release \
                      from rest) no longer than the limit.";

pub(super) const EQUATION: &str = "<math display=\"block\"><mrow>\
<mi>ζ</mi><mo>=</mo><mfrac><mi>c</mi><mrow><mn>2</mn><msqrt><mi>k</mi><mi>m</mi></msqrt></mrow></mfrac>\
<mo>∝</mo><msup><mi>m</mi><mrow><mo>−</mo><mn>1/2</mn></mrow></msup><mo>,</mo><mspace width=\"1em\"/>\
<mi>ζ</mi><mo>=</mo><mfrac><mi>R</mi><mn>2</mn></mfrac><msqrt><mfrac><mi>C</mi><mi>L</mi></mfrac></msqrt>\
</mrow></math>";

/// `v` to `sig` significant digits without trailing zeros ("10", "0.6"), in the
/// interface language's digits.
pub(super) fn short(v: f64, sig: usize) -> String {
    let plain = significant_plain(v, sig);
    if plain.contains('e') {
        return significant(v, sig);
    }
    let trimmed = if plain.contains('.') {
        plain.trim_end_matches('0').trim_end_matches('.')
    } else {
        plain.as_str()
    };
    let decimals = trimmed.split_once('.').map_or(0, |(_, f)| f.len());
    number::fixed(trimmed.parse().unwrap_or(v), decimals)
}

/// A count of draws in the language's digits.
fn count_text(n: usize) -> String {
    // Digit grouping follows the language (Intl: `10 000` in French, `10.000` in
    // Portuguese); English keeps the plain form, as everywhere in the app.
    crate::i18n::number::fixed(n as f64, 0)
}

/// A band member's legend label: its name and, where defined, its ζ.
pub(super) fn band_label(member: &Member) -> String {
    let name = match member.name {
        BandName::MassUp(pct) => format!("m + {} %", short(pct, 3)),
        BandName::NominalMass => t!("uncertainty-band-nominal-mass"),
        BandName::MassDown(pct) => format!("m − {} %", short(pct, 3)),
        BandName::LowestCorner => t!("uncertainty-band-lowest-corner"),
        BandName::Nominal => t!("uncertainty-band-nominal"),
        BandName::HighestCorner => t!("uncertainty-band-highest-corner"),
    };
    match member.zeta {
        Some(z) => format!("{name} (ζ = {})", significant(z, 3)),
        None => name,
    }
}

/// The band of free responses in words.
pub(super) fn describe_band(p: &P, r: &Ranges) -> String {
    let fmt_t = |t: Option<f64>| t.map_or_else(|| t!("uncertainty-never"), |t| si(t, "s", 3));
    let (what, ignored) = match p.system {
        System::Suspension => (
            t!(
                "uncertainty-band-suspension",
                start = si(r.x0, "m", 2),
                percent = short(p.dm, 3)
            ),
            t!("uncertainty-ignored-rlc"),
        ),
        System::Rlc => (
            t!("uncertainty-band-rlc"),
            t!("uncertainty-ignored-suspension"),
        ),
    };
    let zeta_text = r.zeta.map_or_else(
        || t!("uncertainty-zeta-undefined"),
        |(lo, hi)| {
            t!(
                "uncertainty-zeta-spans",
                low = significant(lo, 3),
                high = significant(hi, 3)
            )
        },
    );
    let [a, b, c] = &r.band;
    t!(
        "uncertainty-describe-band",
        what = what,
        zeta = zeta_text,
        first = fmt_t(a.settling_time),
        second = fmt_t(b.settling_time),
        third = fmt_t(c.settling_time),
        ignored = ignored
    )
}

/// A histogram in words: its range, percentiles and the spec where it is marked.
pub(super) fn describe_histogram(
    p: &P,
    h: HistOf,
    draws: usize,
    range: Option<(f64, f64)>,
    [p5, p95]: [f64; 2],
    yield_pct: f64,
) -> String {
    let (name, unit) = h.label();
    let dist = match p.dist.0 {
        Distribution::Normal => t!("uncertainty-dist-normal"),
        Distribution::Uniform => t!("uncertainty-dist-uniform"),
    };
    let (zlo, zhi) = p.zeta_window();
    let spec_text = match h {
        HistOf::Zeta => Some(t!(
            "uncertainty-spec-zeta",
            low = short(zlo, 3),
            high = short(zhi, 3),
            share = si(yield_pct, "%", 3)
        )),
        HistOf::SettlingTime => Some(t!(
            "uncertainty-spec-settling-time",
            limit = si(p.ts_max, "s", 3)
        )),
        _ => None,
    };
    let Some((lo, hi)) = range else {
        return t!("uncertainty-no-finite", quantity = name);
    };
    let (lo, hi, p5, p95) = (
        si(lo, unit, 4),
        si(hi, unit, 4),
        si(p5, unit, 4),
        si(p95, unit, 4),
    );
    t!(
        "uncertainty-describe-histogram",
        quantity = name,
        draws = count_text(draws),
        distribution = dist,
        low = lo,
        high = hi,
        p5 = p5,
        p95 = p95,
        marked = if spec_text.is_some() { "yes" } else { "no" },
        spec = spec_text.unwrap_or_default()
    )
}

/// Marks a histogram drawn from the first `shown` draws while the full run of `full` draws
/// continues as provisional, in its title and its description.
pub(super) fn mark_provisional(fig: &mut crate::figure::Figure, shown: usize, full: usize) {
    fig.title = t!("uncertainty-provisional-title", title = &fig.title);
    fig.description = t!(
        "uncertainty-provisional-description",
        shown = shown,
        full = full,
        description = &fig.description
    );
}
