#version 450
// The one vertex shader of the PHIGS renderer: modelling (meshes only; other primitives arrive
// in world coordinates), view orientation and mapping, workstation transform, screen offsets for
// markers (pixels) and annotation text (NPC), and Gouraud lighting (of PATTERN interiors: the
// gain and specular term the fragment shader applies to the pattern cell).
#extension GL_GOOGLE_include_directive : require
#include "scene.glsl"
#include "colour_models.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec3 inColour;
layout(location = 3) in vec2 inOffset;
layout(location = 4) in float inPattern;

layout(location = 0) out vec3 vWorld;
layout(location = 1) out vec3 vNormal;
layout(location = 2) out vec3 vColour;
layout(location = 3) out float vPattern;
// NPC depth after the divide is affine across the screen: interpolated without perspective.
layout(location = 4) noperspective out float vNpcZ;
layout(location = 5) out vec3 vLitFront;
layout(location = 6) out vec3 vLitBack;
layout(location = 7) out vec3 vSpecularFront;
layout(location = 8) out vec3 vSpecularBack;

// Four steps of a 32-bit float depth just below 1.
const float kLineDepthLead = 1.0 / 4194304.0;

void main() {
    // Outputs are written, never read back: the renderer removes the stores the fragment shader
    // does not need (phigs/src/vk/ShaderSpecialisation.cpp), which a read-back would then miss.
    vec4 world = MODEL_IDENTITY ? vec4(inPosition, 1.0) : DRAW.model * vec4(inPosition, 1.0);
    vec3 worldPoint = MODEL_IDENTITY ? inPosition : world.xyz / world.w;
    vec3 normal = MODEL_IDENTITY ? inNormal : mat3(DRAW.normalMatrix) * inNormal;
    normal = dot(normal, normal) > 0.0 ? normalize(normal) : vec3(0.0);
    vec3 colour = USE_VERTEX_COLOURS ? inColour : push.colour.rgb;
    vWorld = worldPoint;
    vNormal = normal;
    // Interpolated in the rendering colour model (fragment shader: back to RGB).
    vColour = toRenderingModel(colour);
    vPattern = inPattern;
    vec4 npc = runView.worldToNpc * world;
    vNpcZ = npc.z / npc.w;
    vec4 clip = runView.worldToClip * world;
    if (SCREEN_OFFSETS != 0) {
        float offsetScale = SCREEN_OFFSETS == 2 ? frame.pixelScale.z : 1.0;
        clip.xy += inOffset * offsetScale * frame.pixelScale.xy * clip.w;
    }
    // A marker is clipped by its position and annotation text by its reference point (ISO 9592):
    // one outside the view's clip rectangle draws nothing, though its glyph would reach inside
    // (the scissor alone would keep that part). Depth and model clipping already discard every
    // fragment alike: vNpcZ and vWorld are the position's.
    if (SCREEN_OFFSETS != 0) {
        vec2 at = npc.xy / npc.w;
        if (!(npc.w > 0.0) || any(lessThan(at, runView.clipXY.xy)) || any(greaterThan(at, runView.clipXY.zw)))
            clip = vec4(4.0, 4.0, 4.0, 1.0);
    }
    // Both ends of a facet edge decide alike (the same plane against the same viewer): a line
    // whose triangle shows the other side goes wholly outside the clip volume.
    if (SIDED_EDGES != 0) {
        bool front = dot(vec4(inNormal, inPattern), push.backReflectance) >= 0.0;
        if (front != (SIDED_EDGES > 0)) clip = vec4(4.0, 4.0, 4.0, 1.0);
    }
    // Lines lead surfaces at the same depth by a few steps of the depth buffer (surfaces are
    // pushed back by the pipeline's depth bias too, but at the back plane, where 2D primitives
    // lie, that bias clamps away): a line on a coplanar fill stays visible under HLHSR, as the
    // vector hardcopy draws it. Not past the front plane, which would clip it; a vertex beyond
    // it (a line the front plane cuts) keeps its depth.
    if (!TRIANGLES && clip.z >= 0.0) clip.z = max(clip.z - kLineDepthLead * clip.w, 0.0);
    gl_Position = clip;
    vLitFront = vec3(0.0);
    vLitBack = vec3(0.0);
    vSpecularFront = vec3(0.0);
    vSpecularBack = vec3(0.0);
    if (VERTEX_LIGHTING && PATTERNED) {
        // The pattern cell is the colour lit, known only per fragment. The reflectance equations
        // are affine in the base colour, lit(c) = c * gain + specular: the vertices carry the gain
        // and the specular term, and the fragment shader applies them to its cell.
        vec3 eye = towardViewer(worldPoint);
        vSpecularFront = lit(false, vec3(0.0), worldPoint, normal, eye);
        vSpecularBack = lit(DISTINGUISH_BACK, vec3(0.0), worldPoint, -normal, eye);
        vLitFront = lit(false, vec3(1.0), worldPoint, normal, eye) - vSpecularFront;
        vLitBack = lit(DISTINGUISH_BACK, vec3(1.0), worldPoint, -normal, eye) - vSpecularBack;
    } else if (VERTEX_LIGHTING) {
        vec3 eye = towardViewer(worldPoint);
        // Each vertex's colour is a colour: clamped before it is interpolated.
        vLitFront = toRenderingModel(clamp(lit(false, colour, worldPoint, normal, eye), 0.0, 1.0));
        vLitBack = toRenderingModel(clamp(
            lit(DISTINGUISH_BACK, DISTINGUISH_BACK ? push.backColour.rgb : colour, worldPoint, -normal, eye), 0.0,
            1.0));
    }
}
