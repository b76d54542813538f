#version 330 core
// The sun-sky pass: the Preetham sky (common/preetham.glsl, the twin of
// src/math/preetham.rs) in the direction of each pixel's ray.
#include "common/preetham.glsl"
#include "common/lighting_output.glsl"
in vec3 v_direction;
uniform float u_sky_intensity;
// The sun's disc (src/scene/sky.rs, sun_disc_radiance): radiance, the
// direction to the sun, and the cosine of its angular radius.
uniform vec3 u_sun_disc;
uniform vec3 u_sun_direction;
uniform float u_sun_cos_radius;
out vec4 frag_color;

void main() {
    vec3 d = normalize(v_direction);
    vec3 c = u_sky_intensity * preetham_sky(d);
    if (dot(d, u_sun_direction) >= u_sun_cos_radius) {
        c += u_sun_disc;
    }
    frag_color = output_color(c);
}
