#version 330 compatibility

// The legacy matrix stack, as nearly every GLIB script writes it.
void main( )
{
    gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
}
