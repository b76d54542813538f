#version 330 core
// The diffuse term of image-based lighting: E(N) / pi, the cosine-weighted
// mean of the environment about N, into a small cube map. A convolution,
// not spherical harmonics: every texel of the environment's mip level of
// u_source_size texels a side, weighted by its solid angle and max(N.L, 0),
// over the sum of the weights (pi in the limit; a uniform environment gives
// itself exactly). Order-2 harmonics ring under a sun (negative light
// opposite it); a sum of positive terms cannot. CPU twin:
// `irradiance_convolution` in src/lighting/image_based_lighting.rs.
#include "common/cube_face.glsl"
uniform samplerCube u_environment;
uniform int u_face;             // the output face, 0..5
uniform float u_size;           // the output face's side in texels
uniform int u_source_level;     // the environment's level read
uniform int u_source_size;      // its side in texels
out vec4 frag_color;

// The solid angle of the face rectangle (x0, y0)-(x1, y1) in [-1, 1]^2.
float area(float x, float y) {
    return atan(x * y, sqrt(x * x + y * y + 1.0));
}

void main() {
    vec3 N = normalize(cube_face_direction(u_face, gl_FragCoord.xy / u_size));
    vec3 sum = vec3(0.0);
    float weight = 0.0;
    float n = float(u_source_size);
    for (int face = 0; face < 6; ++face) {
        for (int j = 0; j < u_source_size; ++j) {
            for (int i = 0; i < u_source_size; ++i) {
                vec2 st = (vec2(i, j) + 0.5) / n;
                vec3 L = normalize(cube_face_direction(face, st));
                float c = dot(N, L);
                if (c <= 0.0) continue;
                vec2 p0 = 2.0 * vec2(i, j) / n - 1.0;
                vec2 p1 = p0 + 2.0 / n;
                float omega = area(p0.x, p0.y) - area(p0.x, p1.y) - area(p1.x, p0.y) + area(p1.x, p1.y);
                // Texel (i, j) of that face at that level: along its centre's direction.
                sum += c * omega * textureLod(u_environment, L, float(u_source_level)).rgb;
                weight += c * omega;
            }
        }
    }
    frag_color = vec4(sum / weight, 1.0);
}
