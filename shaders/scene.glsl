// Shared by prim.vert and prim.frag: the frame and draw data the renderer uploads, in the layout
// of phigs/src/vk/GpuLayout.h, and the PHIGS PLUS reflectance equations.

const int FLAG_VERTEX_COLOURS = 1;
const int FLAG_LIT = 2;
const int FLAG_DISTINGUISH_BACK = 4;
const int FLAG_HIGHLIGHT = 8;
const int FLAG_HATCH = 16;
const int FLAG_PATTERN = 32;
const int FLAG_OFFSET_NPC = 64;
const int FLAG_TRIANGLES = 128;

const int SHADE_FLAT = 1;
const int SHADE_GOURAUD = 2;
const int SHADE_PHONG = 4;

const int MAX_VIEWS = 16;
const int MAX_LIGHTS = 64;
const int MAX_LIGHT_SETS = 16;
const int MAX_CUES = 16;
const int MAX_CLIP_PLANES = 64;

struct View {
    mat4 worldToClip;
    mat4 worldToNpc;
    vec4 eye;   // unit direction toward the viewer, world coordinates
    vec4 clip;  // NPC z min, z max, clip back (1/0), clip front (1/0)
};

struct Light {
    vec4 colour;     // rgb, w = type (1 ambient, 2 directional, 3 positional, 4 spot)
    vec4 position;   // world
    vec4 direction;  // world, unit length, w = concentration
    vec4 attenuation;  // constant, linear, cos(spread angle), unused
};

struct DepthCue {
    vec4 planes;  // front plane, back plane, front scale, back scale
    vec4 colour;  // rgb, w = enabled
};

layout(std140, set = 0, binding = 0) uniform Frame {
    View views[MAX_VIEWS];
    Light lights[MAX_LIGHTS];
    ivec4 lightSets[MAX_LIGHT_SETS];  // first light, count
    DepthCue cues[MAX_CUES];
    vec4 pixelScale;  // 2 / width, -2 / height (pixels to clip), pixels per NPC unit, unused
    vec4 highlight;   // rgb, mix factor
    vec4 clipPlanes[MAX_CLIP_PLANES];  // model clipping: keep world x where dot(xyz, x) + w >= 0
} frame;

struct DrawParams {
    mat4 model;
    mat4 normalMatrix;
    vec4 colour;
    vec4 backColour;
    vec4 reflectance;      // ambient, diffuse, specular, exponent
    vec4 specularColour;   // rgb, reflectance model
    vec4 backReflectance;
    vec4 backSpecularColour;
    ivec4 indices;         // view, light set, depth cue, flags
    ivec4 style;           // role, hatch index, line type, shading
    vec4 misc;             // line width, first model clip plane, model clip plane count
};

layout(std430, set = 0, binding = 1) readonly buffer Draws {
    DrawParams draws[];
};

layout(push_constant) uniform Push {
    uint drawIndex;
} push;

// The current draw's record, read field by field (copying whole records is slow on lavapipe).
#define DRAW draws[push.drawIndex]

// Pipelines may fix the light set's shape at compile time: LIGHT_SIGNATURE is -1 (read the set
// at run time) or count | type1 << 3 | type2 << 6 | ... (up to 4 lights); REFLECTANCE_MODEL is 0
// (read it from the draw record) or the model. Fixed shapes let the compiler unroll the loop.
layout(constant_id = 2) const int LIGHT_SIGNATURE = -1;
layout(constant_id = 3) const int REFLECTANCE_MODEL = 0;

vec3 oneLight(int type, int i, int model, vec4 k, vec4 sc, vec3 base, vec3 world, vec3 n, vec3 eye) {
    vec4 colour = frame.lights[i].colour;
    if (type == 1) return k.x * colour.rgb * base;
    if (model < 3) return vec3(0.0);
    vec3 l;
    float attenuation = 1.0;
    vec4 direction = frame.lights[i].direction;
    if (type == 2) {
        l = -direction.xyz;  // normalised when uploaded
    } else {
        vec4 coefficients = frame.lights[i].attenuation;
        vec3 toLight = frame.lights[i].position.xyz - world;
        float distance = length(toLight);
        l = toLight / max(distance, 1e-9);
        attenuation = 1.0 / max(coefficients.x + coefficients.y * distance, 1e-9);
        if (type == 4) {
            float c = dot(-l, direction.xyz);
            attenuation *= c >= coefficients.z ? pow(max(c, 0.0), direction.w) : 0.0;
        }
    }
    float nl = dot(n, l);
    if (nl <= 0.0) return vec3(0.0);
    vec3 sum = k.y * colour.rgb * base * nl * attenuation;
    if (model >= 4) {
        vec3 r = reflect(-l, n);
        float rv = max(dot(r, eye), 0.0);
        sum += k.z * colour.rgb * sc.rgb * pow(rv, max(k.w, 0.0)) * attenuation;
    }
    return sum;
}

// PHIGS PLUS reflectance: model 1 none, 2 ambient, 3 ambient + diffuse, 4 + specular.
vec3 lit(bool back, vec3 base, vec3 world, vec3 n, vec3 eye) {
    vec4 k = back ? DRAW.backReflectance : DRAW.reflectance;
    vec4 sc = back ? DRAW.backSpecularColour : DRAW.specularColour;
    int model = REFLECTANCE_MODEL != 0 ? REFLECTANCE_MODEL : int(sc.w + 0.5);
    int lightSet = DRAW.indices.y;
    if (model <= 1 || lightSet < 0) return base;
    ivec2 set = frame.lightSets[lightSet].xy;
    vec3 sum = vec3(0.0);
    if (LIGHT_SIGNATURE >= 0) {
        int count = LIGHT_SIGNATURE & 7;
        for (int j = 0; j < 4; ++j)
            if (j < count) sum += oneLight((LIGHT_SIGNATURE >> (3 + 3 * j)) & 7, set.x + j, model, k, sc, base, world, n, eye);
        return sum;
    }
    for (int i = set.x; i < set.x + set.y; ++i)
        sum += oneLight(int(frame.lights[i].colour.w + 0.5), i, model, k, sc, base, world, n, eye);
    return sum;
}
