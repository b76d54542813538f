#version 330 core
// FXAA 3.11, quality version (Timothy Lottes, "FXAA", NVIDIA whitepaper,
// 2009; FXAA 3.11 source, NVIDIA, 2011), a stage of the post chain after
// tone mapping and before gamma (src/techniques/post/fxaa.rs has the steps).
// The input is tone-mapped linear colour, read through a linear,
// clamp-to-edge sampler: the search and the blend fetch between texels.
// GL's y points up: N is +y, S is -y. "Neg" is the -x or -y side.
uniform sampler2D u_image;
uniform float u_subpix;             // fxaaQualitySubpix
uniform float u_edge_threshold;     // fxaaQualityEdgeThreshold
uniform float u_edge_threshold_min; // fxaaQualityEdgeThresholdMin
uniform int u_steps;                // the preset's search steps (FXAA_QUALITY__PS)
uniform float u_step[12];           // FXAA_QUALITY__P0 ..: texels per step
out vec4 frag_color;

// FXAA wants luma in a perceptual space; for linear colour its source
// gives sqrt(dot(rgb, (0.299, 0.587, 0.114))), gamma 2.0.
float luma(vec3 c) {
    return sqrt(max(dot(c, vec3(0.299, 0.587, 0.114)), 0.0));
}

float luma_at(vec2 uv) {
    return luma(textureLod(u_image, uv, 0.0).rgb);
}

// A neighbour, o texels away (textureLodOffset wants a constant offset).
float luma_near(vec2 uv, vec2 o, vec2 texel) {
    return luma(textureLod(u_image, uv + o * texel, 0.0).rgb);
}

void main() {
    vec2 texel = 1.0 / vec2(textureSize(u_image, 0));
    vec2 uv = gl_FragCoord.xy * texel;
    vec4 centre = textureLod(u_image, uv, 0.0);
    float lumaM = luma(centre.rgb);
    float lumaN = luma_near(uv, vec2(0.0, 1.0), texel);
    float lumaS = luma_near(uv, vec2(0.0, -1.0), texel);
    float lumaE = luma_near(uv, vec2(1.0, 0.0), texel);
    float lumaW = luma_near(uv, vec2(-1.0, 0.0), texel);

    // 1. Local contrast: too little, and the pixel is no edge.
    float rangeMax = max(max(max(lumaN, lumaS), max(lumaE, lumaW)), lumaM);
    float rangeMin = min(min(min(lumaN, lumaS), min(lumaE, lumaW)), lumaM);
    float range = rangeMax - rangeMin;
    if (range < max(u_edge_threshold_min, rangeMax * u_edge_threshold)) {
        frag_color = centre;
        return;
    }
    float lumaNE = luma_near(uv, vec2(1.0, 1.0), texel);
    float lumaNW = luma_near(uv, vec2(-1.0, 1.0), texel);
    float lumaSE = luma_near(uv, vec2(1.0, -1.0), texel);
    float lumaSW = luma_near(uv, vec2(-1.0, -1.0), texel);

    // 2. Sub-pixel aliasing: the pixel against the 3x3 lowpass (edges
    // weighted 2, corners 1), relative to the range, smoothstep, squared.
    float lowpass = (2.0 * (lumaN + lumaS + lumaE + lumaW) + lumaNE + lumaNW + lumaSE + lumaSW) / 12.0;
    float subpixC = clamp(abs(lowpass - lumaM) / range, 0.0, 1.0);
    float subpixF = (-2.0 * subpixC + 3.0) * subpixC * subpixC;
    float subpixOffset = subpixF * subpixF * u_subpix;

    // 3. Edge direction: second differences across the rows (a horizontal
    // edge) against those across the columns (a vertical edge).
    float edgeHorz = abs(lumaNW + lumaSW - 2.0 * lumaW)
                   + 2.0 * abs(lumaN + lumaS - 2.0 * lumaM)
                   + abs(lumaNE + lumaSE - 2.0 * lumaE);
    float edgeVert = abs(lumaSW + lumaSE - 2.0 * lumaS)
                   + 2.0 * abs(lumaW + lumaE - 2.0 * lumaM)
                   + abs(lumaNW + lumaNE - 2.0 * lumaN);
    bool horzSpan = edgeHorz >= edgeVert;
    // Across the edge: y for a horizontal edge, x for a vertical one. The
    // edge lies on the side of the steeper gradient.
    float lumaNeg = horzSpan ? lumaS : lumaW;
    float lumaPos = horzSpan ? lumaN : lumaE;
    float gradientNeg = lumaNeg - lumaM;
    float gradientPos = lumaPos - lumaM;
    bool pairNeg = abs(gradientNeg) >= abs(gradientPos);
    float gradient = max(abs(gradientNeg), abs(gradientPos));
    float across = horzSpan ? texel.y : texel.x;
    if (pairNeg) across = -across;
    float lumaEdge = 0.5 * (lumaM + (pairNeg ? lumaNeg : lumaPos));

    // 4. Search along the edge, both ways, from half a texel across: stop
    // where the luma leaves the edge's average by a quarter of the gradient.
    vec2 posB = uv + (horzSpan ? vec2(0.0, 0.5 * across) : vec2(0.5 * across, 0.0));
    vec2 along = horzSpan ? vec2(texel.x, 0.0) : vec2(0.0, texel.y);
    vec2 posN = posB - along * u_step[0];
    vec2 posP = posB + along * u_step[0];
    float gradientScaled = 0.25 * gradient;
    float lumaEndN = luma_at(posN) - lumaEdge;
    float lumaEndP = luma_at(posP) - lumaEdge;
    bool doneN = abs(lumaEndN) >= gradientScaled;
    bool doneP = abs(lumaEndP) >= gradientScaled;
    if (!doneN) posN -= along * u_step[1];
    if (!doneP) posP += along * u_step[1];
    for (int i = 2; i < u_steps && !(doneN && doneP); i++) {
        if (!doneN) lumaEndN = luma_at(posN) - lumaEdge;
        if (!doneP) lumaEndP = luma_at(posP) - lumaEdge;
        doneN = abs(lumaEndN) >= gradientScaled;
        doneP = abs(lumaEndP) >= gradientScaled;
        // Past the last fetch, the last step is FXAA's guess at the end.
        if (!doneN) posN -= along * u_step[i];
        if (!doneP) posP += along * u_step[i];
    }

    // 5. Blend: the nearer end says where along the edge the pixel lies;
    // only an end where the luma crosses to the other side of the edge's
    // average from the pixel's counts. Move that far across the edge (or
    // the sub-pixel amount, if larger) and fetch between the two sides.
    float dstN = horzSpan ? uv.x - posN.x : uv.y - posN.y;
    float dstP = horzSpan ? posP.x - uv.x : posP.y - uv.y;
    bool lumaMBelow = lumaM - lumaEdge < 0.0;
    bool goodSpanN = (lumaEndN < 0.0) != lumaMBelow;
    bool goodSpanP = (lumaEndP < 0.0) != lumaMBelow;
    bool nearerN = dstN < dstP;
    float dst = min(dstN, dstP);
    bool goodSpan = nearerN ? goodSpanN : goodSpanP;
    float pixelOffset = goodSpan ? 0.5 - dst / (dstN + dstP) : 0.0;
    float offset = max(pixelOffset, subpixOffset);
    vec2 pos = uv + (horzSpan ? vec2(0.0, offset * across) : vec2(offset * across, 0.0));
    frag_color = vec4(textureLod(u_image, pos, 0.0).rgb, centre.a);
}
