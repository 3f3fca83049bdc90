#version 460
// ibl_cube_borders.vert: a vertex-only program drawn once with rasterizer discard, the environment
// cube bound, between the compute passes that write the cube and those that filter it, on devices
// whose DeviceChoices::cubeBordersNeedADraw (SwiftShader refreshes a cube's face borders only when
// a draw binds it). It reads one texel so that the binding is part of the program; nothing is drawn.

layout(set = 0, binding = 0) uniform samplerCube cube;

void main() {
    gl_Position = vec4(textureLod(cube, vec3(1.0f, 0.0f, 0.0f), 0.0f).r * 0.0f, 0.0f, 0.0f, 1.0f);
    gl_PointSize = 1.0f;
}
