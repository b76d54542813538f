//! Window backend (being written).
