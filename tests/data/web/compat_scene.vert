#version 120
// The normal through a varying of the user's own; the colour and the
// texture coordinates through the fixed-function varyings, as glman-era
// shaders pass them.
varying vec3 vN;

void main()
{
    vN = normalize(gl_NormalMatrix * gl_Normal);
    gl_TexCoord[0] = gl_MultiTexCoord0;
    gl_FrontColor = gl_Color;
    gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
}
