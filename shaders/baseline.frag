#version 450
// Benchmark baseline: ambient + directional diffuse + specular per fragment, the toolkit's Phong
// equation for one ambient and one directional light, its parameters in push constants.
layout(push_constant) uniform Push {
    mat4 worldToClip;
    vec4 colour;
    vec4 material;   // ambient, diffuse, specular, exponent
    vec4 toLight;    // unit vector toward the directional light
} push;

layout(location = 0) in vec3 vNormal;
layout(location = 0) out vec4 outColour;

void main() {
    vec3 n = normalize(vNormal);
    vec3 l = push.toLight.xyz;
    float nl = max(dot(n, l), 0.0);
    float rv = max(dot(reflect(-l, n), vec3(0.0, 0.0, 1.0)), 0.0);
    vec3 c = push.material.x * push.colour.rgb + push.material.y * push.colour.rgb * nl +
             vec3(push.material.z * pow(rv, push.material.w));
    outColour = vec4(c, 1.0);
}
