#version 120
varying vec3 vN;
varying vec2 vST;
varying vec4 vColor;

void main()
{
    vN = normalize(gl_NormalMatrix * gl_Normal);
    vST = gl_MultiTexCoord0.st;
    vColor = gl_Color;
    gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
}
