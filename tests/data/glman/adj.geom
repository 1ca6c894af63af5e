#version 330 compatibility
// Triangles with adjacency in: the edges of each front-facing triangle,
// dim, and bright where the neighbour across the edge faces away (the
// silhouette).
layout(triangles_adjacency) in;
layout(line_strip, max_vertices = 6) out;
out vec3 gColor;
bool front(vec4 a, vec4 b, vec4 c) {
    vec2 p = a.xy / a.w, q = b.xy / b.w, r = c.xy / c.w;
    return (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x) > 0.;
}
void edge(int a, int b, int adj) {
    bool silhouette = !front(gl_in[a].gl_Position, gl_in[adj].gl_Position, gl_in[b].gl_Position);
    gColor = silhouette ? vec3(1., 1., 0.) : vec3(.2, .2, .6);
    gl_Position = gl_in[a].gl_Position; EmitVertex();
    gl_Position = gl_in[b].gl_Position; EmitVertex();
    EndPrimitive();
}
void main() {
    if (!front(gl_in[0].gl_Position, gl_in[2].gl_Position, gl_in[4].gl_Position)) return;
    edge(0, 2, 1);
    edge(2, 4, 3);
    edge(4, 0, 5);
}
