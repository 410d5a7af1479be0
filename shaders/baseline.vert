#version 450
// Benchmark baseline: the least a viewer needs to draw a lit mesh (one matrix, one light).
layout(push_constant) uniform Push {
    mat4 worldToClip;
    vec4 colour;
    vec4 material;
    vec4 toLight;
} push;

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;

layout(location = 0) out vec3 vNormal;

void main() {
    vNormal = inNormal;
    gl_Position = push.worldToClip * vec4(inPosition, 1.0);
}
