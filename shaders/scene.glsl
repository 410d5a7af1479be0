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

struct View {
    mat4 worldToClip;
    mat4 worldToNpc;
    vec4 eye;   // unit direction toward the viewer, world coordinates
    vec4 clip;  // NPC z min, z max, clip back (1/0), clip front (1/0)
};

struct Light {
    vec4 colour;     // rgb, w = type (1 ambient, 2 directional, 3 positional, 4 spot)
    vec4 position;   // world
    vec4 direction;  // world, w = concentration
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
    vec4 misc;             // line width
};

layout(std430, set = 0, binding = 1) readonly buffer Draws {
    DrawParams draws[];
};

layout(push_constant) uniform Push {
    uint drawIndex;
} push;

// PHIGS PLUS reflectance: model 1 none, 2 ambient, 3 ambient + diffuse, 4 + specular.
vec3 lit(DrawParams d, bool back, vec3 base, vec3 world, vec3 n, vec3 eye) {
    vec4 k = back ? d.backReflectance : d.reflectance;
    vec4 sc = back ? d.backSpecularColour : d.specularColour;
    int model = int(sc.w + 0.5);
    if (model <= 1 || d.indices.y < 0) return base;
    ivec4 set = frame.lightSets[d.indices.y];
    vec3 sum = vec3(0.0);
    for (int i = 0; i < set.y; ++i) {
        Light light = frame.lights[set.x + i];
        int type = int(light.colour.w + 0.5);
        if (type == 1) {
            sum += k.x * light.colour.rgb * base;
            continue;
        }
        if (model < 3) continue;
        vec3 l;
        float attenuation = 1.0;
        if (type == 2) {
            l = -normalize(light.direction.xyz);
        } else {
            vec3 toLight = light.position.xyz - world;
            float distance = length(toLight);
            l = toLight / max(distance, 1e-9);
            attenuation = 1.0 / max(light.attenuation.x + light.attenuation.y * distance, 1e-9);
            if (type == 4) {
                float c = dot(-l, normalize(light.direction.xyz));
                attenuation *= c >= light.attenuation.z ? pow(max(c, 0.0), light.direction.w) : 0.0;
            }
        }
        float nl = dot(n, l);
        if (nl <= 0.0) continue;
        sum += k.y * light.colour.rgb * base * nl * attenuation;
        if (model >= 4) {
            vec3 r = reflect(-l, n);
            float rv = max(dot(r, eye), 0.0);
            sum += k.z * light.colour.rgb * sc.rgb * pow(rv, max(k.w, 0.0)) * attenuation;
        }
    }
    return sum;
}
