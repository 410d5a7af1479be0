#version 450
// The one vertex shader of the PHIGS renderer: modelling (meshes only; other primitives arrive
// in world coordinates), view orientation and mapping, workstation transform, screen offsets for
// markers (pixels) and annotation text (NPC), and Gouraud lighting.
#extension GL_GOOGLE_include_directive : require
#include "scene.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec3 inColour;
layout(location = 3) in vec2 inOffset;
layout(location = 4) in float inPattern;

layout(location = 0) out vec3 vWorld;
layout(location = 1) out vec3 vNormal;
layout(location = 2) out vec3 vColour;
layout(location = 3) out float vPattern;
layout(location = 4) out float vNpcZ;
layout(location = 5) out vec3 vLitFront;
layout(location = 6) out vec3 vLitBack;

void main() {
    int viewIndex = DRAW.indices.x;
    vec4 world = DRAW.model * vec4(inPosition, 1.0);
    vWorld = world.xyz / world.w;
    vec3 normal = mat3(DRAW.normalMatrix) * inNormal;
    vNormal = dot(normal, normal) > 0.0 ? normalize(normal) : vec3(0.0);
    vColour = (DRAW.indices.w & FLAG_VERTEX_COLOURS) != 0 ? inColour : DRAW.colour.rgb;
    vPattern = inPattern;
    vec4 npc = frame.views[viewIndex].worldToNpc * world;
    vNpcZ = npc.z / npc.w;
    gl_Position = frame.views[viewIndex].worldToClip * world;
    if ((DRAW.indices.w & FLAG_OFFSET_NPC) != 0)
        gl_Position.xy += inOffset * frame.pixelScale.z * frame.pixelScale.xy * gl_Position.w;
    else
        gl_Position.xy += inOffset * frame.pixelScale.xy * gl_Position.w;
    vLitFront = vColour;
    vLitBack = (DRAW.indices.w & FLAG_DISTINGUISH_BACK) != 0 ? DRAW.backColour.rgb : vColour;
    if ((DRAW.indices.w & FLAG_LIT) != 0 && DRAW.style.w == SHADE_GOURAUD) {
        vec3 n = vNormal;
        vLitFront = lit(false, vLitFront, vWorld, n, frame.views[viewIndex].eye.xyz);
        vLitBack = lit((DRAW.indices.w & FLAG_DISTINGUISH_BACK) != 0, vLitBack, vWorld, -n, frame.views[viewIndex].eye.xyz);
    }
}
