//! Design tool: sweep.
