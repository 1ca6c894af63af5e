#version 330 compatibility
// Written for NVIDIA: gl_PositionIn[] is not in GLSL 3.30; Glimmer translates it.
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;

void main() {
    for (int i = 0; i < 3; ++i) {
        gl_Position = gl_PositionIn[i];
        EmitVertex();
    }
    EndPrimitive();
}
