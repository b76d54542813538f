// The environment cube map (notes 03, Implementation: "skybox mirror
// reflection"): the [skybox] faces, or the [sky] rendered into a cube map
// (src/frame/environment.rs binds it on unit::ENVIRONMENT). A surface of
// reflectivity r adds r x environment(R), R = reflect(-V, N): the colour a
// perfect mirror shows, scaled. The passes that read it enable
// GL_TEXTURE_CUBE_MAP_SEAMLESS, so filtering crosses the faces' edges.
uniform samplerCube u_environment;
uniform bool u_has_environment;   // false: the scene has no environment

// What a surface of `reflectivity` with unit normal N mirrors towards the
// unit direction V to the eye.
vec3 environment_reflection(float reflectivity, vec3 N, vec3 V) {
    if (!u_has_environment) return vec3(0.0);
    // Sampled whatever the reflectivity, so that the derivatives the mip
    // level is chosen from exist in every pixel of a 2x2 quad.
    vec3 mirrored = texture(u_environment, reflect(-V, N)).rgb;
    return reflectivity * mirrored;
}
