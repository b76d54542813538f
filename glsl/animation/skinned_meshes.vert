// The skinning pass (notes 01 §7.1, "Skinned meshes"): one point per
// bind-pose vertex in, the skinned vertex out through transform feedback
// (GL_RASTERIZER_DISCARD is on: nothing is drawn). The captured outputs,
// interleaved as position, normal, uv, are exactly the 32-byte vertex of
// the mesh every other pass draws.
//
// Defines: MAX_JOINTS (the uniform array's size, from
// GL_MAX_VERTEX_UNIFORM_COMPONENTS), JOINTS_IN_TEXTURE (read the joints
// from a buffer texture instead, four RGBA32F texels each) and
// DUAL_QUATERNION (each joint is (real, dual, 0, 0), not a matrix).
#version 330 core

layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;
// At most four joints influence a vertex (the notes: "must enforce a
// maximum number of joints that a single vertex can be influenced by").
layout(location = 3) in uvec4 a_joints;
layout(location = 4) in vec4 a_weights;

out vec3 v_position;
out vec3 v_normal;
out vec2 v_uv;

#ifdef JOINTS_IN_TEXTURE
uniform samplerBuffer u_joint_texture;
mat4 joint(uint j) {
    int t = 4 * int(j);
    return mat4(texelFetch(u_joint_texture, t), texelFetch(u_joint_texture, t + 1),
                texelFetch(u_joint_texture, t + 2), texelFetch(u_joint_texture, t + 3));
}
#else
uniform mat4 u_joints[MAX_JOINTS];
mat4 joint(uint j) {
    return u_joints[j];
}
#endif

#ifdef DUAL_QUATERNION
// q * v * conjugate(q) for a unit quaternion q = (x, y, z, w).
vec3 rotate(vec4 q, vec3 v) {
    return v + 2.0 * cross(q.xyz, cross(q.xyz, v) + q.w * v);
}

void main() {
    // Blend the dual quaternions, each on the first one's hemisphere
    // (q and -q are the same rotation; the shortest blend needs one sign).
    // The first influence with a weight is the anchor, as on the CPU.
    vec4 first = vec4(0.0);
    vec4 real = vec4(0.0), dual = vec4(0.0);
    for (int k = 0; k < 4; ++k) {
        float w = a_weights[k];
        if (w == 0.0) continue;
        mat4 d = joint(a_joints[k]);
        if (first == vec4(0.0)) first = d[0];
        float s = dot(d[0], first) < 0.0 ? -w : w;
        real += d[0] * s;
        dual += d[1] * s;
    }
    float len = length(real);
    real /= len;
    dual /= len;
    // The translation: 2 dual conjugate(real), its vector part.
    vec3 t = 2.0 * (real.w * dual.xyz - dual.w * real.xyz + cross(real.xyz, dual.xyz));
    v_position = rotate(real, a_position) + t;
    v_normal = normalize(rotate(real, a_normal));
    v_uv = a_uv;
}
#else
void main() {
    // The notes' formula: position = sum of (t . v) . w over the influences.
    vec3 p = vec3(0.0), n = vec3(0.0);
    for (int k = 0; k < 4; ++k) {
        float w = a_weights[k];
        if (w == 0.0) continue;
        mat4 t = joint(a_joints[k]);
        p += (t * vec4(a_position, 1.0)).xyz * w;
        n += mat3(t) * a_normal * w;
    }
    v_position = p;
    v_normal = normalize(n);
    v_uv = a_uv;
}
#endif
