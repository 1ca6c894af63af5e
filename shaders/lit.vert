#version 330 compatibility
// glman-style lighting: the legacy normal matrix and a per-vertex Tangent (glman gives spheres one).
in vec3 Tangent;
out vec3 vN;
out vec2 vST;
out vec3 vT;
void main() {
    vN = normalize(gl_NormalMatrix * gl_Normal);
    vT = Tangent;
    vST = gl_MultiTexCoord0.st;
    gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
}
