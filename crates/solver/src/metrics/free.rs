//! Free-response metrics relative to the initial displacement: settling, rebound, decrement.
