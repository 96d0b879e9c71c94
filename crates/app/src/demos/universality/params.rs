//! The universality demo's parameters: two slots, A and B, each choosing one of six
//! machines and holding its own copy of every machine's sliders, shown only while that
//! machine is chosen in that slot (`visible_when`).

use super::machine::{
    BORE, C, CAP, CF, CTH, EI, H, J, K, KD, KP, KT, L, LEN, M, MF, MU, R, RA, RHO, RTH,
};
use crate::declare::{choice_enum, Choice, Param};

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

/// Slot `S`'s machine choice and every machine's sliders, each shown only while its
/// machine is chosen.
pub(super) fn slot<const S: usize>() -> Vec<Param<P>> {
    let key = |a, b| pick(S, a, b);
    let choice = key("A", "B");
    let of = |p: Param<P>, kind: Kind| p.visible_when(choice, kind.index());
    use Kind::*;
    vec![
        Param::choice(
            choice,
            key("machine A", "machine B"),
            DEFAULT_KIND[S],
            |p, k| p.slots[S].kind = k,
        ),
        // Mass–spring–damper.
        of(
            Param::log(key("A_m", "B_m"), "mass", "m", "kg", M, 1.0, |p, v| {
                p.slots[S].v.m = v
            }),
            MassSpring,
        ),
        of(
            Param::linear(
                key("A_c", "B_c"),
                "damping coefficient",
                "c",
                "N·s/m",
                C,
                2.0,
                |p, v| p.slots[S].v.c = v,
            ),
            MassSpring,
        ),
        of(
            Param::log(
                key("A_k", "B_k"),
                "spring rate",
                "k",
                "N/m",
                K,
                100.0,
                |p, v| p.slots[S].v.k = v,
            ),
            MassSpring,
        ),
        // Series RLC.
        of(
            Param::log(key("A_L", "B_L"), "inductance", "L", "H", L, 0.1, |p, v| {
                p.slots[S].v.l = v
            }),
            Rlc,
        ),
        of(
            Param::linear(
                key("A_R", "B_R"),
                "resistance",
                "R",
                "Ω",
                R,
                10.0,
                |p, v| p.slots[S].v.r = v,
            ),
            Rlc,
        ),
        of(
            Param::log(
                key("A_C", "B_C"),
                "capacitance",
                "C",
                "F",
                CAP,
                1e-3,
                |p, v| p.slots[S].v.cap = v,
            ),
            Rlc,
        ),
        // U-tube manometer.
        of(
            Param::log(
                key("A_len", "B_len"),
                "liquid column length",
                "L",
                "m",
                LEN,
                0.5,
                |p, v| p.slots[S].v.len = v,
            ),
            UTube,
        ),
        of(
            Param::log(
                key("A_bore", "B_bore"),
                "tube bore",
                "d",
                "m",
                BORE,
                0.01,
                |p, v| p.slots[S].v.bore = v,
            ),
            UTube,
        ),
        of(
            Param::log(
                key("A_rho", "B_rho"),
                "liquid density",
                "ρ",
                "kg/m³",
                RHO,
                1000.0,
                |p, v| p.slots[S].v.rho = v,
            ),
            UTube,
        ),
        of(
            Param::log(
                key("A_mu", "B_mu"),
                "dynamic viscosity",
                "μ",
                "Pa·s",
                MU,
                1e-3,
                |p, v| p.slots[S].v.mu = v,
            ),
            UTube,
        ),
        // DC-motor servo.
        of(
            Param::log(
                key("A_J", "B_J"),
                "inertia of motor and load",
                "J",
                "kg·m²",
                J,
                1e-3,
                |p, v| p.slots[S].v.j = v,
            ),
            Servo,
        ),
        of(
            Param::log(
                key("A_Kt", "B_Kt"),
                "motor torque constant",
                "K_t",
                "N·m/A",
                KT,
                0.1,
                |p, v| p.slots[S].v.kt = v,
            ),
            Servo,
        ),
        of(
            Param::log(
                key("A_Ra", "B_Ra"),
                "armature resistance",
                "R_a",
                "Ω",
                RA,
                2.0,
                |p, v| p.slots[S].v.ra = v,
            ),
            Servo,
        ),
        of(
            Param::log(
                key("A_Kp", "B_Kp"),
                "proportional gain",
                "K_p",
                "V/rad",
                KP,
                20.0,
                |p, v| p.slots[S].v.kp = v,
            ),
            Servo,
        ),
        of(
            Param::linear(
                key("A_Kd", "B_Kd"),
                "derivative gain",
                "K_d",
                "V·s/rad",
                KD,
                0.1,
                |p, v| p.slots[S].v.kd = v,
            ),
            Servo,
        ),
        // Building storey.
        of(
            Param::log(
                key("A_mf", "B_mf"),
                "floor mass",
                "m",
                "kg",
                MF,
                20_000.0,
                |p, v| p.slots[S].v.mf = v,
            ),
            Storey,
        ),
        of(
            Param::linear(
                key("A_h", "B_h"),
                "storey height",
                "h",
                "m",
                H,
                3.0,
                |p, v| p.slots[S].v.h = v,
            ),
            Storey,
        ),
        of(
            Param::log(
                key("A_EI", "B_EI"),
                "bending stiffness of each of the 4 columns",
                "EI",
                "N·m²",
                EI,
                1e7,
                |p, v| p.slots[S].v.ei = v,
            ),
            Storey,
        ),
        of(
            Param::linear(
                key("A_cf", "B_cf"),
                "storey damping coefficient",
                "c",
                "N·s/m",
                CF,
                60_000.0,
                |p, v| p.slots[S].v.cf = v,
            ),
            Storey,
        ),
        // Two-capacity thermal system.
        of(
            Param::log(
                key("A_C1", "B_C1"),
                "heat capacity of body 1",
                "C₁",
                "J/K",
                CTH,
                5.0,
                |p, v| p.slots[S].v.c1 = v,
            ),
            Thermal,
        ),
        of(
            Param::log(
                key("A_R1", "B_R1"),
                "thermal resistance, body 1 to surroundings",
                "R₁",
                "K/W",
                RTH,
                0.5,
                |p, v| p.slots[S].v.r1 = v,
            ),
            Thermal,
        ),
        of(
            Param::log(
                key("A_C2", "B_C2"),
                "heat capacity of body 2",
                "C₂",
                "J/K",
                CTH,
                1.0,
                |p, v| p.slots[S].v.c2 = v,
            ),
            Thermal,
        ),
        of(
            Param::log(
                key("A_R2", "B_R2"),
                "thermal resistance, body 2 to body 1",
                "R₂",
                "K/W",
                RTH,
                2.0,
                |p, v| p.slots[S].v.r2 = v,
            ),
            Thermal,
        ),
    ]
}
