#version 330 core
// Not a pass of the frame: the SSAO measurements (src/bench/ssao.rs) read
// the G-buffer's geometry back through this, so that the CPU reference of
// the ambient light pass (notes 03, "Ambient Light") sees the normal and
// depth the pass saw, decoded by gbuffer_read.glsl as the pass decodes
// them. Written to an RGBA32F target: normal xyz, window depth w.
#include "common/gbuffer_read.glsl"
out vec4 geometry_out;

void main() {
    Surface s = read_geometry_texel(ivec2(gl_FragCoord.xy));
    geometry_out = vec4(s.N, s.depth);
}
