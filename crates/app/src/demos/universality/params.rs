//! The universality demo's parameters: two slots, A and B, each choosing one of six
//! machines and holding its own copy of every machine's sliders, shown only while that
//! machine is chosen in that slot (`visible_when`).

use super::machine::{
    BORE, C, CAP, CF, CTH, EI, H, J, K, KD, KP, KT, L, LEN, M, MF, MU, R, RA, RHO, RTH,
};
use crate::declare::{choice_enum, Choice, Param};
use crate::demos::rows::sliders;

choice_enum! {
    /// The six machines.
    pub enum Kind {
        /// Mass on a spring and damper.
        #[default]
        MassSpring => ("mass-spring", "mass–spring–damper"),
        /// Series RLC circuit.
        Rlc => ("rlc", "series RLC circuit"),
        /// U-tube manometer.
        UTube => ("u-tube", "U-tube manometer"),
        /// DC-motor position servo under PD control.
        Servo => ("servo", "DC-motor position servo (PD control)"),
        /// Building storey under ground motion.
        Storey => ("storey", "building storey under ground motion"),
        /// Two-capacity thermal system.
        Thermal => ("thermal", "two-capacity thermal system"),
    }
}

/// Every machine's physical parameters in one slot, in SI units.
#[derive(Debug, Default, Clone, Copy, PartialEq)]
pub struct Values {
    /// Mass–spring: mass m \[kg\], damping c \[N·s/m\], spring rate k \[N/m\].
    pub m: f64,
    pub c: f64,
    pub k: f64,
    /// RLC: inductance L \[H\], resistance R \[Ω\], capacitance C \[F\].
    pub l: f64,
    pub r: f64,
    pub cap: f64,
    /// U-tube: column length \[m\], bore \[m\], density \[kg/m³\], viscosity \[Pa·s\].
    pub len: f64,
    pub bore: f64,
    pub rho: f64,
    pub mu: f64,
    /// Servo: inertia J \[kg·m²\], torque constant K_t \[N·m/A\], armature resistance
    /// \[Ω\], gains K_p \[V/rad\] and K_d \[V·s/rad\].
    pub j: f64,
    pub kt: f64,
    pub ra: f64,
    pub kp: f64,
    pub kd: f64,
    /// Storey: floor mass \[kg\], height \[m\], column EI \[N·m²\], damping \[N·s/m\].
    pub mf: f64,
    pub h: f64,
    pub ei: f64,
    pub cf: f64,
    /// Thermal: capacities C₁, C₂ \[J/K\], resistances R₁, R₂ \[K/W\].
    pub c1: f64,
    pub r1: f64,
    pub c2: f64,
    pub r2: f64,
}

/// One slot: the machine chosen and the values of every machine's sliders.
#[derive(Debug, Default, Clone, Copy, PartialEq)]
pub struct Slot {
    /// The machine chosen.
    pub kind: Kind,
    /// Slider values.
    pub v: Values,
}

/// Typed parameters, filled from the declaration.
#[derive(Debug, Default, Clone, Copy, PartialEq)]
pub struct P {
    /// Slots A (0) and B (1).
    pub slots: [Slot; 2],
    /// Tune B so that its ωₙ and ζ equal A's.
    pub matched: bool,
}

/// The machine each slot starts with.
const DEFAULT_KIND: [Kind; 2] = [Kind::MassSpring, Kind::Rlc];

/// `a` for slot A, `b` for slot B.
pub(super) const fn pick(slot: usize, a: &'static str, b: &'static str) -> &'static str {
    if slot == 0 {
        a
    } else {
        b
    }
}

/// How many sliders each machine has, in the order of the slider table of [`slot`].
const MACHINE_SLIDERS: [(Kind, usize); 6] = [
    (Kind::MassSpring, 3),
    (Kind::Rlc, 3),
    (Kind::UTube, 4),
    (Kind::Servo, 5),
    (Kind::Storey, 4),
    (Kind::Thermal, 4),
];

/// Slot `S`'s machine choice and every machine's sliders, each shown only while its
/// machine is chosen.
pub(super) fn slot<const S: usize>() -> Vec<Param<P>> {
    let key = |a, b| pick(S, a, b);
    let choice = key("A", "B");
    let sliders = sliders! { P, |p| p.slots[S].v;
        // Mass–spring–damper.
        log key("A_m", "B_m"), "mass", "m", "kg", M, 1.0 => m;
        linear key("A_c", "B_c"), "damping coefficient", "c", "N·s/m", C, 2.0 => c;
        log key("A_k", "B_k"), "spring rate", "k", "N/m", K, 100.0 => k;
        // Series RLC.
        log key("A_L", "B_L"), "inductance", "L", "H", L, 0.1 => l;
        linear key("A_R", "B_R"), "resistance", "R", "Ω", R, 10.0 => r;
        log key("A_C", "B_C"), "capacitance", "C", "F", CAP, 1e-3 => cap;
        // U-tube manometer.
        log key("A_len", "B_len"), "liquid column length", "L", "m", LEN, 0.5 => len;
        log key("A_bore", "B_bore"), "tube bore", "d", "m", BORE, 0.01 => bore;
        log key("A_rho", "B_rho"), "liquid density", "ρ", "kg/m³", RHO, 1000.0 => rho;
        log key("A_mu", "B_mu"), "dynamic viscosity", "μ", "Pa·s", MU, 1e-3 => mu;
        // DC-motor servo.
        log key("A_J", "B_J"), "inertia of motor and load", "J", "kg·m²", J, 1e-3 => j;
        log key("A_Kt", "B_Kt"), "motor torque constant", "K_t", "N·m/A", KT, 0.1 => kt;
        log key("A_Ra", "B_Ra"), "armature resistance", "R_a", "Ω", RA, 2.0 => ra;
        log key("A_Kp", "B_Kp"), "proportional gain", "K_p", "V/rad", KP, 20.0 => kp;
        linear key("A_Kd", "B_Kd"), "derivative gain", "K_d", "V·s/rad", KD, 0.1 => kd;
        // Building storey.
        log key("A_mf", "B_mf"), "floor mass", "m", "kg", MF, 20_000.0 => mf;
        linear key("A_h", "B_h"), "storey height", "h", "m", H, 3.0 => h;
        log key("A_EI", "B_EI"), "bending stiffness of each of the 4 columns", "EI", "N·m²",
            EI, 1e7 => ei;
        linear key("A_cf", "B_cf"), "storey damping coefficient", "c", "N·s/m",
            CF, 60_000.0 => cf;
        // Two-capacity thermal system.
        log key("A_C1", "B_C1"), "heat capacity of body 1", "C₁", "J/K", CTH, 5.0 => c1;
        log key("A_R1", "B_R1"), "thermal resistance, body 1 to surroundings", "R₁", "K/W",
            RTH, 0.5 => r1;
        log key("A_C2", "B_C2"), "heat capacity of body 2", "C₂", "J/K", CTH, 1.0 => c2;
        log key("A_R2", "B_R2"), "thermal resistance, body 2 to body 1", "R₂", "K/W",
            RTH, 2.0 => r2;
    };
    let kinds = MACHINE_SLIDERS
        .iter()
        .flat_map(|&(kind, n)| std::iter::repeat_n(kind, n));
    let mut params = vec![Param::choice(
        choice,
        key("machine A", "machine B"),
        DEFAULT_KIND[S],
        |p: &mut P, k| p.slots[S].kind = k,
    )];
    params.extend(
        sliders
            .into_iter()
            .zip(kinds)
            .map(|(s, kind)| s.visible_when(choice, kind.index())),
    );
    params
}
