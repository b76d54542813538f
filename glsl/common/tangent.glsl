// The tangent frame out of a vertex shader (notes 01 §8.4). The tangent
// points along increasing u on the surface, so it moves with the surface:
// mat3(u_model), not the normal matrix. Its w is the handedness (B =
// cross(N, T) * w), times -1 when the model matrix mirrors (a mirrored
// frame's cross product turns the other way). Include after u_model.
layout(location = 3) in vec4 a_tangent;
uniform float u_tangent_sign;   // sign(det(mat3(u_model)))

out vec4 v_tangent;

void write_tangent() {
    v_tangent = vec4(mat3(u_model) * a_tangent.xyz, a_tangent.w * u_tangent_sign);
}
