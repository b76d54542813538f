#version 400 core
// Tessellation (src/techniques/vertex_geometry/tessellation.rs), step 1: the
// vertex shader passes each patch corner on unchanged; the tessellator runs
// after it (notes 01 §3.1).
layout(location = 0) in vec3 a_position;

void main() {
    gl_Position = vec4(a_position, 1.0);
}
