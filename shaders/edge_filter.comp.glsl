#version 460
// The edge filter (crowdgpu::RendererSettings::edgeFilter): anti-aliasing of the finished picture in
// compute, after the colour pass, in the manner of FXAA (Lottes, 2009). On the H100/H200 every sample
// of multisampling is a fill on the small graphics slice; this pass reads and writes each pixel once
// on every shader core instead (docs/picture-quality.md, "The edge filter").
//
// Where a pixel's neighbourhood has contrast, the edge through it is found (horizontal or vertical,
// and on which side of the pixel), followed both ways to its ends, and the pixel takes a share of its
// neighbour across the edge by where it lies along it: a staircase step's pixels near its middle keep
// their colour, those near its ends blend up to half. A pixel unlike its whole 3x3 neighbourhood (a
// character a pixel or two wide) is blended too, by how unlike. Colours are blended linear, as a
// supersampled render averages them. One thread a pixel; the texture cache serves the neighbours.
layout(local_size_x = 16, local_size_y = 8) in;

// The destination is an R8G8B8A8_UNORM view of an sRGB picture: the filter encodes.
layout(constant_id = 0) const bool kEncodeSrgb = true;

layout(set = 0, binding = 0) uniform sampler2D picture;  // linear filtering, clamped to the edge
layout(set = 0, binding = 1, rgba8) uniform writeonly image2D filtered;

layout(push_constant) uniform Push { ivec2 extent; } push;

// Contrast (of perceptual luma, 0..1) under which a neighbourhood is left as it is: absolute, for dark
// areas, and relative to its brightest pixel. Below them the filter would only blur texture.
const float kLeastContrast = 0.0312;
const float kRelativeContrast = 0.125;
// The most a lone pixel blends towards its neighbours.
const float kLoneShare = 0.75;
// Steps along the edge, in pixels: fine near the pixel, coarser away; 12 reach 26.5 pixels each way.
const int kStepCount = 12;
const float kSteps[kStepCount] = float[](1.0, 1.0, 1.0, 1.0, 1.0, 1.5, 2.0, 2.0, 2.0, 2.0, 4.0, 8.0);

// Luma as the eye sees it (about gamma-encoded): edges are found where they show, dark or bright.
float lumaOf(vec3 linear) { return sqrt(max(dot(linear, vec3(0.299, 0.587, 0.114)), 0.0)); }
float lumaAt(ivec2 p) { return lumaOf(texelFetch(picture, clamp(p, ivec2(0), push.extent - 1), 0).rgb); }
float lumaAtUv(vec2 uv) { return lumaOf(textureLod(picture, uv, 0.0).rgb); }

vec3 srgbEncoded(vec3 linear) {
    linear = clamp(linear, 0.0, 1.0);
    return mix(linear * 12.92, 1.055 * pow(linear, vec3(1.0 / 2.4)) - 0.055, greaterThan(linear, vec3(0.0031308)));
}

void store(ivec2 p, vec4 colour) {
    imageStore(filtered, p, vec4(kEncodeSrgb ? srgbEncoded(colour.rgb) : colour.rgb, colour.a));
}

void main() {
    const ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, push.extent))) return;
    const vec4 centre = texelFetch(picture, p, 0);
    const float m = lumaOf(centre.rgb);
    const float n = lumaAt(p + ivec2(0, -1)), s = lumaAt(p + ivec2(0, 1));
    const float w = lumaAt(p + ivec2(-1, 0)), e = lumaAt(p + ivec2(1, 0));
    const float brightest = max(max(max(n, s), max(w, e)), m);
    const float contrast = brightest - min(min(min(n, s), min(w, e)), m);
    if (contrast < max(kLeastContrast, brightest * kRelativeContrast)) {
        store(p, centre);
        return;
    }
    const float nw = lumaAt(p + ivec2(-1, -1)), ne = lumaAt(p + ivec2(1, -1));
    const float sw = lumaAt(p + ivec2(-1, 1)), se = lumaAt(p + ivec2(1, 1));

    // The edge runs horizontally where luma changes more down the columns than along the rows.
    const float downColumns = abs(nw + sw - 2.0 * w) + 2.0 * abs(n + s - 2.0 * m) + abs(ne + se - 2.0 * e);
    const float alongRows = abs(nw + ne - 2.0 * n) + 2.0 * abs(w + e - 2.0 * m) + abs(sw + se - 2.0 * s);
    const bool horizontal = downColumns >= alongRows;
    // The edge lies between the pixel and the neighbour it differs from most, across it.
    const float before = horizontal ? n : w, after = horizontal ? s : e;
    const bool towardsBefore = abs(before - m) >= abs(after - m);
    const float edgeLuma = 0.5 * (m + (towardsBefore ? before : after));
    const float endContrast = 0.25 * max(abs(before - m), abs(after - m));

    const vec2 texel = 1.0 / vec2(push.extent);
    const vec2 uv = (vec2(p) + 0.5) * texel;
    const vec2 across = (horizontal ? vec2(0.0, texel.y) : vec2(texel.x, 0.0)) * (towardsBefore ? -1.0 : 1.0);
    const vec2 along = horizontal ? vec2(texel.x, 0.0) : vec2(0.0, texel.y);
    // Follow the edge both ways, sampling on it (half way across, the two sides averaged), until its
    // luma leaves the edge's: there it ends.
    const vec2 onEdge = uv + 0.5 * across;
    vec2 back = onEdge, ahead = onEdge;
    float backEnd = 0.0, aheadEnd = 0.0;  // the luma at each end, less the edge's
    bool backFound = false, aheadFound = false;
    for (int i = 0; i < kStepCount && !(backFound && aheadFound); ++i) {
        if (!backFound) {
            back -= kSteps[i] * along;
            backEnd = lumaAtUv(back) - edgeLuma;
            backFound = abs(backEnd) >= endContrast;
        }
        if (!aheadFound) {
            ahead += kSteps[i] * along;
            aheadEnd = lumaAtUv(ahead) - edgeLuma;
            aheadFound = abs(aheadEnd) >= endContrast;
        }
    }
    const float toBack = horizontal ? uv.x - back.x : uv.y - back.y;
    const float toAhead = horizontal ? ahead.x - uv.x : ahead.y - uv.y;
    const bool backNearer = toBack < toAhead;
    // The staircase: at the nearer end the edge steps over to this pixel's side only when this pixel is
    // on the other side of the edge's luma than that end; then the nearer the end, the larger the share.
    const bool stepsHere = ((backNearer ? backEnd : aheadEnd) < 0.0) != (m < edgeLuma);
    const float edgeShare = stepsHere ? 0.5 - min(toBack, toAhead) / (toBack + toAhead) : 0.0;

    // A lone pixel: how far it is from its neighbourhood's average, against the neighbourhood's contrast.
    const float neighbourhood = (2.0 * (n + s + w + e) + (nw + ne + sw + se)) / 12.0;
    const float lone = smoothstep(0.0, 1.0, clamp(abs(neighbourhood - m) / contrast, 0.0, 1.0));
    const float share = max(edgeShare, lone * lone * kLoneShare);
    store(p, vec4(textureLod(picture, uv + share * across, 0.0).rgb, centre.a));
}
