//! Numerical integrators for first-order systems `y' = f(t, y)` of any dimension.
