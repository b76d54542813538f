//! Rendered glTF scenes against pixels predicted on the CPU.
