#version 450
// The one fragment shader (specialised per pipeline, see scene.glsl): NPC z and model clipping, hatch and line patterns, pattern interiors, flat / Gouraud / Phong
// lighting with distinct back faces, depth cueing and highlighting; interpolated colours and depth
// cueing in the rendering colour model (colour_models.glsl).
#extension GL_GOOGLE_include_directive : require
#include "scene.glsl"
#include "colour_models.glsl"

layout(location = 0) in vec3 vWorld;
layout(location = 1) in vec3 vNormal;
layout(location = 2) in vec3 vColour;
layout(location = 3) in float vPattern;
layout(location = 4) noperspective in float vNpcZ;
layout(location = 5) in vec3 vLitFront;
layout(location = 6) in vec3 vLitBack;
layout(location = 7) in vec3 vSpecularFront;
layout(location = 8) in vec3 vSpecularBack;

layout(location = 0) out vec4 outColour;

bool hatchOn(int index, vec2 p) {
    const float spacing = 8.0;
    bool horizontal = mod(p.y, spacing) < 1.0;
    bool vertical = mod(p.x, spacing) < 1.0;
    bool rising = mod(p.x + p.y, spacing * 1.41421) < 1.41421;
    bool falling = mod(p.x - p.y, spacing * 1.41421) < 1.41421;
    switch (index) {
        case 1: return horizontal;
        case 2: return vertical;
        case 3: return rising;
        case 4: return falling;
        case 5: return horizontal || vertical;
        default: return rising || falling;
    }
}

bool patternOn(int type, float width, float distance) {
    vec4 lengths;
    if (type == 2) lengths = vec4(12.0, 6.0, 12.0, 6.0);
    else if (type == 3) lengths = vec4(2.0, 4.0, 2.0, 4.0);
    else if (type == 4) lengths = vec4(12.0, 5.0, 2.0, 5.0);
    else return true;
    float period = lengths.x + lengths.y + lengths.z + lengths.w;
    float d = mod(distance / max(1.0, width), period);
    if (d < lengths.x) return true;
    d -= lengths.x;
    if (d < lengths.y) return false;
    d -= lengths.y;
    return d < lengths.z;
}

// The colour of the pattern cell at a world point: the cell coordinates are affine in the world
// position on the primitive's plane (phigs/render/PatternMapping.h).
vec3 patternColour(vec3 world) {
    int record = int(DRAW.misc.w);
    vec4 u = patternData[record], v = patternData[record + 1];
    ivec3 p = ivec3(patternData[record + 2].xyz);  // first cell, columns, rows
    vec2 cell = floor(vec2(dot(u.xyz, world) + u.w, dot(v.xyz, world) + v.w));
    int column = clamp(int(cell.x - float(p.y) * floor(cell.x / float(p.y))), 0, p.y - 1);
    int row = clamp(int(cell.y - float(p.z) * floor(cell.y / float(p.z))), 0, p.z - 1);
    return patternData[p.x + row * p.y + column].rgb;
}

void main() {
    if (MAY_DISCARD) {
        int flags = DRAW.indices.w;
        // A pattern length in modelling units (mesh iso-lines) becomes pixels by its rate along
        // the line on screen; derivatives are taken before anything may discard.
        vec2 patternRate = vec2(dFdx(vPattern), dFdy(vPattern));
        float patternPixels = (flags & FLAG_PATTERN_IN_MODEL_UNITS) != 0
                                  ? vPattern / max(length(patternRate), 1e-9)
                                  : vPattern;
        vec4 clip = runView.clip;
        if ((clip.z > 0.0 && vNpcZ < clip.x) || (clip.w > 0.0 && vNpcZ > clip.y)) discard;
        if ((flags & FLAG_HATCH) != 0 && !hatchOn(DRAW.style.y, gl_FragCoord.xy)) discard;
        if ((flags & FLAG_PATTERN) != 0 && !patternOn(DRAW.style.z, DRAW.misc.x, patternPixels)) discard;
        // Model clipping volume: the intersection of half spaces in world coordinates.
        int firstPlane = int(DRAW.misc.y);
        int planeEnd = firstPlane + int(DRAW.misc.z);
        for (int i = firstPlane; i < planeEnd; ++i)
            if (dot(frame.clipPlanes[i].xyz, vWorld) + frame.clipPlanes[i].w < 0.0) discard;
    }

    bool back = TRIANGLES && !gl_FrontFacing;
    bool useBack = DISTINGUISH_BACK && back;
    vec3 base = PATTERNED ? patternColour(vWorld) : USE_VERTEX_COLOURS ? fromRenderingModel(vColour) : push.colour.rgb;
    // The side's own colour: the back colour, unless the back's style is PATTERN (a draw fills
    // one style; phigs/src/vk/Renderer.cpp draws differing sides as two draws, each culling the other).
    vec3 side = useBack && !PATTERNED ? push.backColour.rgb : base;
    vec3 colour;
    if (VERTEX_LIGHTING && PATTERNED) {
        // Gouraud on a pattern: the cell lit by the interpolated gain and specular term.
        colour = back ? base * vLitBack + vSpecularBack : base * vLitFront + vSpecularFront;
    } else if (VERTEX_LIGHTING) {
        colour = fromRenderingModel(back ? vLitBack : vLitFront);
    } else if (FRAGMENT_SHADING != 0) {
        vec3 n;
        if (FRAGMENT_SHADING == SHADE_PHONG || FLAT_FACET_NORMALS) {
            n = normalize(vNormal);
        } else {
            // Flat: the facet normal from the screen-space derivatives of the world position,
            // turned to the side the triangle's winding calls front.
            n = normalize(cross(dFdx(vWorld), dFdy(vWorld)));
            if (dot(vNormal, vNormal) > 0.0) {
                if (dot(n, vNormal) < 0.0) n = -n;
            } else {
                // No normals given: the front side is the one the winding shows the viewer.
                if (dot(n, towardViewer(vWorld)) < 0.0) n = -n;
                if (!gl_FrontFacing) n = -n;
            }
        }
        if (back) n = -n;
        vec3 world = USE_WORLD_POSITION ? vWorld : vec3(0.0);
        colour = lit(useBack, side, world, n, towardViewer(world));
    } else {
        colour = side;
    }
    // A colour, lit past 1 or not, is clamped before depth cueing blends it (ISO 9592-4).
    colour = clamp(colour, 0.0, 1.0);
    if (USE_DEPTH_CUE) {
        DepthCue cue = frame.cues[push.depthCue];
        float t = clamp((vNpcZ - cue.planes.y) / max(cue.planes.x - cue.planes.y, 1e-9), 0.0, 1.0);
        float s = mix(cue.planes.w, cue.planes.z, t);
        // Mixed in the rendering colour model.
        colour = fromRenderingModel(s * toRenderingModel(colour) + (1.0 - s) * toRenderingModel(cue.colour.rgb));
    }
    if (HIGHLIGHTED) colour = mix(colour, frame.highlight.rgb, frame.highlight.w);
    // Opacity (1 - PHIGS PLUS transparency) rides in the colours' alpha; only transparent
    // pipelines blend with it.
    outColour = vec4(clamp(colour, 0.0, 1.0), useBack ? push.backColour.a : push.colour.a);
}
