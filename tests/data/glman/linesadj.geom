#version 330 compatibility
// Lines with adjacency in: draws the middle segment v1-v2 and short ticks
// towards the neighbours v0 and v3, in the draw's colour.
layout(lines_adjacency) in;
layout(line_strip, max_vertices = 4) out;
out vec3 gColor;
void main() {
    gColor = gl_in[1].gl_FrontColor.rgb;
    gl_Position = mix(gl_in[1].gl_Position, gl_in[0].gl_Position, 0.3); EmitVertex();
    gl_Position = gl_in[1].gl_Position; EmitVertex();
    gl_Position = gl_in[2].gl_Position; EmitVertex();
    gl_Position = mix(gl_in[2].gl_Position, gl_in[3].gl_Position, 0.3); EmitVertex();
    EndPrimitive();
}
