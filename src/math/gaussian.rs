//! Blur kernels for notes 03, "Blur Pass and Merge Pass": the one-sided
//! weights of a separable Gaussian (or box) blur, and the linear-filtering
//! trick that halves the taps a shader makes.
//!
//! A separable blur filters the rows, then the columns, with the same 1D
//! kernel. The kernel is symmetric, so it is stored one-sided: `weights[0]`
//! is the centre texel, `weights[i]` the texels `i` to the left and `i` to
//! the right. The weights are computed in f64 and normalised so that
//!
//! ```text
//! w[0] + 2 (w[1] + ... + w[radius]) = 1
//! ```
//!
//! and a blur of a flat image is the image itself.
//!
//! The notes give each blur as a standard deviation `sigma` and a `radius`
//! (6.2 / 24, 24.9 / 80, 81.0 / 243, 263 / 799), both in full-resolution
//! pixels: the radius is about 3 sigma at every level. A kernel cut at
//! `radius` is a truncated Gaussian, whose variance is a little below
//! sigma²: [`Kernel::variance`] gives the exact figure (the 3-sigma cuts of
//! the notes give sigma × 0.987).
//!
//! The mip scheme blurs level k of a texture (2^k full-resolution pixels per
//! texel): [`level_kernel`] gives that level's kernel, in level-k texels,
//! after taking out the blur that going down to level k and back up already
//! adds ([`resample_sigma`]).

#[cfg(test)]
mod tests;

/// A symmetric 1D blur kernel, stored one-sided (see the module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct Kernel {
    /// The standard deviation it was made for, in texels (0 for the identity,
    /// infinite for a box).
    pub sigma: f64,
    /// The last texel it reaches on either side.
    pub radius: u32,
    /// `weights[i]` for `i` in `0..=radius`, `weights[0]` the centre.
    pub weights: Vec<f64>,
}

impl Kernel {
    /// The identity: one tap of weight 1.
    pub fn identity() -> Kernel {
        Kernel {
            sigma: 0.0,
            radius: 0,
            weights: vec![1.0],
        }
    }

    /// The Gaussian `exp(-i² / (2 sigma²))` on `i = -radius..=radius`,
    /// normalised. A `sigma` that is not above 0 (or NaN), or a `radius` of
    /// 0, gives the identity; an infinite `sigma` gives the box.
    pub fn gaussian(sigma: f64, radius: u32) -> Kernel {
        if sigma.is_nan() || sigma <= 0.0 || radius == 0 {
            return Kernel::identity();
        }
        if sigma.is_infinite() {
            return Kernel::box_(radius);
        }
        // exp underflows to 0 far from a small sigma, never to NaN, and the
        // centre weight is exp(0) = 1: the sum is at least 1.
        let two_sigma2 = 2.0 * sigma * sigma;
        let raw: Vec<f64> = (0..=radius)
            .map(|i| {
                let i = f64::from(i);
                (-i * i / two_sigma2).exp()
            })
            .collect();
        Kernel {
            sigma,
            radius,
            weights: normalised(raw),
        }
    }

    /// The box: `2 radius + 1` equal weights. Radius 0 is the identity.
    pub fn box_(radius: u32) -> Kernel {
        Kernel {
            sigma: f64::INFINITY,
            radius,
            weights: normalised(vec![1.0; radius as usize + 1]),
        }
    }

    /// The weight of the texel `offset` texels from the centre (0 beyond
    /// the radius).
    pub fn weight(&self, offset: i64) -> f64 {
        let i = offset.unsigned_abs();
        usize::try_from(i)
            .ok()
            .and_then(|i| self.weights.get(i))
            .copied()
            .unwrap_or(0.0)
    }

    /// `w[0] + 2 (w[1] + ... + w[radius])`: 1 for every kernel made here.
    pub fn sum(&self) -> f64 {
        self.weights[0] + 2.0 * self.weights[1..].iter().sum::<f64>()
    }

    /// The kernel's variance in texels², `sum over i of i² w[|i|]` (its
    /// mean is 0): sigma² for a wide radius, a little less when cut at
    /// 3 sigma.
    pub fn variance(&self) -> f64 {
        2.0 * self
            .weights
            .iter()
            .enumerate()
            .map(|(i, w)| (i * i) as f64 * w)
            .sum::<f64>()
    }

    /// The same kernel cut at a smaller `radius` (the "fewer taps" variant),
    /// normalised again. A radius at or beyond this one's returns a copy.
    pub fn cut(&self, radius: u32) -> Kernel {
        if radius >= self.radius {
            return self.clone();
        }
        Kernel {
            sigma: self.sigma,
            radius,
            weights: normalised(self.weights[..=radius as usize].to_vec()),
        }
    }
}

/// Scales one-sided weights so that `w[0] + 2 sum(w[1..]) = 1`.
fn normalised(mut w: Vec<f64>) -> Vec<f64> {
    let total = w[0] + 2.0 * w[1..].iter().sum::<f64>();
    for x in &mut w {
        *x /= total;
    }
    w
}

/// The linear-filtering trick: bilinear filtering returns
/// `(1 - f) T[i] + f T[i + 1]` for a sample at `i + f`, so one sample at
///
/// ```text
/// offset = (i w[i] + (i + 1) w[i + 1]) / (w[i] + w[i + 1]),  weight w[i] + w[i + 1]
/// ```
///
/// reads two texels with their two weights. The taps, one side (mirror them
/// for the other): the centre `(0, w[0])`, then one per pair (1, 2), (3, 4),
/// ...; an odd texel left at the end keeps its own tap `(radius, w[radius])`.
/// A pair whose weights are both 0 (far out on a narrow kernel, where exp
/// underflows) reads nothing and is left out.
///
/// Exact in real arithmetic. On a GPU the error comes from the sub-texel
/// precision of the filter weights (8 bits on llvmpipe).
pub fn linear_taps(k: &Kernel) -> Vec<(f64, f64)> {
    let w = &k.weights;
    let mut taps = vec![(0.0, w[0])];
    let mut i = 1;
    while i < w.len() {
        if i + 1 < w.len() {
            let weight = w[i] + w[i + 1];
            if weight > 0.0 {
                let offset = (i as f64 * w[i] + (i + 1) as f64 * w[i + 1]) / weight;
                taps.push((offset, weight));
            }
        } else if w[i] > 0.0 {
            taps.push((i as f64, w[i]));
        }
        i += 2;
    }
    taps
}

/// The one-sided taps of the direct kernel, one per texel: `(i, w[i])`.
pub fn direct_taps(k: &Kernel) -> Vec<(f64, f64)> {
    k.weights
        .iter()
        .enumerate()
        .map(|(i, &w)| (i as f64, w))
        .collect()
}

/// The standard deviation, in full-resolution pixels, of the blur that
/// taking an image down to mip level `level` and back up adds, averaged
/// over where a pixel sits in its level-k texel: `2^(level - 1)`, and 0 at
/// level 0.
///
/// With `h = 2^level` full-resolution pixels per level-k texel:
/// - going down, each texel is the mean of an h × h block: a pixel lands at
///   one of h offsets from its texel's centre, uniformly, variance
///   `(h² - 1) / 12` per axis;
/// - coming back up, bilinear filtering spreads a texel over the pixels
///   within h of its centre with the tent `1 - |d| / h`, at half-pixel
///   distances d: variance `h² / 6 + 1 / 12`.
///
/// Together `(h² - 1) / 12 + h² / 6 + 1 / 12 = h² / 4`.
pub fn resample_sigma(level: u32) -> f64 {
    if level == 0 {
        0.0
    } else {
        2f64.powi(level as i32 - 1)
    }
}

/// The kernel that blurs mip level `level` so that, once the level is
/// sampled back up, the image is blurred by `sigma` full-resolution pixels:
/// sigma_k = sqrt(sigma² - resample_sigma(level)²) / 2^level texels, cut at
/// the same number of sigmas as `radius` is (`radius / sigma`), rounded up.
/// The identity when the resampling alone already blurs as much as `sigma`.
pub fn level_kernel(sigma: f64, radius: u32, level: u32) -> Kernel {
    if sigma.is_nan() || sigma <= 0.0 || radius == 0 {
        return Kernel::identity();
    }
    let texel = 2f64.powi(level as i32);
    let rest2 = sigma * sigma - resample_sigma(level).powi(2);
    if rest2 <= 0.0 {
        return Kernel::identity();
    }
    let sigma_k = rest2.sqrt() / texel;
    let cuts = f64::from(radius) / sigma;
    // 1e-9 keeps a product that is an integer up to rounding from rounding up.
    let radius_k = (cuts * sigma_k - 1e-9)
        .ceil()
        .clamp(1.0, f64::from(u32::MAX)) as u32;
    Kernel::gaussian(sigma_k, radius_k)
}
