#version 450
// Smoke-test triangle: positions and colours come from push constants so the test decides
// exactly where the triangle lands and what colour it has.
layout(push_constant) uniform Triangle {
    vec4 position[3];
    vec4 color;
} triangle;

layout(location = 0) out vec4 vertexColor;

void main() {
    gl_Position = vec4(triangle.position[gl_VertexIndex].xy, 0.0, 1.0);
    vertexColor = triangle.color;
}
