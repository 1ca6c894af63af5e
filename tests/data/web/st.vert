#version 330 compatibility

// glman style: the legacy matrix stack and vertex attributes, passing the
// texture coordinates on to the fragment shader.
out vec2 vST;

void main( )
{
    vST = gl_MultiTexCoord0.st;
    gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
}
