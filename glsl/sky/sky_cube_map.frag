#version 330 core
// The [sky] rendered into a cube map (notes 03, Implementation: the skybox
// cube map; Sun Sky: the Preetham model): one full-screen triangle per
// face, each texel the sky along the direction through its centre. The
// face table is GL's (GL 3.3 §3.8.10, table 3.19), the twin of
// `direction` in src/math/cube_map.rs; window row 0 is the face's t = 0.
#include "common/preetham.glsl"
uniform int u_face;             // 0..5: +x, -x, +y, -y, +z, -z
uniform float u_size;           // the face's side in texels
uniform float u_sky_intensity;
out vec4 frag_color;

vec3 face_direction(int face, vec2 st) {
    vec2 c = 2.0 * st - 1.0;   // (sc, tc)
    if (face == 0) return vec3(1.0, -c.y, -c.x);
    if (face == 1) return vec3(-1.0, -c.y, c.x);
    if (face == 2) return vec3(c.x, 1.0, c.y);
    if (face == 3) return vec3(c.x, -1.0, -c.y);
    if (face == 4) return vec3(c.x, -c.y, 1.0);
    return vec3(-c.x, -c.y, -1.0);
}

void main() {
    vec3 d = normalize(face_direction(u_face, gl_FragCoord.xy / u_size));
    frag_color = vec4(u_sky_intensity * preetham_sky(d), 1.0);
}
