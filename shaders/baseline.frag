#version 450
// Benchmark baseline: ambient + directional diffuse + specular per fragment, as the toolkit's
// Phong path computes for one ambient and one directional light.
layout(push_constant) uniform Push {
    mat4 worldToClip;
    vec4 colour;
} push;

layout(location = 0) in vec3 vNormal;
layout(location = 0) out vec4 outColour;

void main() {
    vec3 n = normalize(vNormal);
    vec3 l = normalize(vec3(1.0, 1.0, 2.0));
    float nl = max(dot(n, l), 0.0);
    float rv = max(dot(reflect(-l, n), vec3(0.0, 0.0, 1.0)), 0.0);
    vec3 c = 0.2 * push.colour.rgb + 0.7 * push.colour.rgb * nl + vec3(0.5 * pow(rv, 20.0));
    outColour = vec4(c, 1.0);
}
