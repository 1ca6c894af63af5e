#version 400 compatibility
// A bilinear quad patch pushed out into a dome: z = 1 - (u-.5)^2 - (v-.5)^2.
layout(quads, equal_spacing, ccw) in;
out vec3 vColor;
void main() {
    float u = gl_TessCoord.x, v = gl_TessCoord.y;
    vec4 a = mix(gl_in[0].gl_Position, gl_in[1].gl_Position, u);
    vec4 b = mix(gl_in[3].gl_Position, gl_in[2].gl_Position, u);
    vec4 p = mix(a, b, v);
    p.z += 1. - 2. * ((u - .5) * (u - .5) + (v - .5) * (v - .5));
    vColor = vec3(u, v, p.z * 0.5);
    gl_Position = gl_ModelViewProjectionMatrix * p;
}
