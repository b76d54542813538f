// The sun-sky model of notes 03, Sun Sky: Preetham, Shirley and Smits, "A
// Practical Analytic Model for Daylight" (SIGGRAPH 1999). This is the twin
// of src/math/preetham.rs, which evaluates the same formula in f64 for
// the tests and computes these uniforms once per sun position
// (Sky::uniforms); glsl/sky/sun_sky.frag draws it.
//
//   F(theta, gamma) = (1 + A e^(B / cos theta)) (1 + C e^(D gamma) + E cos^2 gamma)   (paper eq. 3)
//   xyY = zenith * F(theta, gamma) / F(0, theta_s), per channel                      (paper eq. 4)
//
// theta is the view's angle from the zenith, gamma its angle from the sun,
// theta_s the sun's angle from the zenith. xyY then goes to CIE XYZ and to
// linear sRGB (the IEC 61966-2-1 matrix).
//
// The horizon: every B is negative, so e^(B / cos theta) -> 0 as
// cos theta -> 0+; cos theta is clamped to PREETHAM_HORIZON_COS, so there is
// no division by zero, no overflow below the horizon, and the sky below the
// horizon repeats the horizon (continuous across it).
// A sun below the horizon: the CPU has moved u_sun onto the horizon at the
// sun's azimuth and folded the twilight fade into u_zenith.z.

uniform vec3 u_perez[5]; // A, B, C, D, E, each for (x, y, Y)
uniform vec3 u_zenith;   // x_z, y_z, and Y_z in kcd/m^2 x Y_SCALE x the fade
uniform vec3 u_sun;      // unit direction to the sun the sky uses (y up, u_sun.y >= 0)

const float PREETHAM_HORIZON_COS = 1e-3; // HORIZON_COS in preetham.rs

// Perez's F for x, y and Y at once; cos_theta > 0.
vec3 preetham_perez(float cos_theta, float gamma) {
    float cos_gamma = cos(gamma);
    return (1.0 + u_perez[0] * exp(u_perez[1] / cos_theta))
         * (1.0 + u_perez[2] * exp(u_perez[3] * gamma) + u_perez[4] * cos_gamma * cos_gamma);
}

// The sky's linear sRGB radiance in the unit direction `view` (world space, y up).
vec3 preetham_sky(vec3 view) {
    float cos_theta = max(view.y, PREETHAM_HORIZON_COS);
    float gamma = acos(clamp(dot(view, u_sun), -1.0, 1.0));
    float theta_s = acos(clamp(u_sun.y, 0.0, 1.0));
    vec3 xyY = u_zenith * preetham_perez(cos_theta, gamma) / preetham_perez(1.0, theta_s);
    float y = max(xyY.y, 1e-6);
    vec3 XYZ = vec3(xyY.x * xyY.z / y, xyY.z, (1.0 - xyY.x - y) * xyY.z / y);
    vec3 rgb = vec3(dot(vec3( 3.2406, -1.5372, -0.4986), XYZ),
                    dot(vec3(-0.9689,  1.8758,  0.0415), XYZ),
                    dot(vec3( 0.0557, -0.2040,  1.0570), XYZ));
    return max(rgb, vec3(0.0));
}
