//! The tour: every claim the issue names is checked, each verdict follows from the linked
//! demo's own readout, and every link opens a registered demo with no notice.

use super::tour::{CLAIMS, EXHIBITS};
use super::*;
use crate::demos::{create, testing, Demo, Typed};
use crate::params::{parse_query, resolve_query};

fn tour() -> Tour {
    let mut demo = Typed::new(Paper);
    let spec = demo.spec();
    demo.update(&crate::params::Params::defaults(&spec));
    demo.tour().expect("the paper demo gives a tour")
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

#[test]
fn values_are_the_linked_demos_own_readouts() {
    let t = tour();
    // ζ range under ±10 % mass: exact 1/√1.1 and 1/√0.9 (ζ ∝ 1/√m).
    let mass = claim(&t, "sec7-mass-tolerance");
    let f = testing::run("uncertainty", "system=0&m=300&k=24000&zeta=1&dm=10");
    assert!(
        mass.computed.contains(&testing::text(&f, "zeta_min")),
        "{}",
        mass.computed
    );
    assert!(
        mass.computed.contains(&testing::text(&f, "zeta_max")),
        "{}",
        mass.computed
    );
    let lo = testing::number(&f, "zeta_min");
    assert!((lo - 0.953_462_589_245_592).abs() < 1e-9, "{lo}");
    // Euler's verdict names its growth factor per step.
    let euler = claim(&t, "fig4-euler-error");
    let g = testing::run("integrators", "zeta=0.05&wn=2&h=0.3");
    assert!(
        euler.reason.contains(&testing::text(&g, "growth_euler")),
        "{}",
        euler.reason
    );
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

#[test]
fn the_tour_translates_into_spanish_without_english_left() {
    use crate::i18n::{tr, Lang};
    let es = tour().translated(|s| tr(Lang::Es, s).into_owned());
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
    ];
    let texts = es.exhibits.iter().flat_map(|e| [&e.place, &e.shows]).chain(
        es.claims
            .iter()
            .flat_map(|c| [&c.place, &c.says, &c.reason]),
    );
    for text in texts {
        for word in english {
            assert!(!text.contains(word), "untranslated {word:?} in {text:?}");
        }
    }
    // Numbers take the decimal comma; ids and links stay as they are.
    let euler = es
        .claims
        .iter()
        .find(|c| c.id == "fig4-euler-error")
        .unwrap();
    let g = testing::run("integrators", "zeta=0.05&wn=2&h=0.3");
    let growth = testing::text(&g, "growth_euler").replace('.', ",");
    assert!(
        euler.reason.contains(&growth),
        "{growth} in {}",
        euler.reason
    );
    assert!(euler.link.contains("h=0.3"), "{}", euler.link);
}
