#version 300 es
uniform mat3 glimmer_NormalMatrix;
uniform mat4 glimmer_ModelViewMatrix;
uniform mat4 glimmer_ProjectionMatrix;
uniform mat4 glimmer_ModelViewMatrixInverse;
in vec4 glimmer_Vertex;
in vec3 glimmer_Normal;
in vec4 glimmer_MultiTexCoord0;
in vec4 glimmer_Color;
out vec3 vN;
out vec3 vE;
out vec2 vST;
out vec4 vColor;
void main() {
    vN = normalize(glimmer_NormalMatrix * glimmer_Normal);
    vec4 eye = glimmer_ModelViewMatrix * glimmer_Vertex;
    vE = -eye.xyz;
    vST = glimmer_MultiTexCoord0.st;
    vColor = glimmer_Color;
    vec4 back = glimmer_ModelViewMatrixInverse * eye;
    gl_Position = glimmer_ProjectionMatrix * glimmer_ModelViewMatrix * back;
}
