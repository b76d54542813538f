//! The alpha test on the CPU (notes 05, "Alpha Test"): the twin of
//! `alpha_test_passes` in glsl/common/alpha_test.glsl, for the tests.
//!
//! ```text
//! if ( alpha_fragment  op  alpha_reference )
//!     pass fragment on
//! ```

use super::settings::AlphaTest;

impl AlphaTest {
    /// Whether a fragment of alpha `alpha` passes against `reference`.
    pub fn passes(self, alpha: f32, reference: f32) -> bool {
        match self {
            AlphaTest::Always => true,
            AlphaTest::Never => false,
            AlphaTest::Less => alpha < reference,
            AlphaTest::Lequal => alpha <= reference,
            AlphaTest::Equal => alpha == reference,
            AlphaTest::Notequal => alpha != reference,
            AlphaTest::Greater => alpha > reference,
            AlphaTest::Gequal => alpha >= reference,
        }
    }

    /// The value of `u_alpha_test` for this op: the ALPHA_* numbers of
    /// glsl/common/alpha_test.glsl. "always" is 0, so a program whose
    /// uniform was never set tests nothing.
    pub fn code(self) -> i32 {
        match self {
            AlphaTest::Always => 0,
            AlphaTest::Never => 1,
            AlphaTest::Less => 2,
            AlphaTest::Lequal => 3,
            AlphaTest::Equal => 4,
            AlphaTest::Notequal => 5,
            AlphaTest::Greater => 6,
            AlphaTest::Gequal => 7,
        }
    }
}

/// The billboards' alpha test: pass alpha >= `render.billboard_alpha_ref`,
/// whose default 0.5 is the notes' "Do not let alpha < 0.5 pass through".
pub const BILLBOARD_ALPHA_TEST: AlphaTest = AlphaTest::Gequal;
