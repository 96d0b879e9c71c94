//! Design tool: sensitivity.
