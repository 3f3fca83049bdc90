#version 460
// A triangle covering the viewport (no vertex buffer): draw 3 vertices.
layout(location = 0) out vec2 outUv;

void main() {
    vec2 uv = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2);
    outUv = uv;
    gl_Position = vec4(uv * 2.0f - 1.0f, 0.0f, 1.0f);
}
