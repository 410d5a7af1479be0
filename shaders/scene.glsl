// Shared by prim.vert and prim.frag: the frame and draw data the renderer uploads, in the layout
// of phigs/src/vk/GpuLayout.h, and the PHIGS PLUS reflectance equations.

// The draw record's flags the shaders test (the others of GpuLayout.h only decide the pipeline).
const int FLAG_HATCH = 16;
const int FLAG_PATTERN = 32;
const int FLAG_PATTERN_IN_MODEL_UNITS = 256;

const int SHADE_FLAT = 1;
const int SHADE_GOURAUD = 2;
const int SHADE_PHONG = 4;

const int MAX_LIGHTS = 64;
const int MAX_LIGHT_SETS = 16;
const int MAX_CUES = 16;
const int MAX_CLIP_PLANES = 64;

struct View {
    mat4 worldToClip;
    mat4 worldToNpc;
    vec4 eye;   // the viewer, world coordinates: a point (w 1, perspective) or unit direction (w 0)
    vec4 clip;  // NPC z min, z max, clip back (1/0), clip front (1/0)
    vec4 clipXY;  // NPC x min, y min, x max, y max: the workstation window within the view's clip limits
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
    ivec4 indices;         // view, light set, depth cue, flags
    ivec4 style;           // role, hatch index, line type, shading
    vec4 misc;             // line width, first model clip plane, model clip plane count, pattern record
};

layout(std430, set = 0, binding = 1) readonly buffer Draws {
    DrawParams draws[];
};

// PATTERN interiors: per patterned draw a record at misc.w (world to cell column as
// dot(xyz, world) + w, the same to cell row, then first cell, columns, rows), and the cells of
// the patterns this frame draws, row by row (rgb, unused).
layout(std430, set = 0, binding = 2) readonly buffer Patterns {
    vec4 patternData[];
};

// The draw's run (Renderer.cpp fills one per view, then one per view, light set, reflectance and
// colour of the frame that PREMULTIPLIED_LIGHTS pipelines draw): the view, then per light the
// ambient or diffuse coefficient times its colour (and times the draw's colour when that is
// uniform: no vertex colours, no pattern), the specular coefficient times its colour and the
// specular colour (w: the exponent), and its position, direction and attenuation as in Light.
// The run is bound at a dynamic offset, so the shaders read it at constant offsets: lavapipe
// loads an array element at an index from push constants lane by lane, and redoes uniform
// arithmetic for every block of vertices or fragments.
struct LitLight {
    vec4 diffuse;
    vec4 specular;
    vec4 position;
    vec4 direction;
    vec4 attenuation;
};

layout(std140, set = 0, binding = 3) uniform LitRun {
    View runView;
    LitLight litLights[4];
};

// The draw record's index, the frame-block indices the shaders look up with, and the values the
// fragment shader reads per draw. Measured on lavapipe: reading these from the draw records
// cost the benchmark frame about 15%, and indices read from a buffer make every later load a
// per-fragment gather; push constants are uniform by rule.
layout(push_constant) uniform Push {
    uint drawIndex;
    int firstLight;  // the light set's first light in frame.lights
    int depthCue;
    int unused;      // keeps the colours 16-byte aligned
    vec4 colour;
    vec4 backColour;
    vec4 reflectance;      // ambient, diffuse, specular, exponent
    vec4 specularColour;   // rgb, reflectance model
    vec4 backReflectance;
    vec4 backSpecularColour;
} push;

// The current draw's record, read field by field (copying whole records is slow on lavapipe).
#define DRAW draws[push.drawIndex]

// Specialisation constants, the same in both stages: phigs/src/vk/Renderer.cpp derives them from
// the pipeline key, so every draw of a pipeline shares them, and freezes them into the SPIR-V
// before the driver sees it. Each optional feature is switched here rather than by a flag in the
// draw record: lavapipe pays for a branch on a flag per vertex or fragment, taken or not.

// False for pipelines whose draws never discard (no hatch, pattern, z or model clip): the compiler then
// drops every discard and the depth test can run before shading.
layout(constant_id = 0) const bool MAY_DISCARD = true;
// The shading done per fragment: 0 none (unlit or Gouraud), SHADE_FLAT or SHADE_PHONG.
layout(constant_id = 1) const int FRAGMENT_SHADING = 0;
// The light set's shape: -1 (read the set at run time) or count | type1 << 3 | type2 << 6 | ...
// (up to 4 lights); REFLECTANCE_MODEL is 0 (read it from the draw record) or the model. Fixed
// shapes let the compiler unroll the loop.
layout(constant_id = 2) const int LIGHT_SIGNATURE = -1;
layout(constant_id = 3) const int REFLECTANCE_MODEL = 0;
// The draws are depth cued / have vertex colours / need the world position per fragment (local
// lights, flat normals, model clipping).
layout(constant_id = 4) const bool USE_DEPTH_CUE = true;
layout(constant_id = 5) const bool USE_VERTEX_COLOURS = true;
layout(constant_id = 6) const bool USE_WORLD_POSITION = true;
// Gouraud: the vertex shader lights the vertices.
layout(constant_id = 7) const bool VERTEX_LIGHTING = false;
// The draws are highlighted / give back faces their own colour and reflectance / are triangles.
layout(constant_id = 8) const bool HIGHLIGHTED = false;
layout(constant_id = 9) const bool DISTINGUISH_BACK = false;
layout(constant_id = 10) const bool TRIANGLES = true;
// Screen offsets of the vertices: 0 none, 1 in pixels (markers), 2 in NPC (annotation text).
layout(constant_id = 11) const int SCREEN_OFFSETS = 1;
// The draws are PATTERN interiors: the base colour is the pattern cell under the fragment.
layout(constant_id = 12) const bool PATTERNED = false;
// The light set's lights and the eye come premultiplied from the lit run (binding 3): a fixed
// LIGHT_SIGNATURE and REFLECTANCE_MODEL, and one reflectance for both sides.
layout(constant_id = 13) const bool PREMULTIPLIED_LIGHTS = false;
// The draws' modelling transformation is the identity: the vertex shader reads no matrix from
// the draw record (lavapipe gathers such reads lane by lane).
layout(constant_id = 14) const bool MODEL_IDENTITY = false;
// The draws are a mesh's facet edges of one HOLLOW side (1 front, -1 back, 0 none): each line
// carries its triangle's plane (normal, offset in the pattern input) and is kept while that
// triangle shows the side: the front while dot(plane, push.backReflectance) >= 0 (edge on counts
// as front), the back while it is < 0 (the viewer in modelling coordinates; lines read no
// reflectance).
layout(constant_id = 16) const int SIDED_EDGES = 0;
// Flat shading lights with the interpolated normal: each facet's given normal, alike at its
// vertices (else the plane of the triangle, from the world position's derivatives).
layout(constant_id = 17) const bool FLAT_FACET_NORMALS = false;

// The unit direction from `world` toward the view's viewer (V of the reflectance equations).
vec3 towardViewer(vec3 world) {
    return runView.eye.w > 0.5 ? normalize(runView.eye.xyz - world) : runView.eye.xyz;
}

// A positional (type 3) or spot (type 4) light at `position` seen from `world`: the unit
// direction to it in l, and its attenuation (the caller reads the light's fields only for these
// types, so directional lights load nothing more).
float positionalLight(int type, vec3 position, vec4 coefficients, vec4 direction, vec3 world, out vec3 l) {
    vec3 toLight = position - world;
    float distance = length(toLight);
    l = toLight / max(distance, 1e-9);
    float attenuation = 1.0 / max(coefficients.x + coefficients.y * distance, 1e-9);
    if (type == 4) {
        float c = dot(-l, direction.xyz);
        attenuation *= c >= coefficients.z ? pow(max(c, 0.0), direction.w) : 0.0;
    }
    return attenuation;
}

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
        attenuation = positionalLight(type, frame.lights[i].position.xyz, frame.lights[i].attenuation, direction,
                                      world, l);
    }
    // No branch on the facing: light from behind adds nothing, diffuse or specular.
    float nl = dot(n, l);
    float facing = nl > 0.0 ? attenuation : 0.0;
    vec3 sum = k.y * colour.rgb * base * (max(nl, 0.0) * attenuation);
    if (model >= 4) {
        vec3 r = reflect(-l, n);
        float rv = max(dot(r, eye), 0.0);
        sum += k.z * colour.rgb * sc.rgb * (pow(rv, max(k.w, 0.0)) * facing);
    }
    return sum;
}

// Light i of litLights, of type `type`, added to the terms the base colour multiplies (diffuse)
// and the specular ones; the same equations as oneLight.
void premultipliedLight(int type, int i, vec3 world, vec3 n, vec3 eye, inout vec3 diffuse, inout vec3 specular) {
    if (type == 1) {
        diffuse += litLights[i].diffuse.rgb;
        return;
    }
    if (REFLECTANCE_MODEL < 3) return;
    vec3 l;
    float attenuation = 1.0;
    vec4 direction = litLights[i].direction;
    if (type == 2) {
        l = -direction.xyz;
    } else {
        attenuation = positionalLight(type, litLights[i].position.xyz, litLights[i].attenuation, direction, world,
                                      l);
    }
    float nl = dot(n, l);
    diffuse += litLights[i].diffuse.rgb * (max(nl, 0.0) * attenuation);
    if (REFLECTANCE_MODEL >= 4) {
        vec4 s = litLights[i].specular;
        float rv = max(dot(reflect(-l, n), eye), 0.0);
        specular += s.rgb * (pow(rv, s.w) * (nl > 0.0 ? attenuation : 0.0));
    }
}

// lit() for PREMULTIPLIED_LIGHTS: the light set's lights from the lit run, unrolled as in lit().
vec3 litPremultiplied(vec3 base, vec3 world, vec3 n) {
    const int first = 0;
    vec3 eye = towardViewer(world);
    int count = LIGHT_SIGNATURE & 7;
    vec3 diffuse = vec3(0.0), specular = vec3(0.0);
    if (count > 0) premultipliedLight((LIGHT_SIGNATURE >> 3) & 7, first, world, n, eye, diffuse, specular);
    if (count > 1) premultipliedLight((LIGHT_SIGNATURE >> 6) & 7, first + 1, world, n, eye, diffuse, specular);
    if (count > 2) premultipliedLight((LIGHT_SIGNATURE >> 9) & 7, first + 2, world, n, eye, diffuse, specular);
    if (count > 3) premultipliedLight((LIGHT_SIGNATURE >> 12) & 7, first + 3, world, n, eye, diffuse, specular);
    // The colour is in the terms unless it varies (Renderer.cpp folds it under the same test).
    return USE_VERTEX_COLOURS || PATTERNED ? base * diffuse + specular : diffuse + specular;
}

// PHIGS PLUS reflectance: model 1 none, 2 ambient, 3 ambient + diffuse, 4 + specular.
vec3 lit(bool back, vec3 base, vec3 world, vec3 n, vec3 eye) {
    if (PREMULTIPLIED_LIGHTS) return litPremultiplied(base, world, n);
    vec4 k = back ? push.backReflectance : push.reflectance;
    vec4 sc = back ? push.backSpecularColour : push.specularColour;
    int model = REFLECTANCE_MODEL != 0 ? REFLECTANCE_MODEL : int(sc.w + 0.5);
    int lightSet = DRAW.indices.y;
    // A fixed model means a lit pipeline, whose draws always name a light set.
    if (model <= 1 || (REFLECTANCE_MODEL == 0 && lightSet < 0)) return base;
    int first = push.firstLight;
    vec3 sum = vec3(0.0);
    if (LIGHT_SIGNATURE >= 0) {
        // Unrolled by hand: with the shape frozen each light's type is a constant, and the code
        // of the other types goes (SPIRV-Tools does not unroll the loop form).
        int count = LIGHT_SIGNATURE & 7;
        if (count > 0) sum += oneLight((LIGHT_SIGNATURE >> 3) & 7, first, model, k, sc, base, world, n, eye);
        if (count > 1) sum += oneLight((LIGHT_SIGNATURE >> 6) & 7, first + 1, model, k, sc, base, world, n, eye);
        if (count > 2) sum += oneLight((LIGHT_SIGNATURE >> 9) & 7, first + 2, model, k, sc, base, world, n, eye);
        if (count > 3) sum += oneLight((LIGHT_SIGNATURE >> 12) & 7, first + 3, model, k, sc, base, world, n, eye);
        return sum;
    }
    int count = frame.lightSets[lightSet].y;
    for (int i = first; i < first + count; ++i)
        sum += oneLight(int(frame.lights[i].colour.w + 0.5), i, model, k, sc, base, world, n, eye);
    return sum;
}
