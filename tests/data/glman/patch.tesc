#version 400 compatibility
layout(vertices = 4) out;
uniform float uLevel;
void main() {
    gl_out[gl_InvocationID].gl_Position = gl_in[gl_InvocationID].gl_Position;
    gl_TessLevelOuter[0] = uLevel;
    gl_TessLevelOuter[1] = uLevel;
    gl_TessLevelOuter[2] = uLevel;
    gl_TessLevelOuter[3] = uLevel;
    gl_TessLevelInner[0] = uLevel;
    gl_TessLevelInner[1] = uLevel;
}
