// A normal that is never NaN: an interpolated normal can be zero where a
// singular model matrix flattened the mesh; fall back to the face normal.
vec3 safe_normal(vec3 n, vec3 P) {
    float len = length(n);
    if (len > 1e-12) return n / len;
    vec3 face = cross(dFdx(P), dFdy(P));
    float fl = length(face);
    return fl > 1e-30 ? face / fl : vec3(0.0, 1.0, 0.0);
}
