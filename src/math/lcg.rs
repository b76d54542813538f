//! A tiny linear congruential generator for tests and seeded scenes
//! (`[[object_fields]]`): the same numbers on every run, and no crate
//! (Knuth's MMIX constants, the top 24 bits).

#[cfg(test)]
use glam::Vec3;

pub struct Lcg(pub u64);

impl Lcg {
    /// A number in [0, 1).
    pub fn next(&mut self) -> f32 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (self.0 >> 40) as f32 / (1u64 << 24) as f32
    }

    /// A number in [lo, hi).
    pub fn range(&mut self, lo: f32, hi: f32) -> f32 {
        lo + (hi - lo) * self.next()
    }

    /// A vector with each coordinate in [lo, hi).
    #[cfg(test)]
    pub fn vec(&mut self, lo: f32, hi: f32) -> Vec3 {
        Vec3::new(self.range(lo, hi), self.range(lo, hi), self.range(lo, hi))
    }
}
