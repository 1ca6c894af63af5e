#version 330 compatibility

// Full-target quad: the legacy matrix stack and the quad's texture
// coordinates, 0..1 over the target.
out vec2 vST;

void main( )
{
    vST = gl_MultiTexCoord0.st;
    gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
}
