#version 400 compatibility
// The tessellated triangles as wireframe.
layout(triangles) in;
layout(line_strip, max_vertices = 4) out;
in vec3 vColor[];
out vec3 gColor;
void main() {
    for (int i = 0; i < 4; ++i) {
        gColor = vColor[i % 3];
        gl_Position = gl_in[i % 3].gl_Position;
        EmitVertex();
    }
    EndPrimitive();
}
