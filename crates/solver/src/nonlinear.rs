//! Nonlinear quarter car: Duffing spring, asymmetric damper, Coulomb friction, bump stops.
