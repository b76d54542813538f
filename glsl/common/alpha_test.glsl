// The alpha test (notes 05, "Alpha Test"). GL 3.3 core has no fixed-function
// alpha test, so the fragment shader does it:
//
//   if (alpha_fragment op alpha_reference)
//       pass fragment on
//
// op is one of <, <=, ==, !=, >, >= or the special tests always and never.
// The numbers are AlphaTest::code in src/scene/alpha_test.rs, which is also
// the CPU twin of alpha_test_passes. ALPHA_ALWAYS is 0, so a program that
// never sets u_alpha_test tests nothing.
#define ALPHA_ALWAYS 0
#define ALPHA_NEVER 1
#define ALPHA_LESS 2
#define ALPHA_LEQUAL 3
#define ALPHA_EQUAL 4
#define ALPHA_NOTEQUAL 5
#define ALPHA_GREATER 6
#define ALPHA_GEQUAL 7

uniform int u_alpha_test;    // op
uniform float u_alpha_ref;   // alpha_reference

bool alpha_test_passes(float alpha, int op, float reference) {
    if (op == ALPHA_NEVER) return false;
    if (op == ALPHA_LESS) return alpha < reference;
    if (op == ALPHA_LEQUAL) return alpha <= reference;
    if (op == ALPHA_EQUAL) return alpha == reference;
    if (op == ALPHA_NOTEQUAL) return alpha != reference;
    if (op == ALPHA_GREATER) return alpha > reference;
    if (op == ALPHA_GEQUAL) return alpha >= reference;
    return true;  // ALPHA_ALWAYS
}

// Stop the fragment unless it passes: no colour, no depth written.
void alpha_test(float alpha) {
    if (!alpha_test_passes(alpha, u_alpha_test, u_alpha_ref)) discard;
}
