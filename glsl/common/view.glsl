// The view a world pass draws for (src/frame/views.rs). A mirror's reflected
// view cuts away what lies behind the mirror: a plane for a planar mirror
// (gl_ClipDistance[0] = dot(plane, world), the plane in world space like the
// vertex), the sphere's inside for a curved one. A curved mirror also moves
// each vertex to its own mirror image (notes 05: "curved mirrors by
// reflecting vertices differently"). GL_CLIP_DISTANCE0 is enabled only for
// a reflected view; otherwise the clip distance is ignored.
uniform vec4 u_clip_plane;
uniform vec4 u_curved_mirror;   // centre xyz, radius w; w = 0: no curved mirror
uniform vec3 u_curved_eye;      // the eye the curved mirror is seen from (world)

// The image of `world` in a convex spherical mirror: reflected about its
// own tangent plane, the one at the sphere point whose normal halves the
// angle (seen from the centre) between the eye and the vertex. When the
// vertex and the eye are equally far from the centre that point is the
// exact reflection point (the law of reflection holds there), and the image
// lies on the eye's ray through it; otherwise it is close. Its CPU twin is
// `curved_image` in src/frame/views.rs.
vec4 view_position(vec4 world) {
    float r = u_curved_mirror.w;
    if (r <= 0.0) {
        return world;
    }
    vec3 c = u_curved_mirror.xyz;
    vec3 to_eye = normalize(u_curved_eye - c);
    vec3 to_p = normalize(world.xyz - c);
    vec3 h = to_eye + to_p;
    vec3 n = length(h) > 1e-6 ? normalize(h) : to_eye;
    vec3 s = c + r * n;
    return vec4(world.xyz - 2.0 * dot(world.xyz - s, n) * n, 1.0);
}

// The scene's [[clip_planes]] (src/scene/clip_planes.rs), world space
// (n, -n . p): gl_ClipDistance[1 + i] = dot(plane i, world), kept where it
// is >= 0. The pass enables GL_CLIP_DISTANCE1 + i for each plane the scene
// has; the others are written and ignored.
uniform vec4 u_clip_planes[7];

float clip_distance(vec4 world) {
    if (u_curved_mirror.w > 0.0) {
        return length(world.xyz - u_curved_mirror.xyz) - u_curved_mirror.w;
    }
    return dot(u_clip_plane, world);
}

// Every clip distance of a vertex at `world`: the mirror's (0), then the
// scene's planes (1 to 7). Constant indices, so gl_ClipDistance's size (8,
// GL 3.3's minimum of GL_MAX_CLIP_DISTANCES) is known without redeclaring it.
void write_clip_distances(vec4 world) {
    gl_ClipDistance[0] = clip_distance(world);
    gl_ClipDistance[1] = dot(u_clip_planes[0], world);
    gl_ClipDistance[2] = dot(u_clip_planes[1], world);
    gl_ClipDistance[3] = dot(u_clip_planes[2], world);
    gl_ClipDistance[4] = dot(u_clip_planes[3], world);
    gl_ClipDistance[5] = dot(u_clip_planes[4], world);
    gl_ClipDistance[6] = dot(u_clip_planes[5], world);
    gl_ClipDistance[7] = dot(u_clip_planes[6], world);
}
