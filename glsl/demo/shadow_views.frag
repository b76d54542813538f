#version 330 core
// The demo's shadow-map inspector (src/demo/shadow_views.rs), two passes:
//   u_pass 0: the map's stored value laid out in u_rect (pixels: x, y,
//     width, height), a 2D map as the light sees it or a cube's six faces
//     unfolded into a cross, into a float target cleared to -1. The map is
//     read through a sampler object with GL_TEXTURE_COMPARE_MODE = GL_NONE,
//     so the plain samplers below return the stored depth.
//   u_pass 1: that layout made visible: u_min black to u_max white; 1.0
//     (nothing drawn there) u_nothing; -1 (outside the map) u_background.
uniform sampler2D u_map;
uniform samplerCube u_cube_map;
uniform sampler2D u_layout;
uniform int u_pass;
uniform bool u_cube;
uniform int u_face;      // one face of the cube alone (0..5, GL's order), -1: the cross
uniform vec4 u_rect;
uniform float u_min;
uniform float u_max;
uniform vec3 u_background;
uniform vec3 u_nothing;
out vec4 frag_color;

// The direction through point p (each coordinate in -1..1, x right, y up)
// of cell `cell` (column, row from the bottom) of the cross
//         +y
//   -x    +z    +x    -z
//         -y
// Each face comes out as GL stores it (s to the right, t = 0 at the top:
// the spec's face table), so neighbouring faces share their edges. False
// outside the cross.
bool cross_direction(ivec2 cell, vec2 p, out vec3 d) {
    d = vec3(0.0);
    if (cell.y == 1) {
        if (cell.x == 0) {
            d = vec3(-1.0, p.y, p.x);   // -x
        } else if (cell.x == 1) {
            d = vec3(p.x, p.y, 1.0);    // +z
        } else if (cell.x == 2) {
            d = vec3(1.0, p.y, -p.x);   // +x
        } else {
            d = vec3(-p.x, p.y, -1.0);  // -z
        }
        return true;
    }
    if (cell.x != 1) {
        return false;
    }
    // +y above +z, -y below it.
    d = cell.y == 2 ? vec3(p.x, 1.0, -p.y) : vec3(p.x, -1.0, p.y);
    return true;
}

void main() {
    if (u_pass == 1) {
        float v = texelFetch(u_layout, ivec2(gl_FragCoord.xy), 0).r;
        vec3 c;
        if (v < 0.0) {
            c = u_background;
        } else if (v >= 1.0) {
            c = u_nothing;
        } else {
            c = vec3(clamp((v - u_min) / max(u_max - u_min, 1e-7), 0.0, 1.0));
        }
        frag_color = vec4(c, 1.0);
        return;
    }
    vec2 uv = (gl_FragCoord.xy - u_rect.xy) / u_rect.zw;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThanEqual(uv, vec2(1.0)))) {
        discard;
    }
    float depth;
    if (u_cube) {
        vec2 g = uv * vec2(4.0, 3.0);
        ivec2 cell = ivec2(floor(g));
        vec2 p = fract(g) * 2.0 - 1.0;
        if (u_face >= 0) {
            // The face's cell of the cross (+x, -x, +y, -y, +z, -z), filling the square.
            const ivec2 FACE_CELL[6] = ivec2[](ivec2(2, 1), ivec2(0, 1), ivec2(1, 2),
                                               ivec2(1, 0), ivec2(1, 1), ivec2(3, 1));
            cell = FACE_CELL[u_face];
            p = uv * 2.0 - 1.0;
        }
        vec3 d;
        if (!cross_direction(cell, p, d)) {
            discard;
        }
        depth = texture(u_cube_map, d).r;
    } else {
        depth = texture(u_map, uv).r;
    }
    frag_color = vec4(depth, 0.0, 0.0, 1.0);
}
