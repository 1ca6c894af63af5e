#version 330 compatibility
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;
in vec2 vST[];
out vec2 gST;

void main()
{
    for (int i = 0; i < 3; ++i) {
        gST = vST[i];
        gl_Position = gl_in[i].gl_Position;
        EmitVertex();
    }
}
