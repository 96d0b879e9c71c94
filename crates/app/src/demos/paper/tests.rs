//! The tour: every claim the issue names is checked, each verdict follows from the linked
//! demo's own readout, and every link opens a registered demo with no notice.

use super::tour::{Place, CLAIMS, EXHIBITS};
use super::*;
use crate::demos::create;
use crate::demos::testing::{self, Tested};
use crate::params::{parse_query, resolve_query};

fn tour() -> Tour {
    Paper::live("")
        .demo
        .tour()
        .expect("the paper demo gives a tour")
}

fn claim<'a>(t: &'a Tour, id: &str) -> &'a ClaimView {
    t.claims
        .iter()
        .find(|c| c.id == id)
        .unwrap_or_else(|| panic!("no claim {id}"))
}

#[test]
fn every_required_claim_is_there_with_the_expected_verdict() {
    let t = tour();
    use Verdict::*;
    for (id, verdict) in [
        ("fig1-zeta-optimum", Confirmed),
        ("sec3-natural-frequency", Confirmed),
        ("sec4-critical-resistance", Confirmed),
        ("fig3-q-factor", Confirmed),
        ("sec5-peak-frequency", Confirmed),
        ("fig4-euler-error", Differs),
        ("fig4-rk4-error", Differs),
        ("fig4-euler-slope", Differs),
        ("sec7-mass-tolerance", Differs),
    ] {
        let c = claim(&t, id);
        assert_eq!(c.verdict, verdict, "{id}: {} / {}", c.computed, c.reason);
        assert!(!c.reason.is_empty());
    }
    assert_eq!(t.claims.len(), CLAIMS.len());
}

/// Asserts that `text` quotes the text of readout `key` of `frame`.
fn assert_shows(text: &str, frame: &crate::demos::Frame, key: &str) {
    assert!(text.contains(&testing::text(frame, key)), "{key}: {text}");
}

#[test]
fn values_are_the_linked_demos_own_readouts() {
    let t = tour();
    // ζ range under ±10 % mass: exact 1/√1.1 and 1/√0.9 (ζ ∝ 1/√m).
    let mass = claim(&t, "sec7-mass-tolerance");
    let f = testing::run("uncertainty", "system=0&m=300&k=24000&zeta=1&dm=10");
    assert_shows(&mass.computed, &f, "zeta_min");
    assert_shows(&mass.computed, &f, "zeta_max");
    let lo = testing::number(&f, "zeta_min");
    assert!((lo - 0.953_462_589_245_592).abs() < 1e-9, "{lo}");
    // Euler's verdict names its growth factor per step.
    let euler = claim(&t, "fig4-euler-error");
    let g = testing::run("integrators", "zeta=0.05&wn=2&h=0.3");
    assert_shows(&euler.reason, &g, "growth_euler");
    assert_eq!(euler.computed, testing::text(&g, "max_err_euler"));
}

#[test]
fn every_link_opens_a_registered_demo_without_notices() {
    let t = tour();
    let links = t
        .exhibits
        .iter()
        .map(|e| &e.link)
        .chain(t.claims.iter().map(|c| &c.link));
    for link in links {
        let pairs = parse_query(link);
        let id = &pairs.iter().find(|(k, _)| k == "demo").expect("demo=").1;
        let Some(demo) = create(id) else {
            // Figure 5's demo joins the registry with the universality demo.
            assert_eq!(id, "universality", "{link}");
            continue;
        };
        let (_, notices) = resolve_query(&demo.spec(), link);
        assert!(notices.is_empty(), "{link}: {notices:?}");
    }
    assert_eq!(t.exhibits.len(), EXHIBITS.len());
}

/// The tour in language `tag` (its catalogue loaded from `ftl`), English restored
/// afterwards; with the ids that catalogue lacked while the tour was built.
#[test]
fn every_claim_is_written_out() {
    // A claim's parts left out of its `claim(…)` chain stay empty.
    for c in CLAIMS {
        assert!(!(c.says)().is_empty(), "{}: says nothing", c.id);
        let numbers = match c.place {
            Place::Figure(n) | Place::Section(n) => [n, n],
            Place::SectionFigure(s, f) => [s, f],
        };
        assert!(!numbers.contains(&""), "{}: no place", c.id);
        assert!(create(c.at.demo).is_some(), "{}: no demo", c.id);
    }
}

fn tour_in(tag: &str, ftl: &str) -> (Tour, Vec<String>) {
    // A syntax error elsewhere in the file shows here as missing ids of ours, if any.
    let _ = crate::i18n::load(tag, ftl);
    crate::i18n::set_language(&[tag]);
    crate::i18n::take_missing();
    let t = tour();
    let missing = crate::i18n::take_missing();
    crate::i18n::set_language(&["en"]);
    (t, missing)
}

/// Asserts that none of the paper's own messages (`paper-…`) is among the `missing` ids
/// of the catalogue `tag`.
fn assert_has_paper_messages(tag: &str, missing: &[String]) {
    let ours: Vec<_> = missing
        .iter()
        .filter(|id| id.starts_with("paper-"))
        .collect();
    assert!(ours.is_empty(), "{tag}.ftl lacks {ours:?}");
}

fn spanish_tour() -> (Tour, Vec<String>) {
    tour_in("es", include_str!("../../../locales/es.ftl"))
}

#[test]
fn every_language_builds_the_whole_tour_from_its_own_catalogue() {
    let en = tour();
    for (tag, ftl) in [
        ("fr", include_str!("../../../locales/fr.ftl")),
        ("pt-BR", include_str!("../../../locales/pt-BR.ftl")),
        ("zh-CN", include_str!("../../../locales/zh-CN.ftl")),
    ] {
        let (t, missing) = tour_in(tag, ftl);
        assert_has_paper_messages(tag, &missing);
        for (e, s) in en.exhibits.iter().zip(&t.exhibits) {
            assert_ne!(e.shows, s.shows, "{tag}: {}", e.id);
        }
        for (e, s) in en.claims.iter().zip(&t.claims) {
            assert_eq!((e.id, &e.link, e.verdict), (s.id, &s.link, s.verdict));
            assert_ne!(e.says, s.says, "{tag}: {}", e.id);
            assert_ne!(e.reason, s.reason, "{tag}: {}", e.id);
        }
    }
}

#[test]
fn the_tour_is_built_in_spanish_with_no_english_left() {
    let (es, missing) = spanish_tour();
    let en = tour();
    assert_has_paper_messages("es", &missing);
    // Every sentence of the tour is the catalogue's, not the English one.
    for (e, s) in en.exhibits.iter().zip(&es.exhibits) {
        assert_eq!((e.id, &e.link), (s.id, &s.link));
        assert_ne!(e.place, s.place, "{}", e.id);
        assert_ne!(e.shows, s.shows, "{}", e.id);
    }
    for (e, s) in en.claims.iter().zip(&es.claims) {
        assert_eq!((e.id, &e.link, e.verdict), (s.id, &s.link, s.verdict));
        assert_ne!(e.place, s.place, "{}", e.id);
        assert_ne!(e.says, s.says, "{}", e.id);
        assert_ne!(e.reason, s.reason, "{}", e.id);
    }
    let english = [
        "The demo",
        "paper's",
        " the ",
        "Figure",
        "Table",
        "Section",
        "Euler is",
        "RK4 is",
        "Over the",
        "In hertz",
        "varies as",
        "instead",
        "within the",
        "found by",
        " to ",
    ];
    let texts = es.exhibits.iter().flat_map(|e| [&e.place, &e.shows]).chain(
        es.claims
            .iter()
            .flat_map(|c| [&c.place, &c.says, &c.claimed, &c.computed, &c.reason]),
    );
    for text in texts {
        for word in english {
            assert!(!text.contains(word), "untranslated {word:?} in {text:?}");
        }
    }
    // A few known places, word for word.
    assert_eq!(es.exhibits[0].place, "Figura 1(a)");
    let euler = claim(&es, "fig4-euler-error");
    assert_eq!(euler.place, "Sección 6.5, figura 4(a)");
    let g = testing::run("integrators", "zeta=0.05&wn=2&h=0.3");
    let growth = testing::text(&g, "growth_euler");
    assert!(
        euler.reason.starts_with("La demostración calcula")
            && euler.reason.contains(&format!(
                "Euler es inestable con este paso: |1 + hλ| = {growth} por paso"
            )),
        "{}",
        euler.reason
    );
    let mass = claim(&es, "sec7-mass-tolerance");
    assert!(mass.claimed.contains(" a "), "{}", mass.claimed);
    // English again once the language is restored.
    assert_eq!(tour(), en);
}

#[test]
fn a_first_module_checks_what_it_links_and_leaves_the_rest_pending() {
    // The paper's first module links the demo of its first figure (the registry's mark);
    // what needs another demo waits for the full module, shown as pending, never guessed.
    let first = EXHIBITS[0].at.demo;
    let with = crate::demos::FIRST_WITH
        .iter()
        .find(|(id, _)| *id == "paper");
    assert_eq!(
        with.map(|(_, w)| *w),
        Some(first),
        "the first module links {first}"
    );
    let full = Paper::default().check(verdict::Runs::default());
    let mut paper = Paper::default();
    let partial = paper.check(verdict::Runs::only(&[first]));
    assert_eq!(partial.tour.exhibits, full.tour.exhibits);
    assert_eq!(partial.tour.claims.len(), CLAIMS.len());
    let (mut checked, mut pending) = (0, 0);
    for ((def, c), f) in CLAIMS
        .iter()
        .zip(&partial.tour.claims)
        .zip(&full.tour.claims)
    {
        if def.at.demo == first {
            assert_eq!(c, f, "{}: checked as in the full module", c.id);
            checked += 1;
        } else {
            assert_eq!(c.verdict, Verdict::Pending, "{}", c.id);
            assert_eq!((&c.id, &c.claimed, &c.link), (&f.id, &f.claimed, &f.link));
            assert_eq!(c.computed, "…");
            pending += 1;
        }
    }
    assert!(
        checked > 0 && pending > 0,
        "{checked} checked, {pending} pending"
    );
    let marked = paper.provisional();
    for key in ["claims", "confirmed", "differs"] {
        assert!(marked.contains(&key), "{key}: counts to come");
    }
    assert_eq!(partial.count(Verdict::Pending), pending);
    for ((e, thumb), full_thumb) in EXHIBITS
        .iter()
        .zip(&partial.thumbnails)
        .zip(&full.thumbnails)
    {
        if e.at.demo == first {
            // Debug text: figures may hold NaN gaps, which `==` never equates.
            assert_eq!(format!("{thumb:?}"), format!("{full_thumb:?}"), "{}", e.id);
            assert!(!marked.contains(&e.id), "{}", e.id);
        } else {
            assert!(marked.contains(&e.id), "{} marked", e.id);
            assert!(
                thumb.description.contains("loaded"),
                "{}",
                thumb.description
            );
        }
    }
    assert_eq!(paper.study_round(), 1, "the marks start with the page");
    // The full module's tour has nothing pending.
    let mut whole = Paper::default();
    let all = whole.check(verdict::Runs::default());
    assert!(all
        .tour
        .claims
        .iter()
        .all(|c| c.verdict != Verdict::Pending));
    assert!(whole.provisional().is_empty() && whole.study_round() == 0);
}
