#version 330 compatibility
out vec3 vN;
out vec3 vE;
out vec2 vST;
out vec4 vColor;
void main() {
    vN = normalize(gl_NormalMatrix * gl_Normal);
    vec4 eye = gl_ModelViewMatrix * gl_Vertex;
    vE = -eye.xyz;
    vST = gl_MultiTexCoord0.st;
    vColor = gl_Color;
    vec4 back = gl_ModelViewMatrixInverse * eye;           // == gl_Vertex
    gl_Position = gl_ProjectionMatrix * gl_ModelViewMatrix * back;
}
