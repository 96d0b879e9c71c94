//! Frequency response `H(r) = 1/(1 − r² + 2iζr)`: magnitude, phase, peak, half-power points.
