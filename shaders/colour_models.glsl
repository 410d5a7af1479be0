// The PHIGS PLUS rendering colour model: the space the renderer interpolates vertex colours and
// lit vertex colours in and mixes depth cueing in. The conversions mirror
// phigs/src/core/ColourModels.cpp (RGB; CIE u', v', Y over the sRGB primaries, white D65; HSV and
// HLS with hue a fraction of a turn); colours other than RGB are clamped to [0, 1] first. The
// components are interpolated as they are, hue included: from hue 0.9 to 0.1 the way passes 0.5
// (the model's coordinates mix linearly; there is no shorter way round the hue circle).

// 1 RGB, 2 CIE, 3 HSV, 4 HLS (the C binding's PRCM_RGB .. PRCM_HLS).
layout(constant_id = 15) const int RENDERING_COLOUR_MODEL = 1;

// Linear RGB to CIE XYZ (IEC 61966-2-1) and back; column-major.
const mat3 RGB_TO_XYZ = mat3(0.4124, 0.2126, 0.0193, 0.3576, 0.7152, 0.1192, 0.1805, 0.0722, 0.9505);
const mat3 XYZ_TO_RGB = mat3(3.240625477, -0.968930715, 0.055710120, -1.537207972, 1.875756061,
                             -0.204021051, -0.498628599, 0.041517524, 1.056995942);
const vec2 WHITE_UV = vec2(0.1978405100, 0.4683231430);

float hueOf(vec3 c, float hi, float lo) {
    float d = hi - lo;
    float h;
    if (hi == c.r) h = (c.g - c.b) / d;
    else if (hi == c.g) h = 2.0 + (c.b - c.r) / d;
    else h = 4.0 + (c.r - c.g) / d;
    h /= 6.0;
    if (h < 0.0) h += 1.0;
    return h >= 1.0 ? 0.0 : h;
}

// The fully saturated colour of hue h: each component 1 within a sixth of a turn of its centre.
vec3 pureHue(float h) {
    vec3 d = abs(vec3(6.0 * fract(h)) - vec3(0.0, 2.0, 4.0));
    return clamp(2.0 - min(d, 6.0 - d), 0.0, 1.0);
}

// An RGB colour's components in the rendering colour model.
vec3 toRenderingModel(vec3 rgb) {
    if (RENDERING_COLOUR_MODEL == 1) return rgb;
    vec3 c = clamp(rgb, 0.0, 1.0);
    if (RENDERING_COLOUR_MODEL == 2) {
        vec3 xyz = RGB_TO_XYZ * c;
        float d = xyz.x + 15.0 * xyz.y + 3.0 * xyz.z;
        return d > 0.0 ? vec3(4.0 * xyz.x / d, 9.0 * xyz.y / d, xyz.y) : vec3(WHITE_UV, 0.0);
    }
    float hi = max(c.r, max(c.g, c.b)), lo = min(c.r, min(c.g, c.b));
    if (RENDERING_COLOUR_MODEL == 3) return hi > lo ? vec3(hueOf(c, hi, lo), (hi - lo) / hi, hi) : vec3(0.0, 0.0, hi);
    float l = 0.5 * (hi + lo);
    return hi > lo ? vec3(hueOf(c, hi, lo), l, (hi - lo) / (1.0 - abs(hi + lo - 1.0))) : vec3(0.0, l, 0.0);
}

// The RGB colour of components in the rendering colour model.
vec3 fromRenderingModel(vec3 c) {
    if (RENDERING_COLOUR_MODEL == 1) return c;
    if (RENDERING_COLOUR_MODEL == 2) {
        if (!(c.y > 0.0)) return vec3(0.0);
        return XYZ_TO_RGB * vec3(c.z * 9.0 * c.x / (4.0 * c.y), c.z, c.z * (12.0 - 3.0 * c.x - 20.0 * c.y) / (4.0 * c.y));
    }
    if (RENDERING_COLOUR_MODEL == 3) return c.z * (vec3(1.0) - c.y * (vec3(1.0) - pureHue(c.x)));
    float chroma = (1.0 - abs(2.0 * c.y - 1.0)) * c.z;
    return vec3(c.y - 0.5 * chroma) + chroma * pureHue(c.x);
}
