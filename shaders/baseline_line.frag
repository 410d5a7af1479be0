#version 450
// Benchmark baseline: iso-lines in one flat colour.
layout(push_constant) uniform Push {
    mat4 worldToClip;
    vec4 colour;
    vec4 material;
    vec4 toLight;
} push;

layout(location = 0) in vec3 vNormal;
layout(location = 0) out vec4 outColour;

void main() {
    outColour = vec4(push.colour.rgb, 1.0);
}
