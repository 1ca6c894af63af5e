#version 330 compatibility

// Full-target quad for every bloom pass: the legacy matrix stack (Ortho -1 1 -1 1,
// LookAt 0 0 1 ..., QuadXY 0 1 covers any render target exactly) and the quad's
// texture coordinates, 0..1 over the target.
out vec2 vST;

void main( )
{
    vST = gl_MultiTexCoord0.st;
    gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
}
