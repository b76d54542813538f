#version 330 core
// The demo's light-volume views (notes 04's debug view, the wireframe
// overlay, the overdraw count): each volume drawn in one flat colour.
uniform vec4 u_color;
out vec4 frag_color;
void main() {
    frag_color = u_color;
}
