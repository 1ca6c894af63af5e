#version 330 compatibility
// Position, colour, texture coordinates and a normal in eye space.
out vec2 vST;
out vec3 vN;
out vec3 vMC;
void main() {
    vST = gl_MultiTexCoord0.st;
    vN = normalize(gl_NormalMatrix * gl_Normal);
    vMC = gl_Vertex.xyz;
    gl_FrontColor = gl_Color;
    gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
}
