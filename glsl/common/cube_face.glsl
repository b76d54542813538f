// The direction through (s, t) of a cube map face, GL's face table (GL 3.3
// §3.8.10, table 3.19): the twin of `direction` in src/math/cube_map.rs
// (sky/sky_cube_map.frag has the same table). Window row 0 is the face's t = 0.
#ifndef CUBE_FACE_GLSL
#define CUBE_FACE_GLSL
vec3 cube_face_direction(int face, vec2 st) {
    vec2 c = 2.0 * st - 1.0;   // (sc, tc)
    if (face == 0) return vec3(1.0, -c.y, -c.x);
    if (face == 1) return vec3(-1.0, -c.y, c.x);
    if (face == 2) return vec3(c.x, 1.0, c.y);
    if (face == 3) return vec3(c.x, -1.0, -c.y);
    if (face == 4) return vec3(c.x, -c.y, 1.0);
    return vec3(-c.x, -c.y, -1.0);
}
#endif
